#!/bin/sh
# Beyond the thesis (issue 13): the Monte Carlo integration error of
# uniform sample distributions against the point count n, by mc-error(1)
# on its test integrands gauss (smooth), disc and step (discontinuous),
# for FRS (frs-sample -i const, the default matrix), jittered FRS
# (--jitter random), FRS on a void-and-cluster matrix (vfrs: frd-gen
# --method vac, 1024^2 in quick mode, 2048^2 in full; see exp-vac.sh), HSW (hsw-sample -i const with its default input,
# Halton, which the constant map leaves unchanged), uniform random,
# jittered, Halton (Cranley-Patterson rotated by the seed) and dart
# throwing (ref-sample -k random|jittered|halton|dart; jittered rounds n
# to a square).  Every (sampler,
# n) is m sets (--sets m, seeds 1..m); FRS sets vary in size with the
# seed, so they are split into per-set files and taken together by
# mc-error --group all (n is then their mean count).  HSW's Halton input
# does not depend on the seed, so HSW is one set, its rmse the error of
# that one deterministic set.  The generation of the m sets is timed (wall
# clock, one thread, -j 1, one process; jobs run JOBS at a time; for HSW
# one run of m n points), the per-set time is that over m.  The empirical convergence rate is
# the least-squares slope of log rmse on log n.
#
# The environment-lit case, where importance sampling matters, as
# renderers need it (issue 35): mc-error's env integrand (the irradiance
# of a diffuse surface facing the zenith, relative rmse) lit by each of
# the three shared maps data/forest.exr, interior.exr and sunset.exr
# (and ENVMAP when it is another; tiny mode: ENVMAP alone), for the
# uniform samplers random, jittered, Halton and dart (plain mean) and for
# importance samplers that follow the map weighted by sin theta
# (--equirect) and divide by their density: FRS with each tiling
# (frs-sample --tiles levels|plain|shuffled: ifrs, ifrs_plain,
# ifrs_shuf), jittered FRS (ijfrs, levels), HSW with each input
# (hsw-sample --input halton|hammersley|regular|random|jittered|dart:
# ihsw, ihsw_ham, ihsw_reg, ihsw_rand, ihsw_jit, ihsw_dart; the first
# three do not depend on the seed, so they are one set, the rmse of that
# one deterministic set) and relaxed dart throwing (ref-sample -k
# relaxed-dart: irdart), which writes no density: mc-error --pdf-map
# takes it from the weighted map (imap convert --equirect, at the map's
# own size, cache/mc/NAME-equirect.exr), the density it follows.  EM
# sets per n, n = 2^EKMIN..2^EKMAX.  These are not timed.
#
# Why a sampler loses: f / p = C max(0, cos theta) does not depend on
# the map, so the error is how far a set's distribution in theta strays
# from p's.  Its coarsest part is the fraction K/n of a set's samples
# above the horizon against q, p's mass there.  Per map and importance
# sampler, horizon.tsv gives the mean and spread of K/n over the sets,
# their dispersion var(K/n) n / (q (1 - q)) (1 for independent samples),
# the rms over the sets of (K/n - q) / q (horizon_rel: the relative
# error were K/n the only error) and of the rest (sky_rel: the error
# were K/n exactly q), the relative error they make together (rel_err,
# which reproduces mc-error's rel_rmse up to the variation of sin theta
# within a map row) and, beside them, the mean and the dispersion of the
# fraction in the bright half of the map (pdf above its median; "-"
# without a pdf column, for relaxed dart throwing).  q, the mean of
# max(0, cos theta) and that median are measured on 2 sets of HSW with
# jittered input of QN points (stratified, exact in expectation; its
# spread is far below that of any set here), QN = 2^14, 2^18 and 2^20 in
# tiny, quick and full mode.  The verdict names a cause only where these
# numbers show it.
#
# Parameters per mode:
#   tiny:  n = 2^4, 2^5, m = 4; env: one map, n = 2^4, 2^5, 4 sets
#   quick: n = 2^6..2^12, m = 32; env: n = 2^8..2^12, 16 sets
#   full:  n = 2^4..2^16, m = 256 (FRS's per-set text files reach ~0.5 GB
#          per job at n = 2^16, removed after each job); env: n =
#          2^8..2^16, 32 sets
# Output (RES/mc/): rmse.tsv (sampler n sets integrand rmse rel_rmse
#   abs_error time_s time_per_set; env rows have integrand env_MAP and
#   time_s, time_per_set "-": not timed), slopes.tsv (sampler slope_gauss
#   slope_disc slope_step), slopes.md (the same as a table, with the env
#   table), env-slopes.tsv (map sampler slope rel_rmse, the relative rmse
#   at 2^EKMAX), horizon.tsv (map sampler n sets q frac_mean frac_sd
#   dispersion horizon_rel sky_rel rel_err rel_rmse bright_mean
#   bright_disp), rmse-gauss.png, rmse-disc.png,
#   rmse-step.png (rmse against n), rmse-env.png (relative rmse against
#   n, a panel per map) and rmse-time.png (rmse against the time per
#   set, for gauss, disc and step).
# ids: mc mc-error integration
. "$(dirname "$0")/explib.sh"

M=$(pick 4 32 256)
KMIN=$(pick 4 6 4)
KMAX=$(pick 5 12 16)
SAMPLERS="frs jfrs vfrs hsw random jittered halton dart"
FUNCS="gauss disc step"
# The env samplers: uniform ones, then those that follow the map.
EUNI="random jittered halton dart"
EIMP="ifrs ifrs_plain ifrs_shuf ijfrs ihsw ihsw_ham ihsw_reg ihsw_rand ihsw_jit ihsw_dart irdart"
ESAMPLERS="$EUNI $EIMP"
EM=$(pick 4 16 32)
EKMIN=$(pick 4 8 8)
EKMAX=$(pick 5 12 16)
QN=$(pick 16384 262144 1048576)	# q's reference: HSW, jittered input
D=$CACHE/mc
# FRS on a void-and-cluster matrix (frd-gen --method vac, seed 1; the
# same file exp-vac.sh makes at that size): large enough that the
# largest n does not repeat it (S^2 / 64 unique samples).
VS=$(pick 128 1024 2048)
VACM=$CACHE/vac/vac-$VS.frd
# The maps: the three shared ones and ENVMAP when it is another (tiny
# mode: ENVMAP alone).
if [ "$MODE" = tiny ]; then
	EMAPS=$ENVMAP
else
	EMAPS="$TOP/data/forest.exr $TOP/data/interior.exr $TOP/data/sunset.exr"
	case " $EMAPS " in *" $ENVMAP "*) ;; *) EMAPS="$EMAPS $ENVMAP" ;; esac
fi
mname() { b_=$(basename "$1"); echo "${b_%.*}"; }	# mname MAP: its name
MNAMES=$(for m in $EMAPS; do mname "$m"; done)
wmap() { echo "$D/$(mname "$1")-equirect.exr"; }	# the weighted map

base() { echo "$D/$1-n$2-m$M"; }	# base SAMPLER N
ebase() { echo "$D/env-$1-$2-n$3-m$EM"; }	# ebase MAPNAME SAMPLER N

# run_one SAMPLER N: make the sets of the uniform integrands in a scratch
# directory, timing their generation into BASE.time (seconds, sets
# made), and print mc-error's table; the sets are removed afterwards.
run_one() {
	b=$(base "$1" "$2")
	w=$b.d
	rm -rf "$w"
	mkdir -p "$w"
	alone	# the generation is timed: no other job beside it
	t0=$(date +%s.%N)
	case $1 in
	frs | jfrs | vfrs)
		j=none
		[ "$1" = jfrs ] && j=random
		mo=""
		[ "$1" = vfrs ] && mo="-m $VACM"
		# shellcheck disable=SC2086
		frs-sample -q -j 1 $mo -i const -n "$2" --sets "$M" --jitter "$j" \
		    -o "$w/all.pts" ;;
	hsw)	# m sets' worth of points in one run, like --sets elsewhere
		hsw-sample -q -j 1 -i const -n $(($2 * M)) -o "$w/timed.pts" ;;
	*)
		ref-sample -q -j 1 -k "$1" -n "$2" --sets "$M" -o "$w/all.pts" ;;
	esac
	t1=$(date +%s.%N)
	together
	awk -v a="$t0" -v b="$t1" -v m="$M" \
	    'BEGIN { printf "%.6f\t%d\n", b - a, m }' >"$b.time"
	case $1 in
	frs | jfrs | vfrs)
		# The same sets again as text, cut into per-set files (untimed).
		# shellcheck disable=SC2086
		split_frs "$w" $mo -i const -n "$2" --sets "$M" --jitter "$j" \
		    >/dev/null
		mc-error -q --group all "$w"/s*.txt ;;
	hsw)	# the one deterministic set (untimed)
		hsw-sample -q -i const -n "$2" -o "$w/all.pts"
		mc-error -q "$w/all.pts" ;;
	*)	# jittered makes a square count per set: the file's count / m
		c=$(od -A n -t u8 -j 24 -N 8 "$w/all.pts" | tr -d ' ')
		mc-error -q --sets $((c / M)) "$w/all.pts" ;;
	esac
	rm -rf "$w"
}

# horizon Q G T: from text sets (pts(5), a set column or one set) on
# standard input, per set the fraction K/n of its points above the
# horizon (y < 1/2), its relative error e = (mean g - G) / G, g =
# max(0, cos pi y) (f / p up to a constant: the error of env's estimate
# when p is the map's density), its part h = (K/n - Q) / Q and the rest
# s = (1 + e) / (1 + h) - 1 (the error were K/n exactly Q), and the
# fraction of points whose pdf is at least T (the bright half of the
# map): their means and spreads over the sets, "-" for the bright half
# without a pdf column.  Q, G and T as run_q measures them.
horizon() {
	awk -v q="$1" -v G="$2" -v t="$3" '/^#pts / { sc = 0; pc = 0
		for (i = 2; i <= NF; i++) { split($i, kv, "=")
			if (kv[1] == "dims") d = kv[2]
			if (kv[1] == "names") nn = split(kv[2], nm, ",") }
		for (i = 1; i <= nn; i++) {
			if (nm[i] == "set") sc = d + i
			if (nm[i] == "pdf") pc = d + i }
		next }
	    /^#/ || NF == 0 { next }
	    { j = sc ? $sc : 0; if (!(j in n)) ord[++k] = j
	      n[j]++
	      if ($2 < 0.5) { a[j]++; g[j] += cos(3.14159265358979324 * $2) }
	      if (pc && $pc >= t) b[j]++ }
	    END { for (i = 1; i <= k; i++) { j = ord[i]; f = a[j] / n[j]
		    e = (g[j] / n[j] - G) / G; h = (f - q) / q
		    s = f > 0 ? (1 + e) / (1 + h) - 1 : 0
		    s1 += f; s2 += f * f; se += e * e; sh += h * h; ss += s * s
		    nb += n[j]; bb = b[j] / n[j]; b1 += bb; b2 += bb * bb }
		  mu = s1 / k; v = s2 / k - mu * mu; if (v < 0) v = 0
		  bm = b1 / k; bv = b2 / k - bm * bm; if (bv < 0) bv = 0
		  printf "n_mean\tfrac_mean\tfrac_var\te_rms\th_rms\ts_rms\tbright_mean\tbright_var\n"
		  printf "%.6g\t%.9g\t%.9g\t%.6g\t%.6g\t%.6g", nb / k, mu, v, sqrt(se / k), sqrt(sh / k), sqrt(ss / k)
		  if (pc) printf "\t%.6g\t%.6g\n", bm, bv; else printf "\t-\t-\n" }'
}

# run_env MAP SAMPLER N WMAP QTAB: the env integrand lit by MAP for EM
# sets of N points of SAMPLER (importance samplers: MAP with --equirect;
# WMAP the weighted map, relaxed dart's density): mc-error's row and
# horizon's columns beside it, by the reference values of QTAB.  The sets are text, in a scratch directory removed
# afterwards; not timed.
run_env() {
	w=$(ebase "$(mname "$1")" "$2" "$3").d
	rm -rf "$w"
	mkdir -p "$w"
	o="-q -n $3 -T -o $w/all.txt"
	im="-i $1 --equirect"
	case $2 in
	ifrs* | ijfrs)
		t=levels j=none
		case $2 in ifrs_plain) t=plain ;; ifrs_shuf) t=shuffled ;; ijfrs) j=random ;; esac
		# shellcheck disable=SC2086
		frs-sample -j 1 $im --pdf --tiles $t --jitter $j --sets "$EM" $o ;;
	ihsw*)
		case $2 in
		ihsw) in=halton ;; ihsw_ham) in=hammersley ;; ihsw_reg) in=regular ;;
		ihsw_rand) in=random ;; ihsw_jit) in=jittered ;; ihsw_dart) in=dart ;;
		esac
		ss="--sets $EM"	# the seedless inputs make one set
		case $in in halton | hammersley | regular) ss= ;; esac
		# shellcheck disable=SC2086
		hsw-sample -j 1 $im --pdf --input $in $ss $o ;;
	irdart)
		# shellcheck disable=SC2086
		ref-sample -k relaxed-dart $im --sets "$EM" $o ;;
	*)
		# shellcheck disable=SC2086
		ref-sample -k "$2" --sets "$EM" $o ;;
	esac
	case $2 in
	irdart) pd="--pdf-map $4" ;; i*) pd=--weights ;; *) pd=--no-pdf ;;
	esac
	# shellcheck disable=SC2086
	mc-error -q -f env --env "$1" --group all $pd "$w/all.txt" >"$w/mc"
	# shellcheck disable=SC2086
	horizon $5 <"$w/all.txt" >"$w/hz"
	paste "$w/mc" "$w/hz"
	rm -rf "$w"
}

# run_q MAP: the reference values of horizon for MAP weighted by sin
# theta, from 2 sets of QN points of HSW with jittered input (stratified,
# exact in expectation): q, the mass above the horizon, and its spread
# over the sets; G, the mean of max(0, cos pi y); T, the median of the
# pdf column, which splits the mass in halves.
run_q() {
	hsw-sample -q -j 1 -i "$1" --equirect --input jittered --pdf -n "$QN" \
	    --sets 2 -T -o "$D/q.$$.txt"
	t_=$(awk '!/^#/ && NF { print $3 }' "$D/q.$$.txt" | sort -g |
	    awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
	awk -v t="$t_" '/^#pts / { for (i = 2; i <= NF; i++) { split($i, kv, "=")
			if (kv[1] == "names") nn = split(kv[2], nm, ",") }
		for (i = 1; i <= nn; i++) if (nm[i] == "set") sc = 2 + i
		next }
	    /^#/ || NF == 0 { next }
	    { j = $sc; if (!(j in n)) ord[++k] = j; n[j]++; N++
	      if ($2 < 0.5) { a[j]++; g += cos(3.14159265358979324 * $2) } }
	    END { for (i = 1; i <= k; i++) { f = a[ord[i]] / n[ord[i]]; s1 += f; s2 += f * f }
		mu = s1 / k; v = s2 / k - mu * mu; if (v < 0) v = 0
		printf "q\tq_sd\tG\tT\n%.9g\t%.3g\t%.9g\t%s\n", mu, sqrt(v), g / N, t }' \
	    "$D/q.$$.txt"
	rm -f "$D/q.$$.txt"
}
# qref MAP: "q G T" of run_q's table for MAP.
qref() { awk -F '\t' 'NR == 2 { print $1, $3, $4 }' "$D/env-$(mname "$1")-q-$QN.tsv"; }

if [ "${1:-}" = job ]; then	# worker: sh exp-mc.sh job SAMPLER N
	job_lock
	cached "$(base "$2" "$3").tsv" run_one "$2" "$3"
	exit 0
fi
if [ "${1:-}" = envjob ]; then	# worker: sh exp-mc.sh envjob MAP SAMPLER N
	job_lock	# never beside a timed generation
	# the weighted map last: relaxed dart's density, the key needs it
	cached "$(ebase "$(mname "$2")" "$3" "$4").tsv" run_env "$2" "$3" "$4" \
	    "$(wmap "$2")" "$(qref "$2")"
	exit 0
fi
if [ "${1:-}" = qjob ]; then	# worker: sh exp-mc.sh qjob MAP
	job_lock
	cached "$D/env-$(mname "$2")-q-$QN.tsv" run_q "$2"
	exit 0
fi

# NS: the counts, largest first (the longest jobs start first); ENS the
# env counts.
NS=$(k=$KMAX; while [ $k -ge "$KMIN" ]; do echo $((1 << k)); k=$((k - 1)); done)
ENS=$(k=$EKMAX; while [ $k -ge "$EKMIN" ]; do echo $((1 << k)); k=$((k - 1)); done)
exp_begin mc "Integration error (beyond the thesis)" \
    "not in the thesis (issues 13 and 35); Monte Carlo rmse of gauss, disc and step (n = 2^$KMIN..2^$KMAX, m = $M sets), and the relative rmse of env lit by $(echo $MNAMES | sed 's/ /, /g') with importance sampling (n = 2^$EKMIN..2^$EKMAX, $EM sets), by mc-error(1)" \
    "about 40 minutes on 2 cores (estimated from quick mode's times, not measured; relaxed dart throwing on the maps at n = 2^15 and 2^16 dominates)"
mkdir -p "$D"
cached "$VACM" frd-gen -q --method vac -s "$VS" -S 1
# the weighted maps, relaxed dart's density
for m in $EMAPS; do
	cached "$(wmap "$m")" imap convert -q --equirect --format exr "$m" -
done
# the reference values first: the env jobs' keys name them
for m in $EMAPS; do echo "sh $0 qjob $m"; done | par_run
{
	for n in $ENS; do for m in $EMAPS; do
		echo "sh $0 envjob $m irdart $n"
	done; done
	for n in $NS; do
		for s in $SAMPLERS; do
			echo "sh $0 job $s $n"
		done
	done
	for n in $ENS; do for m in $EMAPS; do for s in $ESAMPLERS; do
		[ "$s" = irdart ] || echo "sh $0 envjob $m $s $n"
	done; done; done
} | par_run

# Gather: one row per sampler, n and integrand (the env rows last, not
# timed); horizon.tsv from the env rows of the importance samplers.
{
	printf 'sampler\tn\tsets\tintegrand\trmse\trel_rmse\tabs_error\ttime_s\ttime_per_set\n'
	for s in $SAMPLERS; do
		for n in $(echo "$NS" | sort -n); do
			b=$(base $s $n)
			awk -F '\t' -v s="$s" 'NR == FNR { t = $1; m = $2; next }
			    FNR > 1 { printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.6g\n",
				s, $2, $3, $1, $6, $7, $5, t, t / m }' \
			    "$b.time" "$b.tsv"
		done
	done
	for mn in $MNAMES; do for s in $ESAMPLERS; do
		for n in $(echo "$ENS" | sort -n); do
			awk -F '\t' -v s="$s" -v i="env_$mn" 'FNR > 1 {
			    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t-\t-\n",
				s, $2, $3, i, $6, $7, $5 }' "$(ebase $mn $s $n).tsv"
		done
	done; done
} >"$OUT/rmse.tsv"
{
	printf 'map\tsampler\tn\tsets\tq\tfrac_mean\tfrac_sd\tdispersion\thorizon_rel\tsky_rel\trel_err\trel_rmse\tbright_mean\tbright_disp\n'
	for mn in $MNAMES; do for s in $EIMP; do
		for n in $(echo "$ENS" | sort -n); do
			# job columns: mc-error's 7, then horizon's: n_mean
			# frac_mean frac_var e_rms h_rms s_rms bright_mean bright_var
			awk -F '\t' -v mn="$mn" -v s="$s" 'NR == FNR { if (FNR == 2) q = $1; next }
			    FNR > 1 { v = $10; nb = $8
				d = $3 > 1 ? sprintf("%.3g", v * nb / (q * (1 - q))) : "-"
				bd = ($3 > 1 && $15 != "-") ? sprintf("%.3g", $15 * nb / 0.25) : "-"
				printf "%s\t%s\t%s\t%s\t%.6g\t%.6g\t%.3g\t%s\t%.4g\t%.4g\t%.4g\t%.4g\t%s\t%s\n",
				    mn, s, nb, $3, q, $9, sqrt(v), d, $12, $13, $11, $7, $14, bd }' \
			    "$D/env-$mn-q-$QN.tsv" "$(ebase $mn $s $n).tsv"
		done
	done; done
} >"$OUT/horizon.tsv"

# Least-squares slope of log rmse against log n.
slope() {	# slope SAMPLER INTEGRAND
	awk -F '\t' -v s="$1" -v f="$2" 'NR > 1 && $1 == s && $4 == f && $5 > 0 {
	    x = log($2); y = log($5); sx += x; sy += y; sxx += x * x
	    sxy += x * y; k++ }
	    END { if (k < 2 || k * sxx == sx * sx) print "-"
		else printf "%.2f\n", (k * sxy - sx * sy) / (k * sxx - sx * sx) }' \
	    "$OUT/rmse.tsv"
}
printf 'sampler\tslope_gauss\tslope_disc\tslope_step\n' >"$OUT/slopes.tsv"
for s in $SAMPLERS; do
	printf '%s\t%s\t%s\t%s\n' "$s" "$(slope $s gauss)" "$(slope $s disc)" \
	    "$(slope $s step)" >>"$OUT/slopes.tsv"
done
# env: the slope and the relative rmse at the largest n, per map.
printf 'map\tsampler\tslope\trel_rmse\n' >"$OUT/env-slopes.tsv"
for mn in $MNAMES; do for s in $ESAMPLERS; do
	printf '%s\t%s\t%s\t%s\n' "$mn" "$s" "$(slope $s env_$mn)" \
	    "$(awk -F '\t' -v s="$s" -v f="env_$mn" '$1 == s && $4 == f { v = $6 } END { printf "%.4g", v }' "$OUT/rmse.tsv")" \
	    >>"$OUT/env-slopes.tsv"
done; done

label() {
	case $1 in
	frs) echo FRS ;; jfrs) echo "jittered FRS" ;; hsw) echo "HSW (Halton input)" ;;
	vfrs) echo "FRS, void-and-cluster matrix" ;;
	random) echo "uniform random" ;; jittered) echo jittered ;;
	halton) echo Halton ;; dart) echo "dart throwing" ;;
	ifrs) echo "FRS (levels)" ;; ifrs_plain) echo "FRS (plain tiles)" ;;
	ifrs_shuf) echo "FRS (shuffled tiles)" ;; ijfrs) echo "jittered FRS (levels)" ;;
	ihsw) echo "HSW (Halton input)" ;; ihsw_ham) echo "HSW (Hammersley input)" ;;
	ihsw_reg) echo "HSW (regular input)" ;; ihsw_rand) echo "HSW (random input)" ;;
	ihsw_jit) echo "HSW (jittered input)" ;; ihsw_dart) echo "HSW (dart input)" ;;
	irdart) echo "relaxed dart throwing" ;;
	esac
}
# es MAP SAMPLER COLUMN: a value of env-slopes.tsv; hz MAP SAMPLER
# COLUMN: one of horizon.tsv at the largest n.
es() { awk -F '\t' -v m="$1" -v s="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) k[$i] = i; next } $1 == m && $2 == s { print $k[c] }' "$OUT/env-slopes.tsv"; }
hz() { awk -F '\t' -v m="$1" -v s="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) k[$i] = i; next } $1 == m && $2 == s { v = $k[c] } END { print v }' "$OUT/horizon.tsv"; }
{
	echo "Empirical convergence slopes, d log rmse / d log n (least squares over n = 2^$KMIN..2^$KMAX; random MC: -0.5):"
	echo
	echo "| sampler | gauss | disc | step |"
	echo "| --- | --- | --- | --- |"
	awk -F '\t' 'NR > 1 { print $1 "\t" $2 "\t" $3 "\t" $4 }' "$OUT/slopes.tsv" |
	    while IFS="$(printf '\t')" read -r s a b c; do
		echo "| $(label "$s") | $a | $b | $c |"
	    done
	echo
	echo "env, the irradiance of a diffuse surface facing the zenith lit by each map: relative rmse at n = 2^$EKMAX ($EM sets; one set for HSW's seedless inputs) and, in brackets, its slope over n = 2^$EKMIN..2^$EKMAX.  The importance samplers follow the map weighted by sin theta (--equirect) and divide by their density (relaxed dart throwing: that of the weighted map, mc-error --pdf-map); the uniform ones take the plain mean:"
	echo
	printf '| sampler |'; for mn in $MNAMES; do printf ' %s |' "$mn"; done; echo
	printf '| --- |'; for mn in $MNAMES; do printf ' --- |'; done; echo
	for s in $ESAMPLERS; do
		printf '| %s |' "$(label $s)"
		for mn in $MNAMES; do printf ' %s (%s) |' "$(es $mn $s rel_rmse)" "$(es $mn $s slope)"; done
		echo
	done
	echo
	echo "Why: f / p = C max(0, cos theta) whatever the map, so a set's error is how its samples stray in theta from p.  Per map and sampler at n = 2^$EKMAX: the dispersion var(K/n) n / (q (1 - q)) over the sets of the fraction K/n of samples above the horizon (1 for independent samples; - for one set), q the weighted map's mass there (from $QN points of HSW, jittered input), and in brackets that of the count in the bright half of the map (pdf above its median); then the relative error were K/n the only error, rms (K/n - q) / q, the rest, were K/n exactly q, and the relative error recomputed so (up to sin theta's variation within a row), / mc-error's relative rmse:"
	echo
	printf '| sampler |'; for mn in $MNAMES; do printf ' %s (q = %s) |' "$mn" "$(hz $mn ihsw_jit q)"; done; echo
	printf '| --- |'; for mn in $MNAMES; do printf ' --- |'; done; echo
	for s in $EIMP; do
		printf '| %s |' "$(label $s)"
		for mn in $MNAMES; do printf ' %s (%s); %s, %s, %s / %s |' "$(hz $mn $s dispersion)" "$(hz $mn $s bright_disp)" "$(hz $mn $s horizon_rel)" "$(hz $mn $s sky_rel)" "$(hz $mn $s rel_err)" "$(hz $mn $s rel_rmse)"; done
		echo
	done
	echo
} >"$OUT/slopes.md"
sl() { awk -F '\t' -v s="$1" -v c="$2" '$1 == s { print $c }' "$OUT/slopes.tsv"; }
# Beside the discrepancy slopes of fig6.3-6.8 (when it has run): by
# Koksma-Hlawka the error of a smooth integrand is bounded through the
# star discrepancy, that of an indicator through the discrepancy of its
# shape class (disc: circles, step: halfplanes).
DS=$RES/fig6.3-6.8/slopes.tsv
if [ -s "$DS" ]; then
	dsl() { awk -F '\t' -v c="$1" -v d="$2" '$1 == c && $2 == d { print $3 }' "$DS"; }
	{
		echo "The same slopes beside those of the D2 discrepancy in fig6.3-6.8 (its n range; $(sed -n 's/^Thesis: .*Mode: \(.*\)\.$/\1/p' "$RES/fig6.3-6.8/summary.md" 2>/dev/null || echo unknown) mode), per integrand and its shape class:"
		echo
		echo "| sampler | gauss | star D2 | disc | circle D2 | step | half D2 |"
		echo "| --- | --- | --- | --- | --- | --- | --- |"
		for x in frs jfrs random halton dart; do
			echo "| $(label $x) | $(sl $x 2) | $(dsl star $x) | $(sl $x 3) | $(dsl circle $x) | $(sl $x 4) | $(dsl half $x) |"
		done
		echo
	} >"$OUT/beside.md"
	cat "$OUT/beside.md" >>"$OUT/slopes.md"
fi
# The table goes into the summary, after the head (exp_end composes it).
cat "$OUT/slopes.md" >>"$OUT/head.md"

# Plots: rmse against n, one per integrand; rmse against time per set;
# the env relative rmse against n, a panel per map.
COLS="#d62728 #ff7f0e #17becf #8c564b #7f7f7f #2ca02c #9467bd #1f77b4"
# color SAMPLER: its curve's color
color() {
	i=1
	for c in $SAMPLERS; do
		[ "$c" = "$1" ] && break
		i=$((i + 1))
	done
	echo "$COLS" | cut -d' ' -f$i
}
# blocks: the curves' data as gnuplot data blocks $S_F (x, rmse).
blocks() {
	for bs in $SAMPLERS; do for bf in $FUNCS; do block $bs $bf; done; done
}
block() {	# block SAMPLER INTEGRAND
	echo "\$${1}_$2 << EOD"
	# a header line (gp_png: columnhead), then n, time, rmse
	awk -F '\t' -v s="$1" -v f="$2" 'NR == 1 { print "n\ttime\trmse" }
	    $1 == s && $4 == f { print $2 "\t" $9 "\t" $5 }' "$OUT/rmse.tsv"
	echo "EOD"
}
curves() {	# curves INTEGRAND XCOLUMN: the plot command's curves
	i=1
	for s in $SAMPLERS; do
		[ $i = 1 ] || printf ', '
		printf "\$%s_%s using %s:3 with linespoints lw 2 lc rgb '%s' pt 7 ps 0.7 title '%s'" \
		    "$s" "$1" "$2" "$(color $s)" "$(label $s)"
		i=$((i + 1))
	done
}
for f in $FUNCS; do
	{
		gp_png "$OUT/rmse-$f.png"
		blocks
		echo "set title 'Integration error of $f ($M sets; dashed: n^{-1/2}, n^{-3/4}, n^{-1})'"
		echo "set logscale xy; set xlabel 'n'; set ylabel 'rmse'"
		echo "set format y '10^{%L}'; set grid; set key outside right"
		# Reference slopes through the random rmse at the smallest n.
		r0=$(awk -F '\t' -v f="$f" 'NR > 1 && $1 == "random" && $4 == f { print $2, $5; exit }' "$OUT/rmse.tsv")
		n0=${r0% *}
		e0=${r0#* }
		printf "plot %s, %s * (x / %s)**-0.5 with lines dt 2 lc rgb '#aaaaaa' notitle, %s * (x / %s)**-0.75 with lines dt 3 lc rgb '#aaaaaa' notitle, %s * (x / %s)**-1 with lines dt 4 lc rgb '#aaaaaa' notitle\n" \
		    "$(curves $f 1)" "$e0" "$n0" "$e0" "$n0" "$e0" "$n0"
	} | gnuplot
done
{
	gp_png "$OUT/rmse-time.png"
	blocks
	echo "set terminal png size 1500,550 font ',10'"
	echo "set multiplot layout 1,3 title 'Integration error against the time to generate a set ($M sets, one thread)'"
	echo "set logscale xy; set xlabel 'seconds per set'; set ylabel 'rmse'"
	echo "set format y '10^{%L}'; set format x '10^{%L}'; set grid"
	for f in $FUNCS; do
		echo "set title '$f'"
		if [ "$f" = gauss ]; then echo "set key top right"; else echo "unset key"; fi
		echo "plot $(curves $f 2)"
	done
	echo "unset multiplot"
} | gnuplot
# env: uniform random and the importance samplers, FRS solid, HSW dashed
ECURVES="random $EIMP"
ECOLS="#7f7f7f #d62728 #ff7f0e #e377c2 #8c564b #1f77b4 #17becf #aec7e8 #9467bd #2ca02c #bcbd22 #000000"
{
	gp_png "$OUT/rmse-env.png"
	for mn in $MNAMES; do for s in $ECURVES; do
		echo "\$${s}_env_$mn << EOD"
		awk -F '\t' -v s="$s" -v f="env_$mn" 'NR == 1 { print "n\trel_rmse" }
		    $1 == s && $4 == f { print $2 "\t" $6 }' "$OUT/rmse.tsv"
		echo "EOD"
	done; done
	nm=$(echo $MNAMES | wc -w)
	echo "set terminal png size $((450 * nm + 250)),520 font ',10'"
	echo "set multiplot layout 1,$nm title 'Relative rmse of env (zenith irradiance) against n ($EM sets; importance samplers: --equirect, divided by the density)'"
	echo "set logscale xy; set xlabel 'n'; set ylabel 'relative rmse'"
	echo "set format y '10^{%L}'; set grid"
	i=0
	for mn in $MNAMES; do
		i=$((i + 1))
		echo "set title '$mn'"
		if [ $i = "$nm" ]; then echo "set key outside right"; else echo "unset key"; fi
		printf 'plot '
		j=1
		for s in $ECURVES; do
			[ $j = 1 ] || printf ', '
			dt=1
			case $s in ihsw*) dt=2 ;; esac
			printf "\$%s_env_%s using 1:2 with linespoints lw 2 dt %s lc rgb '%s' pt 7 ps 0.6 title '%s'" \
			    "$s" "$mn" "$dt" "$(echo "$ECOLS" | cut -d' ' -f$j)" "$(label $s)"
			j=$((j + 1))
		done
		echo
	done
	echo "unset multiplot"
} | gnuplot

# Rows: slopes beside what theory leads one to expect.
i=2
for f in $FUNCS; do
	o=""
	for s in $SAMPLERS; do o="$o${o:+ / }$(sl $s $i)"; done
	case $f in
	gauss) th="not in the thesis; theory: random -0.5, jittered -1.0 (smooth f), Halton ~ -1 (up to log n)" ;;
	*) th="not in the thesis; theory: random -0.5, jittered and QMC ~ -0.75 (discontinuity along a curve)" ;;
	esac
	row "$f: rmse slope $(echo $SAMPLERS | tr ' ' /)" "$o" "$th"
	i=$((i + 1))
done
big() {	# big SAMPLER INTEGRAND: rmse at the largest n
	awk -F '\t' -v s="$1" -v f="$2" 'NR > 1 && $1 == s && $4 == f { v = $5 } END { printf "%.4g\n", v }' "$OUT/rmse.tsv"
}
for f in $FUNCS; do
	o=""
	for s in $SAMPLERS; do o="$o${o:+ / }$(big $s $f)"; done
	row "$f: rmse at n = 2^$KMAX $(echo $SAMPLERS | tr ' ' /)" "$o" "-"
done
for mn in $MNAMES; do
	o=""
	for s in $ESAMPLERS; do o="$o${o:+ / }$(es $mn $s slope)"; done
	row "env on $mn: relative rmse slope $(echo $ESAMPLERS | tr ' ' /)" "$o" \
	    'not in the thesis; theory: independent samples -0.5; importance sampling by L sin(theta) leaves f/p ~ max(0, cos theta), smooth above the horizon'
done
# The cause's rows: the dispersion of the counts, per map, at the largest
# n (hz is defined above, with the tables).
DS="ifrs ifrs_plain ifrs_shuf ijfrs ihsw_rand ihsw_jit ihsw_dart irdart"
for mn in $MNAMES; do
	o=""
	for s in $DS; do o="$o${o:+ / }$(hz $mn $s dispersion) ($(hz $mn $s bright_disp))"; done
	row "env on $mn: dispersion var(K/n) n / (q (1 - q)) of the count above the horizon (in brackets: in the bright half) at n = 2^$EKMAX, $(echo $DS | tr ' ' /)" "$o" \
	    'not in the thesis; theory: independent samples 1, stratified samples far below 1'
done

# The claims, checked on this run: plain Monte Carlo (random) converges
# as n^-1/2 on gauss, disc and step (slope within 0.12), and so do
# independent importance samples (HSW with random input) on env lit by
# each map (within three standard errors of a slope from EM sets; not
# uniform random there: its error on an HDR map comes from rare hits of
# the brightest pixels, which EM sets do not estimate); jittered
# sampling and Halton as the theory in the rows says (gauss: -1, at most
# -0.85; disc and step: -0.75 within 0.15); FRS and jittered FRS beat
# random on every uniform integrand at the largest n; on env lit by each
# map, FRS (each tiling, and jittered) and HSW (Halton and jittered
# input) beat every uniform sampler, stratified warping (HSW, jittered
# input) beats every FRS (issue 35), and every FRS tiling beats
# independent importance samples.
exp_note "Not a thesis experiment: the checks are Monte Carlo theory and the claims of frs(7) and of this script; m = $M sets per n, n = 2^$KMIN..2^$KMAX; env: $EM sets per n, n = 2^$EKMIN..2^$EKMAX, maps $(echo $MNAMES | sed 's/ /, /g')."
exp_note "The time per set includes each program's start and, for FRS, reading the matrix; the env sets are not timed."
o=""
c=""
for i in 2 3 4; do
	a=$(sl random $i)
	o="$o${o:+ / }$a"
	c="$c${c:+ && }$a > -0.62 && $a < -0.38"
done
check "uniform random converges as n^-1/2 on gauss, disc and step (slope -0.5 +- 0.12)" "$o" "$c"
for s in jittered halton; do
	a=$(sl $s 2)
	b=$(sl $s 3)
	e=$(sl $s 4)
	check "$(label $s): slope about -1 on gauss (<= -0.85), -0.75 +- 0.15 on disc and step" "$a / $b / $e" \
	    "$a <= -0.85 && $b >= -0.9 && $b <= -0.6 && $e >= -0.9 && $e <= -0.6"
done
for s in frs jfrs; do
	o=""
	c=""
	for f in $FUNCS; do
		a=$(big $s $f)
		b=$(big random $f)
		o="$o${o:+, }$a / $b"
		c="$c${c:+ && }$a < $b"
	done
	check_order "$(label $s) beats uniform random on gauss, disc and step (rmse at n = 2^$KMAX)" "$o" "$c"
done
# ETOL: three standard errors of a least-squares slope of log rmse over
# ENS from EM sets (log rmse has about 1 / sqrt(2 m) of spread).
ETOL=$(echo "$ENS" | awk -v m="$EM" '{ x[NR] = log($1); s += x[NR] }
    END { s /= NR; for (i = 1; i <= NR; i++) q += (x[i] - s) ^ 2
	printf "%.2f", 3 / sqrt(2 * m) / sqrt(q) }')
FRSS="ifrs ifrs_plain ifrs_shuf ijfrs"
# ern MAP SAMPLER N: the relative rmse of env on MAP at N (FRS: the row
# whose mean count is within 10% of N).
ern() { awk -F '\t' -v s="$2" -v f="env_$1" -v n="$3" '$1 == s && $4 == f && $2 > 0.9 * n && $2 < 1.1 * n { print $6 }' "$OUT/rmse.tsv"; }
# ebest MAP SAMPLERS: "value sampler" of the lowest relative rmse at the
# largest n among SAMPLERS; eworst the highest.
ebest() { for s_ in $2; do echo "$(es $1 $s_ rel_rmse) $s_"; done | sort -g | head -n 1; }
eworst() { for s_ in $2; do echo "$(es $1 $s_ rel_rmse) $s_"; done | sort -g | tail -n 1; }
for mn in $MNAMES; do
	b=$(es $mn ihsw_rand slope)
	check "independent importance samples (HSW, random input) converge as n^-1/2 on env lit by $mn (slope -0.5 +- $ETOL, 3 standard errors)" \
	    "$b" "$b > -0.5 - $ETOL && $b < -0.5 + $ETOL"
	bu=$(ebest $mn "$EUNI")
	wi=$(eworst $mn "$FRSS ihsw ihsw_jit")
	check_order "every FRS tiling, jittered FRS and HSW (Halton and jittered input) beat every uniform sampler on env lit by $mn (relative rmse at n = 2^$EKMAX: the worst of them, $(label ${wi#* }), against the best uniform, $(label ${bu#* }))" \
	    "${wi% *} / ${bu% *}" "${wi% *} < ${bu% *}"
	a=$(es $mn ihsw_rand rel_rmse)
	observe "$a >= ${bu% *}" "On $mn independent importance samples (HSW, random input: $a) do not beat the best uniform sampler, $(label ${bu#* }) (${bu% *}), at n = 2^$EKMAX."
	bf=$(ebest $mn "$FRSS")
	j=$(es $mn ihsw_jit rel_rmse)
	check_order "stratified warping (HSW, jittered input) beats every FRS tiling and jittered FRS on env lit by $mn (relative rmse at n = 2^$EKMAX, against the best of them, $(label ${bf#* }))" \
	    "$j / ${bf% *}" "$j < ${bf% *}"
	o=""
	c=""
	r=$(es $mn ihsw_rand rel_rmse)
	for s in ifrs ifrs_plain ifrs_shuf; do
		o="$o${o:+, }$(es $mn $s rel_rmse)"
		c="$c${c:+ && }$(es $mn $s rel_rmse) < $r"
	done
	check_order "FRS with each tiling (levels, plain, shuffled) beats independent importance samples (HSW, random input) on env lit by $mn (relative rmse at n = 2^$EKMAX)" \
	    "$o / $r" "$c"
done
# Where FRS loses on env and by how much, from the numbers: per map, the
# samplers below FRS's best tiling at the largest n, with the factor.
for mn in $MNAMES; do
	bf=$(ebest $mn "$FRSS")
	bv=${bf% *}
	bs=${bf#* }
	lose=$(for s in $EIMP; do
		case " $FRSS " in *" $s "*) continue ;; esac
		v=$(es $mn $s rel_rmse)
		holds "$v < $bv" && printf '%s %s\n' "$v" "$s"
	done | sort -g | while read -r v s; do
		case $s in ihsw | ihsw_ham | ihsw_reg) one=", one set" ;; *) one= ;; esac
		printf '%s (%s, %s times lower%s); ' "$(label $s)" "$v" "$(ratio "$bv" "$v")" "$one"
	done | sed 's/; $//')
	if [ -n "$lose" ]; then
		observe 1 "On $mn at n = 2^$EKMAX the best FRS, $(label $bs) (relative rmse $bv, slope $(es $mn $bs slope)), loses to: $lose; HSW with jittered input has slope $(es $mn ihsw_jit slope)."
	else
		observe 1 "On $mn at n = 2^$EKMAX the best FRS, $(label $bs) (relative rmse $bv), has the lowest error of the importance samplers."
	fi
	# HSW's jittered input fills the first n cells of a k x k grid, k =
	# ceil(sqrt n): at an n that is no square, where FRS does better
	o=$(for n in $(echo "$ENS" | sort -n); do
		awk -v n="$n" 'BEGIN { k = int(sqrt(n) + 0.5); exit k * k == n }' || continue
		j=$(ern $mn ihsw_jit $n)
		f=$(for s in $FRSS; do ern $mn $s $n; done | sort -g | head -n 1)
		holds "$j > $f" && printf '%s: %.4g against %.4g; ' "$n" "$j" "$f"
	done | sed 's/; $//')
	observe "\"$o\" != \"\"" "On $mn HSW with jittered input loses to the best FRS where n is no square, as its grid's last row is then incomplete (n: its relative rmse against FRS's): $o."
	# The cause, when the numbers show it: the count above the horizon
	# when, were it exact, FRS's error would fall to half or less; the
	# rest (the distribution within the sky) when that count alone would
	# give half or less; both otherwise.  Beside it the dispersions of
	# that count and of the count in the bright half.
	h=$(hz $mn $bs horizon_rel)
	sk=$(hz $mn $bs sky_rel)
	r=$(hz $mn $bs rel_rmse)
	observe "$sk <= 0.5 * $r" "On $mn the count above the horizon is what $(label $bs) loses by: were that count exact, its relative error would be $sk instead of $r."
	observe "$h <= 0.5 * $r && $sk > 0.5 * $r" "On $mn it is not the count above the horizon that $(label $bs) loses by (that count alone would give a relative error of $h; its relative rmse is $r) but the distribution within the sky (were that count exact: $sk)."
	observe "$sk > 0.5 * $r && $h > 0.5 * $r" "On $mn $(label $bs) loses both by its count above the horizon (that count alone would give a relative error of $h; its relative rmse is $r) and within the sky (were that count exact: $sk)."
	# Its counts over large regions against stratified warping's and
	# independent samples': said when its dispersion above the horizon is
	# at least twice stratified warping's.
	d=$(hz $mn $bs dispersion)
	dj=$(hz $mn ihsw_jit dispersion)
	dr=$(hz $mn ihsw_rand dispersion)
	bd=$(hz $mn $bs bright_disp)
	bj=$(hz $mn ihsw_jit bright_disp)
	br=$(hz $mn ihsw_rand bright_disp)
	observe "$d >= 2 * $dj" "On $mn the counts of $(label $bs) over large regions stray more than stratified warping's: the dispersion of its count above the horizon is $d, $(ratio "$d" "$dj") times that of HSW with jittered input ($dj; independent samples: $dr), and in the bright half of the map $bd ($bj; $br)."
	# relaxed dart throwing's bias: its mean fraction above the horizon
	# against q, in standard errors of that mean over the sets
	rf=$(hz $mn irdart frac_mean)
	rq=$(hz $mn irdart q)
	rs=$(hz $mn irdart frac_sd)
	rz=$(awk -v f="$rf" -v q="$rq" -v s="$rs" -v m="$EM" 'BEGIN { printf "%.1f", (s > 0 ? (f - q) / (s / sqrt(m)) : 0) }')
	observe "$rz >= 3 || $rz <= -3" "On $mn relaxed dart throwing puts a fraction $rf of its samples above the horizon against q = $rq ($(awk -v f="$rf" -v q="$rq" 'BEGIN { printf "%+.2f%%", 100 * (f - q) / q }'), $rz standard errors of its mean over $EM sets): it does not follow the density it is divided by, and its relative rmse falls as n^$(es $mn irdart slope)."
done
exp_note "The env slopes' tolerance, three standard errors of a slope from $EM sets over n = 2^$EKMIN..2^$EKMAX, is $ETOL."
o=""
c=""
for f in $FUNCS; do
	o="$o${o:+, }$(big frs $f) / $(big dart $f)"
	c="$c${c:+ && }$(big frs $f) < $(big dart $f)"
done
observe "$c" "FRS also has a lower rmse than dart throwing on gauss, disc and step at n = 2^$KMAX ($o)."
o=""
c=""
for f in $FUNCS; do
	o="$o${o:+, }$(big vfrs $f) / $(big frs $f)"
	c="$c${c:+ || }$(big vfrs $f) < $(big frs $f)"
done
observe "!($c)" "FRS on the void-and-cluster matrix has a higher rmse than on FRD on gauss, disc and step at n = 2^$KMAX ($o)."
exp_end
