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
# The environment-lit case, where importance sampling matters: mc-error's
# env integrand (a diffuse surface facing the zenith lit by ENVMAP,
# default data/sunset.exr) for the uniform samplers random, jittered,
# Halton and dart (plain mean) against importance samplers following the
# map with the equirect (sin theta) weighting and their pdf column
# (mc-error --weights): FRS (ifrs), jittered FRS (ijfrs) and HSW (ihsw,
# Halton input, one deterministic set).  hsw-sample has no --equirect, so
# imap convert --equirect makes the weighted map once, at the map's own
# size (cache/mc/NAME-equirect.exr), and both FRS and HSW sample it:
# the same density, and the pdf column (pixel / map mean) is the density
# of that map, the p that mc-error divides by.
#
# Parameters per mode:
#   tiny:  n = 2^4, 2^5, m = 4
#   quick: n = 2^6..2^12, m = 32
#   full:  n = 2^4..2^16, m = 256 (FRS's per-set text files reach ~0.5 GB
#          per job at n = 2^16, removed after each job)
# Output (RES/mc/): rmse.tsv (sampler n sets integrand rmse rel_rmse
#   abs_error time_s time_per_set), slopes.tsv (sampler slope_gauss
#   slope_disc slope_step), slopes.md (the same as a table),
#   rmse-gauss.png, rmse-disc.png, rmse-step.png, rmse-env.png (rmse
#   against n) and rmse-time.png (rmse against the time per set, for
#   gauss, disc and step); env rows (integrand env) in rmse.tsv, a
#   slope_env column in slopes.tsv (- where a sampler is not run).
# ids: mc mc-error integration
. "$(dirname "$0")/explib.sh"

M=$(pick 4 32 256)
KMIN=$(pick 4 6 4)
KMAX=$(pick 5 12 16)
SAMPLERS="frs jfrs vfrs hsw random jittered halton dart"
FUNCS="gauss disc step"
# the env samplers: importance FRS, jittered FRS, HSW, then uniform ones
ESAMPLERS="ifrs ijfrs ihsw random jittered halton dart"
D=$CACHE/mc
# FRS on a void-and-cluster matrix (frd-gen --method vac, seed 1; the
# same file exp-vac.sh makes at that size): large enough that the
# largest n does not repeat it (S^2 / 64 unique samples).
VS=$(pick 128 1024 2048)
VACM=$CACHE/vac/vac-$VS.frd
envb=$(basename "$ENVMAP")
envb=${envb%.*}
EMAP=$D/$envb-equirect.exr	# ENVMAP weighted by sin theta (imap --equirect)

base() { echo "$D/$1-n$2-m$M"; }	# base SAMPLER N
ebase() { echo "$D/env-$envb-$1-n$2-m$M"; }	# ebase SAMPLER N (env)

# mc FILE...: mc-error on the sets, for the integrands of the family FAM
# (uni: gauss, disc, step, plain mean; env: env on ENVMAP, the importance
# samplers' pdf column as weights, the uniform ones' plain mean).
mc() {
	if [ "$FAM" = uni ]; then
		mc-error -q "$@"
	else
		case $S in
		i*) mc-error -q -f env --env "$ENVMAP" --weights "$@" ;;
		*) mc-error -q -f env --env "$ENVMAP" --no-pdf "$@" ;;
		esac
	fi
}

# run_one FAM SAMPLER N: make the sets in a scratch directory, timing their
# generation into BASE.time (seconds, sets made), and print mc-error's
# table; the sets are removed afterwards.  FAM is uni (the uniform
# integrands; samplers on the constant map) or env (the env integrand;
# ifrs, ijfrs and ihsw sample EMAP with --pdf).
run_one() {
	FAM=$1
	S=$2
	shift
	if [ "$FAM" = uni ]; then
		b=$(base "$1" "$2")
		imp=const
		pdf=""
	else
		b=$(ebase "$1" "$2")
		imp=$EMAP
		pdf=--pdf
	fi
	w=$b.d
	rm -rf "$w"
	mkdir -p "$w"
	alone	# the generation is timed: no other job beside it
	t0=$(date +%s.%N)
	case ${1#i} in
	frs | jfrs | vfrs)
		j=none
		[ "${1#i}" = jfrs ] && j=random
		mo=""
		[ "$1" = vfrs ] && mo="-m $VACM"
		# shellcheck disable=SC2086
		frs-sample -q -j 1 $mo -i "$imp" -n "$2" --sets "$M" --jitter "$j" \
		    $pdf -o "$w/all.pts" ;;
	hsw)	# m sets' worth of points in one run, like --sets elsewhere
		hsw-sample -q -j 1 -i "$imp" -n $(($2 * M)) $pdf -o "$w/timed.pts" ;;
	*)
		ref-sample -q -j 1 -k "$1" -n "$2" --sets "$M" -o "$w/all.pts" ;;
	esac
	t1=$(date +%s.%N)
	together
	awk -v a="$t0" -v b="$t1" -v m="$M" \
	    'BEGIN { printf "%.6f\t%d\n", b - a, m }' >"$b.time"
	case ${1#i} in
	frs | jfrs | vfrs)
		# The same sets again as text, cut into per-set files (untimed).
		# shellcheck disable=SC2086
		split_frs "$w" $mo -i "$imp" -n "$2" --sets "$M" --jitter "$j" \
		    $pdf >/dev/null
		mc --group all "$w"/s*.txt ;;
	hsw)	# the one deterministic set (untimed)
		hsw-sample -q -i "$imp" -n "$2" $pdf -o "$w/all.pts"
		mc "$w/all.pts" ;;
	*)	# jittered makes a square count per set: the file's count / m
		c=$(od -A n -t u8 -j 24 -N 8 "$w/all.pts" | tr -d ' ')
		mc --sets $((c / M)) "$w/all.pts" ;;
	esac
	rm -rf "$w"
}

if [ "${1:-}" = job ]; then	# worker: sh exp-mc.sh job SAMPLER N
	job_lock
	cached "$(base "$2" "$3").tsv" run_one uni "$2" "$3"
	exit 0
fi
if [ "${1:-}" = envjob ]; then	# worker: sh exp-mc.sh envjob SAMPLER N
	job_lock
	# the maps last: run_one reads them, the cache key needs them
	cached "$(ebase "$2" "$3").tsv" run_one env "$2" "$3" "$EMAP" "$ENVMAP"
	exit 0
fi

# NS: the counts, largest first (the longest jobs start first).
NS=$(k=$KMAX; while [ $k -ge "$KMIN" ]; do echo $((1 << k)); k=$((k - 1)); done)
exp_begin mc "Integration error (beyond the thesis)" \
    "not in the thesis (issue 13); Monte Carlo rmse of gauss, disc and step, and of env lit by $(basename "$ENVMAP") with importance sampling, by mc-error(1), n = 2^$KMIN..2^$KMAX, m = $M sets" \
    "about 7 minutes on 2 cores (measured; dart throwing and FRS at n = 2^16 dominate)"
mkdir -p "$D"
cached "$VACM" frd-gen -q --method vac -s "$VS" -S 1
# the equirect-weighted map that FRS and HSW both sample, made once
cached "$EMAP" imap convert -q --equirect --format exr "$ENVMAP" -
for n in $NS; do
	for s in $SAMPLERS; do
		echo "sh $0 job $s $n"
	done
	for s in $ESAMPLERS; do
		echo "sh $0 envjob $s $n"
	done
done | par_run

# Gather: one row per sampler, n and integrand (the env rows last).
{
	printf 'sampler\tn\tsets\tintegrand\trmse\trel_rmse\tabs_error\ttime_s\ttime_per_set\n'
	bf=base
	for s in $SAMPLERS env $ESAMPLERS; do
		[ "$s" = env ] && { bf=ebase; continue; }
		for n in $(echo "$NS" | sort -n); do
			b=$($bf $s $n)
			awk -F '\t' -v s="$s" 'NR == FNR { t = $1; m = $2; next }
			    FNR > 1 { printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.6g\n",
				s, $2, $3, $1, $6, $7, $5, t, t / m }' \
			    "$b.time" "$b.tsv"
		done
	done
} >"$OUT/rmse.tsv"

# Least-squares slope of log rmse against log n.
slope() {	# slope SAMPLER INTEGRAND
	awk -F '\t' -v s="$1" -v f="$2" 'NR > 1 && $1 == s && $4 == f && $5 > 0 {
	    x = log($2); y = log($5); sx += x; sy += y; sxx += x * x
	    sxy += x * y; k++ }
	    END { if (k < 2 || k * sxx == sx * sx) print "-"
		else printf "%.2f\n", (k * sxy - sx * sy) / (k * sxx - sx * sx) }' \
	    "$OUT/rmse.tsv"
}
printf 'sampler\tslope_gauss\tslope_disc\tslope_step\tslope_env\n' >"$OUT/slopes.tsv"
for s in $SAMPLERS ifrs ijfrs ihsw; do
	printf '%s\t%s\t%s\t%s\t%s\n' "$s" "$(slope $s gauss)" "$(slope $s disc)" \
	    "$(slope $s step)" "$(slope $s env)" >>"$OUT/slopes.tsv"
done

label() {
	case $1 in
	frs) echo FRS ;; jfrs) echo "jittered FRS" ;; hsw) echo "HSW (Halton input)" ;;
	vfrs) echo "FRS, void-and-cluster matrix" ;;
	random) echo "uniform random" ;; jittered) echo jittered ;;
	halton) echo Halton ;; dart) echo "dart throwing" ;;
	ifrs) echo "FRS (importance)" ;; ijfrs) echo "jittered FRS (importance)" ;;
	ihsw) echo "HSW (importance)" ;;
	esac
}
{
	echo "Empirical convergence slopes, d log rmse / d log n (least squares over n = 2^$KMIN..2^$KMAX; random MC: -0.5):"
	echo
	echo "| sampler | gauss | disc | step | env |"
	echo "| --- | --- | --- | --- | --- |"
	awk -F '\t' 'NR > 1 { print $1 "\t" $2 "\t" $3 "\t" $4 "\t" $5 }' "$OUT/slopes.tsv" |
	    while IFS="$(printf '\t')" read -r s a b c e; do
		echo "| $(label "$s") | $a | $b | $c | $e |"
	    done
	echo
	echo "env: $(basename "$ENVMAP") lighting a diffuse surface; the importance samplers follow the map weighted by sin theta (imap convert --equirect) and divide by their pdf column."
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

# Plots: rmse against n, one per integrand; rmse against time per set.
COLS="#d62728 #ff7f0e #17becf #8c564b #7f7f7f #2ca02c #9467bd #1f77b4"
# color SAMPLER: its curve's color (an importance sampler takes that of
# its uniform namesake, which the env plot does not show).
color() {
	i=1
	for c in $SAMPLERS; do
		[ "$c" = "${1#i}" ] && break
		i=$((i + 1))
	done
	echo "$COLS" | cut -d' ' -f$i
}
# blocks: the curves' data as gnuplot data blocks $S_F (x, rmse).
blocks() {
	for bs in $SAMPLERS; do for bf in $FUNCS; do block $bs $bf; done; done
	for bs in $ESAMPLERS; do block $bs env; done
}
block() {	# block SAMPLER INTEGRAND
	echo "\$${1}_$2 << EOD"
	# a header line (gp_png: columnhead), then n, time, rmse
	awk -F '\t' -v s="$1" -v f="$2" 'NR == 1 { print "n\ttime\trmse" }
	    $1 == s && $4 == f { print $2 "\t" $9 "\t" $5 }' "$OUT/rmse.tsv"
	echo "EOD"
}
curves() {	# curves INTEGRAND XCOLUMN: the plot command's curves
	cs=$SAMPLERS
	[ "$1" = env ] && cs=$ESAMPLERS
	i=1
	for s in $cs; do
		[ $i = 1 ] || printf ', '
		printf "\$%s_%s using %s:3 with linespoints lw 2 lc rgb '%s' pt 7 ps 0.7 title '%s'" \
		    "$s" "$1" "$2" "$(color $s)" "$(label $s)"
		i=$((i + 1))
	done
}
for f in $FUNCS env; do
	{
		gp_png "$OUT/rmse-$f.png"
		blocks
		if [ "$f" = env ]; then
			echo "set title 'Integration error of env, $(basename "$ENVMAP") lighting ($M sets; importance: pdf weights; dashed: n^{-1/2}, n^{-3/4}, n^{-1})'"
		else
			echo "set title 'Integration error of $f ($M sets; dashed: n^{-1/2}, n^{-3/4}, n^{-1})'"
		fi
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
o=""
for s in $ESAMPLERS; do o="$o${o:+ / }$(sl $s 5)"; done
row "env: rmse slope ifrs/ijfrs/ihsw/random/jittered/halton/dart" "$o" \
    'not in the thesis; theory: random -0.5; importance sampling by L sin(theta) leaves f/p ~ max(0, cos theta), which lowers the rmse by a constant factor'
big() {	# big SAMPLER INTEGRAND: rmse at the largest n
	awk -F '\t' -v s="$1" -v f="$2" 'NR > 1 && $1 == s && $4 == f { v = $5 } END { printf "%.4g\n", v }' "$OUT/rmse.tsv"
}
for f in $FUNCS; do
	o=""
	for s in $SAMPLERS; do o="$o${o:+ / }$(big $s $f)"; done
	row "$f: rmse at n = 2^$KMAX $(echo $SAMPLERS | tr ' ' /)" "$o" "-"
done
o=""
for s in $ESAMPLERS; do o="$o${o:+ / }$(big $s env)"; done
row "env: rmse at n = 2^$KMAX ifrs/ijfrs/ihsw/random/jittered/halton/dart" "$o" "-"

# The claims, checked on this run: plain Monte Carlo (random) converges
# as n^-1/2 on every integrand (slope within 0.12); jittered sampling and
# Halton as the theory in the rows says (gauss: -1, at most -0.85; disc
# and step: -0.75 within 0.15); FRS and jittered FRS beat random on every
# uniform integrand at the largest n; and importance sampling lowers the
# rmse of env below every uniform sampler's at the largest n.
exp_note "Not a thesis experiment: the checks are Monte Carlo theory and the claims of frs(7) and of this script; m = $M sets per n, n = 2^$KMIN..2^$KMAX."
exp_note "The time per set includes each program's start and, for FRS, reading the matrix."
o=""
c=""
for i in 2 3 4 5; do
	a=$(sl random $i)
	o="$o${o:+ / }$a"
	c="$c${c:+ && }$a > -0.62 && $a < -0.38"
done
check "uniform random converges as n^-1/2 on gauss, disc, step and env (slope -0.5 +- 0.12)" "$o" "$c"
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
# the best uniform sampler on env
bu=$(for s in random jittered halton dart; do echo "$(big $s env) $s"; done | sort -g | head -n 1)
bv=${bu% *}
bs=${bu#* }
for s in ifrs ijfrs ihsw; do
	a=$(big $s env)
	check_order "$(label $s) beats every uniform sampler on env, the best being $(label $bs) (rmse at n = 2^$KMAX)" \
	    "$a / $bv" "$a < $bv"
done
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
