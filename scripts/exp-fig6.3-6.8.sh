#!/bin/sh
# Thesis Sec. 6.2, Fig. 6.3-6.8: the average (D2) and worst-case (Dinf)
# discrepancy of uniform sample distributions against the point count n,
# for the shape classes star (Fig. 6.3), rectangle (6.4), quadrilateral
# (6.5), halfspace (6.7) and circle (6.8).  Distributions: FRS
# (frs-sample -i const), jittered FRS (--jitter random), regular, uniform
# random, Poisson disk (ref-sample -k dart) and Halton (Cranley-Patterson
# rotated by the seed).  Every (distribution, n, class) is one discrepancy
# process over m sets (discrepancy --sets N, or --group all over per-set
# files for FRS, whose set sizes vary with the seed), run through par_run.
# The regular grid is the same for every seed, so it is one set.
#
# Parameters per mode:
#   tiny:  n = 2^2..2^5, m = 4;  star --exact; rect --exact; half --grid
#          100; quad, circle --shapes 2000
#   quick: n = 2^2..2^11, m = 20; star --exact; rect --exact for n <= 256,
#          else --exact --grid 100; half --grid 300; quad, circle --shapes
#          20000
#   full:  n = 2^2..2^13, m = 1000 (the thesis); star --exact (exact D2
#          and Dinf, cheaper than and exact where the thesis used the grid
#          3000); rect --exact for n <= 1024, else --exact --grid 500;
#          half --grid 3000; quad, circle --shapes 9000000.  About 210 h on
#          2 cores (quad alone ~1.2e6 CPU s by discrepancy(1)'s table).
# Output (RES/fig6.3-6.8/): CLASS.tsv (dist n sets D2 D2_se Dinf Dinf_mean
#   method) and CLASS.png for CLASS in star rect quad half circle;
#   slopes.tsv (class dist slope_D2 slope_Dinf).
# ids: fig6.3-6.8 fig6.3 fig6.4 fig6.5 fig6.6 fig6.7 fig6.8
. "$(dirname "$0")/explib.sh"

M=$(pick 4 20 1000)
KMAX=$(pick 5 11 13)
SHAPES=$(pick 2000 20000 9000000)
HGRID=$(pick 100 300 3000)
REXACT=$(pick 64 256 1024)     # rect: --exact up to this n
RGRID=$(pick 100 100 500)      # rect: --exact --grid RGRID above it
DISTS="frs jfrs regular random dart halton"
CLASSES="star rect quad half circle"
D=$CACHE/fig6.3-6.8

# sets DIST N: the point sets of DIST with about N points, m sets; prints
# "FILE" (one file of equal sets) or the list of per-set files (FRS).
setname() { echo "$D/$1-n$2-m$M"; }

gen() {	# gen DIST N
	b=$(setname "$1" "$2")
	case $1 in
	frs) cached "$b/list" split_frs "$b" -i const -n "$2" --sets "$M" ;;
	jfrs) cached "$b/list" split_frs "$b" -i const -n "$2" --sets "$M" \
	    --jitter random ;;
	regular) cached "$b.pts" ref-sample -q -k regular -n "$2" ;;
	*) cached "$b.pts" ref-sample -q -k "$1" -n "$2" --sets "$M" ;;
	esac
}

clopts() {	# clopts CLASS N
	case $1 in
	star) echo "--exact" ;;
	rect) if [ "$2" -le "$REXACT" ]; then echo "--exact"; else
		echo "--exact --grid $RGRID"; fi ;;
	half) echo "--grid $HGRID" ;;
	*) echo "--shapes $SHAPES" ;;
	esac
}

tfile() {	# tfile DIST N CLASS: the cached discrepancy table
	echo "$(setname "$1" "$2")-$3-$(clopts "$3" "$2" | tr -d ' -').tsv"
}

disc() {	# disc DIST N CLASS: make the discrepancy table (with header)
	b=$(setname "$1" "$2")
	o=$(clopts "$3" "$2")
	t=$(tfile "$@")
	case $1 in
	frs | jfrs)
		# shellcheck disable=SC2046,SC2086
		cached "$t" discrepancy -q -j 1 -c "$3" $o --group all \
		    $(cat "$b/list") ;;
	regular)
		# shellcheck disable=SC2086
		cached "$t" discrepancy -q -j 1 -c "$3" $o "$b.pts" ;;
	*)
		# shellcheck disable=SC2086
		cached "$t" discrepancy -q -j 1 -c "$3" $o --sets "$2" "$b.pts" ;;
	esac
}

# Worker mode: sh exp-fig6.3-6.8.sh job gen|disc ARGS (what par_run runs).
if [ "${1:-}" = job ]; then
	shift
	w=$1
	shift
	case $w in
	gen) gen "$@" ;;
	disc) disc "$@" ;;
	esac
	exit 0
fi

# NS: the counts, largest first (the longest jobs start first).
NS=$(k=$KMAX; while [ $k -ge 2 ]; do echo $((1 << k)); k=$((k - 1)); done)
exp_begin fig6.3-6.8 "Discrepancy of uniform sample distributions" \
    "Sec. 6.2, Fig. 6.3-6.8; n = 2^2..2^13, m = 1000 sets, star grid 3000, rect grid 500, half grid 3000, quad and circle 3000^2 shapes" \
    "about 210 hours on 2 cores (quad 9000000 shapes x 1000 sets dominates)"
mkdir -p "$D"
self="sh $0 job"
# Every job; one whose result is cached returns at once.
for n in $NS; do for d in $DISTS; do
	echo "$self gen $d $n"
done; done | par_run
for n in $NS; do for c in quad half circle rect star; do for d in $DISTS; do
	echo "$self disc $d $n $c"
done; done; done | par_run

# Gather: one TSV per class.
for c in $CLASSES; do
	{
		printf 'dist\tn\tsets\tD2\tD2_se\tDinf\tDinf_mean\tmethod\n'
		for d in $DISTS; do
			for n in $(echo "$NS" | sort -n); do
				t=$(tfile "$d" "$n" "$c")
				awk -v d="$d" -F '\t' 'NR == 2 {
				    se = ($5 == "-") ? 0 : $5
				    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n",
					d, $2, $3, $4, se, $6, $7, $9 }' "$t"
			done
		done
	} >"$OUT/$c.tsv"
done

# Least-squares slopes of log D2 and log Dinf against log n.
slope() {	# slope CLASS DIST COLUMN
	awk -F '\t' -v d="$2" -v col="$3" 'NR > 1 && $1 == d {
	    x = log($2); y = log($col); sx += x; sy += y; sxx += x * x
	    sxy += x * y; k++ }
	    END { printf "%.2f", (k * sxy - sx * sy) / (k * sxx - sx * sx) }' \
	    "$OUT/$1.tsv"
}
printf 'class\tdist\tslope_D2\tslope_Dinf\n' >"$OUT/slopes.tsv"
for c in $CLASSES; do for d in $DISTS; do
	printf '%s\t%s\t%s\t%s\n' "$c" "$d" "$(slope $c $d 4)" \
	    "$(slope $c $d 6)" >>"$OUT/slopes.tsv"
done; done

# Plots: log-log, D2 solid, Dinf dashed, a colour per distribution.
label() {
	case $1 in
	frs) echo FRS ;; jfrs) echo "jittered FRS" ;; regular) echo regular ;;
	random) echo "uniform random" ;; dart) echo "Poisson disk" ;;
	halton) echo Halton ;;
	esac
}
title() {
	case $1 in
	star) echo "Fig. 6.3: star discrepancy" ;;
	rect) echo "Fig. 6.4: rectangle discrepancy" ;;
	quad) echo "Fig. 6.5: quadrilateral discrepancy" ;;
	half) echo "Fig. 6.7: halfspace discrepancy" ;;
	circle) echo "Fig. 6.8: circle discrepancy" ;;
	esac
}
COLS="#d62728 #ff7f0e #2ca02c #7f7f7f #1f77b4 #9467bd"
for c in $CLASSES; do
	{
		gp_png "$OUT/$c.png"
		echo "set title '$(title $c) (m = $M sets; filled: D2, open: Dinf)'"
		echo "set logscale xy; set xlabel 'n'; set ylabel 'discrepancy'"
		echo "set format y '10^{%L}'; set grid; set key outside right"
		printf 'plot '
		i=1
		for d in $DISTS; do
			[ $i = 1 ] || printf ', '
			col=$(echo "$COLS" | cut -d' ' -f$i)
			printf "'%s' using (strcol(1) eq '%s' ? \$2 : NaN):4 with linespoints lw 2 lc rgb '%s' pt 7 ps 0.7 title '%s D2', " \
			    "$OUT/$c.tsv" "$d" "$col" "$(label $d)"
			printf "'' using (strcol(1) eq '%s' ? \$2 : NaN):6 with linespoints lw 1 lc rgb '%s' pt 6 ps 0.8 title '%s Dinf'" \
			    "$d" "$col" "$(label $d)"
			i=$((i + 1))
		done
		echo
	} | gnuplot
done

# Rows: slopes and the ranking at the largest n beside the thesis.
sl() { awk -F '\t' -v c="$1" -v d="$2" '$1 == c && $2 == d { print $3 }' "$OUT/slopes.tsv"; }
rank() {	# rank CLASS COLUMN: distributions by D2 or Dinf at the largest n
	awk -F '\t' -v col="$2" 'NR > 1 { if ($2 + 0 >= big[$1] + 0) {
	    big[$1] = $2; v[$1] = $col } }
	    END { for (d in v) printf "%s %s\n", v[d], d }' "$OUT/$1.tsv" |
	    sort -g | awk '{ printf "%s%s", (NR > 1 ? " < " : ""), $2 }'
}
thesis_of() {
	case $1 in
	star) echo "Halton lowest; random highest; Poisson disk poor; FRS and the slightly better jittered FRS between Poisson disk and Halton" ;;
	rect) echo "like star, Halton's slope less steep; Halton still best for axis-aligned shapes" ;;
	quad) echo "FRS, jittered FRS below Halton in D2 and Dinf; Poisson disk near random" ;;
	half) echo "regular lowest D2 (as Dobkin et al.); FRS, jittered FRS close to Halton; their Dinf below Halton's; jittered FRS Dinf slightly above FRS" ;;
	circle) echo "regular lowest; then FRS, jittered FRS slightly below Halton; Poisson disk significantly higher" ;;
	esac
}
for c in $CLASSES; do
	row "$c: D2 slope frs/jfrs/regular/random/dart/halton" \
	    "$(sl $c frs) / $(sl $c jfrs) / $(sl $c regular) / $(sl $c random) / $(sl $c dart) / $(sl $c halton)" \
	    "random about -0.5, Poisson disk alike; Halton steeper (Fig. $(title $c | sed 's/Fig. \([0-9.]*\):.*/\1/'))"
	row "$c: D2 order at the largest n (Dinf order)" \
	    "$(rank $c 4) ($(rank $c 6))" "$(thesis_of $c)"
done

# The claims of Sec. 6.2, checked at the largest n of each distribution
# (FRS: the mean set size; regular: the largest square).
at() {	# at CLASS DIST COLUMN: the value at the distribution's largest n
	awk -F '\t' -v d="$2" -v col="$3" 'NR > 1 && $1 == d && $2 + 0 >= big {
	    big = $2 + 0; v = $col } END { print v }' "$OUT/$1.tsv"
}
g3() { awk -v x="$1" 'BEGIN { printf "%.3g", x }'; }
# g2 A B: "A / B" with the digits that tell them apart.
g2() {
	awk -v a="$1" -v b="$2" 'BEGIN { for (p = 3; p < 8; p++) {
	    x = sprintf("%." p "g", a); y = sprintf("%." p "g", b)
	    if (x != y || a == b) break }
	    printf "%s / %s", x, y }'
}
colof() { if [ "$1" = D2 ]; then echo 4; else echo 6; fi; }
# below CLASS MEASURE A B ["why"]: the thesis' order "A below B in
# MEASURE" (D2 or Dinf); a tie, or a D2 difference within 2 standard
# errors of the means of the M sets, is said when it fails (a reversal
# within them is counted in NOISY, for the verdict).
NOISY=""
NNOISY=0
below() {
	bc=$1 bm=$2 bk=$(colof "$2")
	ba=$(at "$bc" "$3" "$bk") bb=$(at "$bc" "$4" "$bk")
	bw="$bc: $(label "$3") below $(label "$4") in $bm${5:+ ($5)}"
	bo=$(g2 "$ba" "$bb")
	if holds "$ba == $bb"; then
		check "$bw" "$bo (tied)" "$ba < $bb" "a tie at this measure's resolution"
		return
	fi
	bcause=""
	if [ "$bm" = D2 ]; then
		bsa=$(at "$bc" "$3" 5) bsb=$(at "$bc" "$4" 5)
		holds "($ba - $bb) * ($ba - $bb) < 4 * ($bsa * $bsa + $bsb * $bsb)" &&
		    bcause="the difference is within 2 standard errors of the means of $M sets"
	fi
	if [ -n "$bcause" ] && ! holds "$ba < $bb"; then
		NOISY="$NOISY${NOISY:+; }$bw"
		NNOISY=$((NNOISY + 1))
	fi
	check_order "$bw" "$bo" "$ba < $bb" "$bcause"
}
# lowest CLASS MEASURE DIST ["why"]: DIST has the lowest MEASURE of all.
lowest() {
	bk=$(colof "$2")
	ba=$(at "$1" "$3" "$bk")
	bn=$(for d in $DISTS; do [ "$d" = "$3" ] ||
	    echo "$(at "$1" "$d" "$bk") $d"; done | sort -g | head -n 1)
	bb=${bn% *}
	check_order "$1: $(label "$3") lowest $2 of all${4:+ ($4)}" \
	    "$(g3 "$ba") / next $(label "${bn#* }") $(g3 "$bb")" "$ba < $bb"
}
# closer CLASS A B F "claim": the D2 of FRS and of jittered FRS is F
# times closer to A's than to B's on a log scale (F = 2: much closer).
closer() {
	cf=$(at "$1" frs 4) cj=$(at "$1" jfrs 4)
	ca=$(at "$1" "$2" 4) cb=$(at "$1" "$3" 4)
	check "$5" "FRS $(g3 "$cf"), jittered $(g3 "$cj") / $(label "$2") $(g3 "$ca") / $(label "$3") $(g3 "$cb")" \
	    "$4 * $4 * log($cf / $ca) * log($cf / $ca) < log($cf / $cb) * log($cf / $cb) && $4 * $4 * log($cj / $ca) * log($cj / $ca) < log($cj / $cb) * log($cj / $cb)"
}

# Fig. 6.3: Halton lowest, random highest, Poisson disk poor, FRS and the
# slightly better jittered FRS between Poisson disk and Halton.
lowest star D2 halton
rs=$(at star random 4)
rn=$(for d in $DISTS; do [ $d = random ] || echo "$(at star $d 4) $d"; done | sort -g | tail -n 1)
check_order "star: uniform random highest D2 of all" \
    "$(g3 "$rs") / next $(label "${rn#* }") $(g3 "${rn% *}")" "$rs > ${rn% *}"
for ms in D2 Dinf; do
	below star $ms halton frs "\"Both FRS and the slightly better jittered FRS range well between Poisson disk and Halton sampling\", Sec. 6.1"
	below star $ms frs dart "\"Both FRS and the slightly better jittered FRS range well between Poisson disk and Halton sampling\", Sec. 6.1"
done
QS='"Both FRS and the slightly better jittered FRS range well between Poisson disk and Halton sampling", Sec. 6.1'
below star D2 halton jfrs "$QS"
below star D2 jfrs dart "$QS"
below star D2 jfrs frs "$QS"
below star Dinf jfrs frs "$QS"
# Fig. 6.4: like star; Halton the best for axis-aligned shapes, its slope
# less steep than for star; jittering impairs only non-axis-parallel shapes.
for ms in D2 Dinf; do
	lowest rect $ms halton "the best for axis-aligned shapes"
	below rect $ms halton frs "as for star"
	below rect $ms frs dart "as for star"
	below rect $ms jfrs frs "as for star"
done
check 'rect: "the slope of the Halton samples'"'"' discrepancy is less steep" than for star (Sec. 6.1, Rectangle Discrepancy)' \
    "$(sl rect halton) / star $(sl star halton)" "$(sl rect halton) > $(sl star halton)"
# Fig. 6.5: FRS and jittered FRS below Halton in D2 and Dinf, much closer
# to Halton than to Poisson disk; jittering impairs the discrepancy.
for ms in D2 Dinf; do
	below quad $ms frs halton
	below quad $ms jfrs halton
	below quad $ms frs dart
done
closer quad halton dart 2 "quad: D2 of FRS and jittered FRS much closer to Halton than to Poisson disk (log scale, 2x)"
below quad D2 frs jfrs "jittering impairs"
# Fig. 6.7: regular lowest D2; FRS and jittered FRS closely match Halton
# in D2, their Dinf below Halton's; jittered FRS's Dinf slightly above FRS.
lowest half D2 regular "as Dobkin et al."
hf=$(at half frs 4) hj=$(at half jfrs 4) hh=$(at half halton 4)
check "half: D2 of FRS and jittered FRS closely match Halton's (within 25 %)" \
    "$(g3 "$hf"), $(g3 "$hj") / $(g3 "$hh")" \
    "$hf < 1.25 * $hh && $hf > 0.8 * $hh && $hj < 1.25 * $hh && $hj > 0.8 * $hh"
below half Dinf frs halton
below half Dinf jfrs halton
below half Dinf frs jfrs "jittered FRS slightly higher"
below half D2 frs jfrs "jittering impairs"
below half D2 frs dart
below half Dinf frs dart
# Fig. 6.8: regular lowest; FRS and jittered FRS slightly below Halton,
# significantly below Poisson disk.
lowest circle D2 regular
lowest circle Dinf regular
for ms in D2 Dinf; do
	below circle $ms frs halton
	below circle $ms jfrs halton
done
below circle D2 frs dart
below circle Dinf frs dart
cf=$(at circle frs 4) cj=$(at circle jfrs 4) cdd=$(at circle dart 4)
check "circle: D2 of FRS and jittered FRS significantly below Poisson disk's (by 20 %)" \
    "$(g3 "$cf"), $(g3 "$cj") / $(g3 "$cdd")" "$cf < 0.8 * $cdd && $cj < 0.8 * $cdd"
below circle D2 frs jfrs "jittering impairs"
# Every class: FRS below random; the slopes against n.
# (each condition the conjunction over the classes, the numbers in it,
# so that the report prints what was tested)
fr="" fx=""
for c in $CLASSES; do
	a=$(at $c frs 4) b=$(at $c random 4) e=$(at $c frs 6) f=$(at $c random 6)
	fr="$fr${fr:+; }$c D2 $(g3 "$a")/$(g3 "$b"), Dinf $(g3 "$e")/$(g3 "$f")"
	fx="$fx${fx:+ && }$a < $b && $e < $f"
done
check_order "FRS below uniform random in D2 and Dinf, every class" "$fr" "$fx"
sr="" sd="" sh="" xr="" xd="" xh=""
for c in $CLASSES; do
	r=$(sl $c random) d=$(sl $c dart) h=$(sl $c halton)
	sr="$sr${sr:+, }$c $r"
	sd="$sd${sd:+, }$c $d/$r"
	sh="$sh${sh:+, }$c $h/$r"
	xr="$xr${xr:+ && }$r > -0.6 && $r < -0.4"
	xd="$xd${xd:+ && }$d - ($r) < 0.1 && $r - ($d) < 0.1"
	xh="$xh${xh:+ && }$h < $r - 0.1"
done
check "uniform random's D2 slope about -0.5 (within 0.1), every class" "$sr" "$xr"
check '"Although it has a high spatial uniformity, the asymptotic behavior of its discrepancy is very similar to the one of uniform random sampling" (Poisson disk; Sec. 6.1, Summary): D2 slopes within 0.1 of random'"'"'s, every class' \
    "Poisson disk/random $sd" "$xd"
check 'Halton a low-discrepancy sequence ("this is what low-discrepancy sequences are designed for", Sec. 6.1, Star Discrepancy): its D2 slope steeper than random'"'"'s by 0.1, every class' "Halton/random $sh" "$xh"
observe "$NNOISY > 0" "Of the D2 reversals, $NNOISY lie within 2 standard errors of the means of the $M sets: $NOISY."

exp_note "m = $M sets (the thesis: 1000), n up to 2^$KMAX (2^13); FRS's n is the mean size of its sets, the regular grid's the nearest square."
exp_note "Star and rect D2 and Dinf are exact (closed forms; rect above n = $REXACT on a grid of $RGRID), where the thesis used grids of 3000 and 500; half uses a border grid of $HGRID, quad and circle $SHAPES random shapes per set (the thesis: 3000 and 3000^2)."
exp_end
