#!/bin/sh
# Beyond the thesis (issue 13): Forced Random Sampling in three
# dimensions, which the thesis claims (k-D, Sec. 4.1) but does not
# measure.  FRS samples the shipped 64^3 matrix (data/default3.frd)
# with sigma 4 (frs; 64 window elements per sample at the maximum, as
# sigma 8 gives in the plane; 4096 samples without repetition), jittered
# (jfrs, --jitter random) and with sigma 8 (frs8; 512 without
# repetition); against ref-sample -d 3: random, jittered (round(cbrt n)^3
# strata), Halton (2, 3, 5), Sobol and dart throwing.
#   star discrepancy: discrepancy -c star --exact (Warnock's D2 and the
#     exact Dinf over the critical boxes) of m sets per n, the mean over
#     the sets, and the least-squares slopes of log D on log n;
#   density: dda --density (rho = dmin / (sqrt 2 / n)^(1/3), the FCC
#     spacing), m sets of n = ND;
#   importance: FRS of blob3:sigma=0.15 and ramp3 (32^3 volumes), the
#     mean and standard deviation of the coordinates against those of the
#     volume (computed here from the spec's closed form per voxel);
#   time: frs-sample -v thresholding time of 3-D FRS (sorted, one
#     thread) for blob3 at n = 2^10 .. 2^NT, beside 2-D FRS of blob (the
#     default matrix prepared as in fig6.13).
# Parameters per mode:
#   tiny:  n = 2^4..2^6, m = 3, ND = 64, NT = 12
#   quick: n = 2^4..2^10, m = 20, ND = 1024, NT = 20
#   full:  n = 2^4..2^12 (the exact Dinf's limit), m = 100, ND = 1024,
#          NT = 22
# Output (RES/3d/): disc.tsv (dist n sets D2 Dinf), slopes.tsv, disc.png
#   (D2 and Dinf against n), density.tsv, importance.tsv, time.tsv,
#   blob3.png and shell3.png (projections xy and xz of one set).
# ids: 3d three-d
. "$(dirname "$0")/explib.sh"
EXP_MATRIX="$FRS_MATRIX $FRS_MATRIX3"	# 3-D FRS, and 2-D beside it

KMIN=4
KMAX=$(pick 6 10 12)
M=$(pick 3 20 100)
ND=$(pick 64 1024 1024)
NT=$(pick 12 20 22)
DISTS="frs jfrs frs8 random jittered halton sobol dart"
D=$CACHE/3d

frsopt() {	# the frs-sample options of an FRS variant
	case $1 in
	frs) echo "--sigma 4" ;;
	jfrs) echo "--sigma 4 --jitter random" ;;
	frs8) echo "--sigma 8" ;;
	esac
}

# sets DIST N: the discrepancy and dda arguments naming m sets of ~N.
sets() {
	b=$D/$1-n$2-m$M
	case $1 in
	frs | jfrs | frs8)
		# shellcheck disable=SC2046
		cached "$b/list" split_frs "$b" -i const $(frsopt "$1") -n "$2" \
		    --sets "$M" >/dev/null
		echo "--group all $(cat "$b/list")" ;;
	*)
		cached "$b.pts" ref-sample -q -d 3 -k "$1" -n "$2" --sets "$M"
		c=$(od -A n -t u8 -j 24 -N 8 "$b.pts" | tr -d ' ')
		echo "--sets $((c / M)) $b.pts" ;;
	esac
}

job() {	# job DIST N
	# shellcheck disable=SC2046
	cached "$D/$1-n$2-m$M-star.tsv" discrepancy -q -j 1 -c star --exact \
	    $(sets "$1" "$2")
	if [ "$2" = "$ND" ]; then
		# shellcheck disable=SC2046
		cached "$D/$1-n$2-m$M-rho.tsv" dda -q -j 1 --density \
		    $(sets "$1" "$2" | sed 's/--group all//')
	fi
}

if [ "${1:-}" = job ]; then	# worker: sh exp-3d.sh job DIST N
	job "$2" "$3"
	exit 0
fi

exp_begin 3d "Forced Random Sampling in three dimensions (beyond the thesis)" \
    "not in the thesis (issue 13; Sec. 4.1 claims k-D); 64^3 FRD matrix, star discrepancy of m = $M sets for n = 2^$KMIN..2^$KMAX, density at n = $ND" \
    "about 17 minutes on 2 cores (measured; the exact Dinf at n = 2^12 for 100 sets)"
mkdir -p "$D"
NS=$(k=$KMAX; while [ $k -ge $KMIN ]; do echo $((1 << k)); k=$((k - 1)); done)
case " $NS " in *" $ND "*) ;; *) NS="$NS $ND" ;; esac
for n in $NS; do for d in $DISTS; do echo "sh $0 job $d $n"; done; done |
    par_run

# Discrepancy against n, and the slopes.
{
	printf 'dist\tn\tsets\tD2\tDinf\n'
	for d in $DISTS; do for n in $(echo "$NS" | tr ' ' '\n' | sort -n); do
		awk -F '\t' -v d="$d" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
		    { printf "%s\t%s\t%s\t%s\t%s\n", d, $h["n"], $h["sets"], $h["D2"], $h["Dinf_mean"] }' \
		    "$D/$d-n$n-m$M-star.tsv"
	done; done
} >"$OUT/disc.tsv"
slope() {	# slope DIST COLUMN
	awk -F '\t' -v d="$1" -v c="$2" 'NR > 1 && $1 == d && $c > 0 {
	    x = log($2); y = log($c); sx += x; sy += y; sxx += x * x; sxy += x * y; k++ }
	    END { printf "%.2f\n", (k * sxy - sx * sy) / (k * sxx - sx * sx) }' "$OUT/disc.tsv"
}
{
	printf 'dist\tslope_D2\tslope_Dinf\n'
	for d in $DISTS; do printf '%s\t%s\t%s\n' "$d" "$(slope $d 4)" "$(slope $d 5)"; done
} >"$OUT/slopes.tsv"
{
	gp_png "$OUT/disc.png"
	echo "set terminal png size 1300,520 font ',10'"
	echo "set multiplot layout 1,2 title '3-D star discrepancy, $M sets per n (exact)'"
	echo "set logscale xy; set xlabel 'n'; set grid; set key bottom left"
	for c in 4:D2 5:Dinf; do
		echo "set title '${c#*:}'; set ylabel '${c#*:}'"
		printf 'plot '
		i=0
		for d in $DISTS; do
			[ $i = 0 ] || printf ', '
			printf "'%s' u (strcol(1) eq '%s' ? \$2 : NaN):%s w lp pt 7 ps 0.6 t '%s'" \
			    "$OUT/disc.tsv" "$d" "${c%:*}" "$d"
			i=1
		done
		echo
	done
	echo "unset multiplot"
} | gnuplot

# Density at n = ND.
{
	printf 'dist\tn\trho\n'
	for d in $DISTS; do
		awk -F '\t' -v d="$d" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
		    $1 == "mean" { printf "%s\t%s\t%.4f\n", d, $h["n"], $h["rho"] }' \
		    "$D/$d-n$ND-m$M-rho.tsv"
	done
} >"$OUT/density.tsv"

# Importance: coordinate means and deviations of FRS against the volume.
# blob3's voxel means are products of 1-D Gaussian means; those of ramp3
# (z from 0 to 1) linear; both are evaluated here on the 32^3 grid.
NI=$(pick 512 8192 65536)
cached "$D/blob3-n$NI.txt" frs-sample -q -i blob3:sigma=0.15 --sigma 4 -n "$NI" -T
cached "$D/ramp3-n$NI.txt" frs-sample -q -i ramp3 --sigma 4 -n "$NI" -T
want() {	# want blob|ramp AXIS: "mean sd" of the voxel-centre density
	awk -v kind="$1" -v ax="$2" 'function g(a, b) {	# mean of the Gaussian over [a, b]
		return (erf_((b - 0.5) / (0.15 * sqrt(2))) - erf_((a - 0.5) / (0.15 * sqrt(2)))) }
	    function erf_(x,  t, y, s) {	# Abramowitz-Stegun 7.1.26
		s = x < 0 ? -1 : 1; x = x < 0 ? -x : x
		t = 1 / (1 + 0.3275911 * x)
		y = 1 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t * exp(-x * x)
		return s * y }
	    BEGIN { for (k = 0; k < 32; k++) {
		w = kind == "blob" ? g(k / 32, (k + 1) / 32) : (ax == 3 ? (k + 0.5) / 32 : 1)
		x = (k + 0.5) / 32; s += w; s1 += w * x; s2 += w * (x * x + 1 / (12 * 32 * 32)) }
		m = s1 / s; printf "%.4f %.4f\n", m, sqrt(s2 / s - m * m) }'
}
got() {	# got FILE AXIS: "mean sd" of the points
	awk -v ax="$2" '!/^#/ { s += $ax; q += $ax * $ax; n++ }
	    END { m = s / n; printf "%.4f %.4f\n", m, sqrt(q / n - m * m) }' "$1"
}
{
	printf 'volume\taxis\tmean\tmean_want\tsd\tsd_want\n'
	for v in blob ramp; do for ax in 1 2 3; do
		set -- $(got "$D/${v}3-n$NI.txt" $ax) $(want $v $ax)
		printf '%s3\t%s\t%s\t%s\t%s\t%s\n' "$v" "$(echo xyz | cut -c$ax)" "$1" "$3" "$2" "$4"
	done; done
} >"$OUT/importance.tsv"

# Time: 3-D against 2-D FRS, sorted, one thread; 2-D on the default
# matrix prepared by frd-prep (FRP), as fig6.13, so that neither counts
# building its sorted lists (3-D builds them in its setup).
timing_inputs ""
thr() {	# thr ARGS...: frs-sample's thresholding seconds and count
	frs-sample -q -j 1 -v -o /dev/null "$@" 2>&1 |
	    sed -n 's/^frs-sample: \([0-9]*\) samples.*thresholding \([0-9.]*\) s.*/\2 \1/p'
}
{
	printf 'n\tthreshold_3d_s\tsamples_3d\tthreshold_2d_s\tsamples_2d\tns_per_sample_3d\tns_per_sample_2d\n'
	e=10
	while [ $e -le "$NT" ]; do
		n=$((1 << e))
		set -- $(thr -i blob3 -n $n --sigma 4) $(thr -m "$FRP" -i blob -n $n)
		awk -v n=$n -v a="$1" -v b="$2" -v c="$3" -v d="$4" 'BEGIN {
		    printf "%d\t%s\t%s\t%s\t%s\t%.1f\t%.1f\n", n, a, b, c, d, 1e9 * a / b, 1e9 * c / d }'
		e=$((e + 2))
	done
} >"$OUT/time.tsv"

# Pictures: one set of blob3 and of shell3, projected on xy and xz.
cached "$D/shell3-n$ND.pts" frs-sample -q -i shell3 --sigma 4 -n "$ND"
cached "$D/blob3-n$ND.pts" frs-sample -q -i blob3 --sigma 4 -n "$ND"
for v in blob3 shell3; do
	for a in xy xz; do
		cached "$D/$v-$a.png" pts-render -q -s 320 --axes $a "$D/$v-n$ND.pts"
	done
	{
		echo "set terminal png size 700,380 font ',10'"
		echo "set output '$OUT/$v.png'"
		echo "set multiplot layout 1,2 title '3-D FRS of $v, n about $ND: projections'"
		echo "unset key; unset tics; unset border; set size ratio -1"
		for a in xy xz; do
			echo "set title '$a'; plot '$D/$v-$a.png' binary filetype=png with rgbimage"
		done
		echo "unset multiplot"
	} | gnuplot
done

sv() { awk -F '\t' -v d="$1" -v c="$2" '$1 == d { print $c }' "$OUT/slopes.tsv"; }
dv() { awk -F '\t' -v d="$1" '$1 == d { print $3 }' "$OUT/density.tsv"; }
o=""
for d in $DISTS; do o="$o${o:+ / }$(sv $d 2)"; done
row "star D2 slope $(echo $DISTS | tr ' ' /)" "$o" "not in the thesis; expected from theory: random -0.5, jittered -(1/2 + 1/6) = -0.67, QMC about -1"
o=""
for d in $DISTS; do o="$o${o:+ / }$(dv $d)"; done
row "density rho at n = $ND, $(echo $DISTS | tr ' ' /)" "$o" "not in the thesis for 3-D (2-D FRS: 0.650 against the reference's 0.700, Table 6.1); reference here: dart throwing"
# imp VOLUME COLUMN: the values of a column of importance.tsv, per axis
imp() { awk -F '\t' -v v="$1" -v c="$2" '$1 == v { printf "%s%s %s", s, $2, $c; s = ", " }' "$OUT/importance.tsv"; }
row "blob3 (sigma 0.15): sd per axis" "$(imp blob3 5)" "not in the thesis; expected (the volume's, closed form): $(imp blob3 6)"
row "ramp3: mean per axis" "$(imp ramp3 3)" "not in the thesis; expected (the volume's, closed form): $(imp ramp3 4)"
tl=$(awk -F '\t' 'NR > 1 { l = $6 " / " $7 " ns (n = " $1 ")" } END { print l }' "$OUT/time.tsv")
row "thresholding time per sample, 3-D / 2-D, sorted, one thread" "$tl" "not in the thesis"

# The claims, checked: frs(7) and the thesis (Sec. 4.1) call FRS
# k-dimensional; in 3-D it should keep what it has in the plane: a star
# discrepancy converging faster than random's, a density near dart
# throwing's (2-D, Table 6.1: FRS at 0.93 of the reference; here at least
# 0.9), and samples that follow the importance volume (coordinate means
# and deviations within 0.01 of the volume's).
exp_note "Not a thesis experiment: the thesis claims FRS in k dimensions (Sec. 4.1) but measures it only in the plane; the checks ask whether 3-D FRS (sigma 4, the 64^3 matrix) keeps what FRS has in the plane; m = $M sets per n."
f=$(sv frs 2)
r=$(sv random 2)
check_order "3-D FRS converges faster than random (star D2 slope)" "$f / $r" "$f < $r"
f=$(dv frs)
r=$(dv random)
d=$(dv dart)
check_order "3-D FRS denser than random (rho at n = $ND)" "$f / $r" "$f > $r"
check "3-D FRS about as dense as dart throwing (rho at least 0.9 x dart's $d)" "$f" "$f >= 0.9 * $d"
for v in blob3 ramp3; do
	e=$(awk -F '\t' -v v=$v '$1 == v { d = $3 - $4; e = $5 - $6; d = d < 0 ? -d : d; e = e < 0 ? -e : e
	    if (d > m) m = d; if (e > m) m = e } END { printf "%.4f", m }' "$OUT/importance.tsv")
	check "3-D FRS follows $v: coordinate means and deviations within 0.01 of the volume's (largest difference)" "$e" "$e <= 0.01"
done
f=$(sv frs 2)
j=$(sv jittered 2)
observe "$f < $j" "3-D FRS's D2 also falls faster than jittered sampling's (slope $f against $j)."
observe "$f >= $j" "3-D FRS's D2 falls more slowly than jittered sampling's (slope $f against $j)."
exp_end
