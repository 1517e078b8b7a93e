#!/bin/sh
# Thesis Sec. 6.2 (Density), Table 6.1: the density rho of Lagae and Dutre
# (dda --density, Eq. 6.21, 6.22; with -i the transformed distance of Wei
# and Wang for adaptive sets) averaged over m sets of n ~ 1024, for the
# distributions Reference (ref-sample -k dart for uniform, -k relaxed-dart
# -i MAP for the maps), FRS (the multi-level window, the default), FRS
# with the thesis's window (--tiles plain), jittered FRS (--jitter
# random), and Poisson
# disk, Random, Regular, Halton warped by HSW (hsw-sample --input
# dart|random|regular|halton), in the columns Uniform (no map: the plain
# distance; for the HSW rows the unwarped input sets of ref-sample),
# Constant (const), Gaussian Blob (blob), Linear Gradient (ramp) and
# Environment ($ENVMAP resampled to 128x64 for every tool).  FRS sets vary
# in size with the seed, so they are split into per-set files.
#
# Parameters per mode:
#   tiny:  n = 256, m = 3 sets
#   quick: n = 1024, m = 10 sets (the thesis parameters)
#   full:  n = 1024, m = 10 sets (the thesis parameters), under a minute
# Output (RES/tab6.1/): tab6.1.tsv (dist uniform constant blob ramp
#   environment: mean rho), thesis.tsv (the same for the thesis' table),
#   sets.tsv (dist map set n dmin rho: every set), tab6.1.md (ours/thesis
#   per cell) and tab6.1.png (bar chart, ours beside the thesis).
# ids: tab6.1 table6.1
. "$(dirname "$0")/explib.sh"

N=$(pick 256 1024 1024)
M=$(pick 3 10 10)
DISTS="reference frs pfrs jfrs dart random regular halton"
MAPS="uniform constant blob ramp environment"
D=$CACHE/tab6.1

spec() {	# the map option words of a column ("" for uniform)
	case $1 in
	uniform) echo "" ;;
	constant) echo "-i const" ;;
	blob) echo "-i blob" ;;
	ramp) echo "-i ramp" ;;
	environment) echo "-i $ENVMAP -s 128x64" ;;
	esac
}

# hsw_sets MAP KIND: M sets of HSW-warped KIND points (seeds 1..M), text.
hsw_sets() {
	s=1
	while [ $s -le "$M" ]; do
		# shellcheck disable=SC2046
		hsw-sample -q $(spec "$1") --input "$2" -n "$N" -S $s -T |
		    grep -v '^#'
		s=$((s + 1))
	done
}

# density DIST MAP: the per-set density table of one cell.
density() {
	b=$D/$1-$2-n$N-m$M
	mo=$(spec "$2")
	case $1 in
	frs | pfrs | jfrs)
		j=none t=levels
		[ "$1" = jfrs ] && j=random
		[ "$1" = pfrs ] && t=plain
		# shellcheck disable=SC2086
		cached "$b/list" split_frs "$b" $mo -n "$N" --sets "$M" --jitter $j \
		    --tiles $t
		# shellcheck disable=SC2046,SC2086
		cached "$b.tsv" dda --density -q -j 1 $mo $(cat "$b/list") ;;
	reference)
		if [ "$2" = uniform ]; then
			cached "$b.pts" ref-sample -q -k dart -n "$N" --sets "$M"
		else
			# shellcheck disable=SC2086
			cached "$b.pts" ref-sample -q -k relaxed-dart $mo -n "$N" --sets "$M"
		fi
		# shellcheck disable=SC2086
		cached "$b.tsv" dda --density -q -j 1 $mo --sets "$N" "$b.pts" ;;
	*)
		if [ "$2" = uniform ]; then
			cached "$b.pts" ref-sample -q -k "$1" -n "$N" --sets "$M"
		else
			# the map words last, for the cache key only
			# shellcheck disable=SC2086
			cached "$b.pts" hsw_sets "$2" "$1" $mo
		fi
		# shellcheck disable=SC2086
		cached "$b.tsv" dda --density -q -j 1 $mo --sets "$N" "$b.pts" ;;
	esac
}

if [ "${1:-}" = job ]; then	# worker: sh exp-tab6.1.sh job DIST MAP
	density "$2" "$3"
	exit 0
fi

exp_begin tab6.1 "Density rho per distribution and importance map" \
    "Sec. 6.2, Table 6.1; 10 sets of n ~ 1024 per distribution and map, transformed distance of Wei and Wang for the maps" \
    "about 10 s (measured)"
mkdir -p "$D"
for d in $DISTS; do for m in $MAPS; do echo "sh $0 job $d $m"; done; done |
    par_run

# Every set, and the table of means.
printf 'dist\tmap\tset\tn\tdmin\trho\n' >"$OUT/sets.tsv"
for d in $DISTS; do for m in $MAPS; do
	awk -F '\t' -v d="$d" -v m="$m" 'NR > 1 && $1 != "mean" {
	    printf "%s\t%s\t%s\t%s\t%s\t%s\n", d, m, $1, $2, $3, $4 }' \
	    "$D/$d-$m-n$N-m$M.tsv" >>"$OUT/sets.tsv"
done; done
awk -F '\t' -v dists="$DISTS" -v maps="$MAPS" 'NR > 1 {
	s[$1 SUBSEP $2] += $6; k[$1 SUBSEP $2]++ }
    END { nd = split(dists, D, " "); nm = split(maps, Mp, " ")
	printf "dist"; for (j = 1; j <= nm; j++) printf "\t%s", Mp[j]; print ""
	for (i = 1; i <= nd; i++) { printf "%s", D[i]
	    for (j = 1; j <= nm; j++)
		printf "\t%.3f", s[D[i] SUBSEP Mp[j]] / k[D[i] SUBSEP Mp[j]]
	    print "" } }' "$OUT/sets.tsv" >"$OUT/tab6.1.tsv"

# The thesis' Table 6.1.
cat >"$OUT/thesis.tsv" <<'EOF'
dist	uniform	constant	blob	ramp	environment
reference	0.700	0.700	0.700	0.700	0.700
frs	0.650	0.681	0.643	0.662	0.644
pfrs	0.650	0.681	0.643	0.662	0.644
jfrs	0.621	0.668	0.634	0.617	0.661
dart	0.700	0.700	0.261	0.370	0.142
random	0.014	0.003	0.004	0.001	0.008
regular	0.930	0.930	0.318	0.439	0.357
halton	0.170	0.066	0.149	0.138	0.041
EOF

name() {
	case $1 in
	reference) echo "Reference" ;; frs) echo "FRS" ;;
	pfrs) echo "FRS, the thesis's window (plain tiles)" ;;
	jfrs) echo "Jittered FRS" ;; dart) echo "Poisson Disk" ;;
	random) echo "Random" ;; regular) echo "Regular" ;;
	halton) echo "Halton" ;;
	esac
}
cell() { awk -F '\t' -v d="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i }
    $1 == d { print $k }' "$1"; }

# Markdown table, ours/thesis in each cell, and the summary rows.
{
	echo "| rho (ours/thesis) | Uniform | Constant | Gaussian Blob | Linear Gradient | Environment |"
	echo "| --- | --- | --- | --- | --- | --- |"
	for d in $DISTS; do
		printf '| %s |' "$(name $d)"
		for m in $MAPS; do
			printf ' %s/%s |' "$(cell "$OUT/tab6.1.tsv" $d $m)" \
			    "$(cell "$OUT/thesis.tsv" $d $m)"
		done
		echo
	done
} >"$OUT/tab6.1.md"
for d in $DISTS; do
	o=""
	t=""
	for m in $MAPS; do
		o="$o${o:+ / }$(cell "$OUT/tab6.1.tsv" $d $m)"
		t="$t${t:+ / }$(cell "$OUT/thesis.tsv" $d $m)"
	done
	row "rho $(name $d) (Uniform / Constant / Blob / Gradient / Environment)" "$o" "$t"
done

# Bar chart: ours (top) and the thesis (bottom), a bar per map.
{
	gp_png "$OUT/tab6.1.png"
	echo "set multiplot layout 2,1"
	echo "set style data histograms; set style histogram clustered gap 1"
	echo "set style fill solid 0.8 border -1; set boxwidth 0.9"
	echo "set yrange [0:1.05]; set ylabel 'rho'; set grid ytics"
	echo "set key outside right; set xtics nomirror"
	echo "set arrow from graph 0, first 0.65 to graph 1, first 0.65 nohead dt 2 lc rgb '#888888'"
	echo "set arrow from graph 0, first 0.85 to graph 1, first 0.85 nohead dt 2 lc rgb '#888888'"
	for f in tab6.1 thesis; do
		if [ $f = tab6.1 ]; then
			echo "set title 'Table 6.1, ours: density rho, $M sets of n = $N (dashed: 0.65-0.85)'"
		else
			echo "set title 'Table 6.1, the thesis'"
		fi
		echo "plot '$OUT/$f.tsv' using 2:xtic(1) title 'Uniform', '' using 3 title 'Constant', '' using 4 title 'Gaussian Blob', '' using 5 title 'Linear Gradient', '' using 6 title 'Environment'"
	done
	echo "unset multiplot"
} | gnuplot

# The claims of Sec. 6.2 on Table 6.1, checked.
v() { cell "$OUT/tab6.1.tsv" "$1" "$2"; }
vals() {	# vals DIST MAP...: "MAP value, ..."
	vd=$1
	shift
	for vm in "$@"; do printf '%s%s %s' "${vs:+, }" "$vm" "$(v "$vd" "$vm")"; vs=1; done
	vs=
}
# all DIST "CONDITION on x" MAP...: the condition holds for every map
all() {
	ad=$1 ac=$2
	shift 2
	for am in "$@"; do holds "$(echo "$ac" | sed "s/x/$(v "$ad" "$am")/g")" || { echo 0; return; }; done
	echo 1
}
for m in $MAPS; do
	x=$(v frs $m)
	check "$m: FRS rho in the lower end of Lagae and Dutre's 0.65-0.85 (0.60-0.75; the thesis 0.643-0.681)" \
	    "$x" "$x >= 0.6 && $x <= 0.75"
done
fmin=$(for m in $MAPS; do v frs $m; done | sort -g | head -n 1)
fmax=$(for m in $MAPS; do v frs $m; done | sort -g | tail -n 1)
check "FRS rho very similar for all maps (spread at most 0.08; the thesis 0.038)" \
    "$fmin to $fmax" "$fmax - $fmin <= 0.08"
check "Reference (dart, relaxed dart on the maps) about 0.7 on every map (0.65-0.75)" \
    "$(vals reference $MAPS)" "$(all reference "x >= 0.65 && x <= 0.75" $MAPS) == 1"
check "Poisson disk input about 0.7 unwarped and on the constant map (0.65-0.75)" \
    "$(vals dart uniform constant)" "$(all dart "x >= 0.65 && x <= 0.75" uniform constant) == 1"
check "Regular 0.930 unwarped and on the constant map (within 0.01)" \
    "$(vals regular uniform constant)" "$(all regular "x >= 0.92 && x <= 0.94" uniform constant) == 1"
check "Random near 0 on every map (below 0.05)" "$(vals random $MAPS)" "$(all random "x < 0.05" $MAPS) == 1"
# HSW does not keep its input's density where it warps non-uniformly.
for d in dart regular; do
	u=$(v $d uniform)
	check "HSW loses the density of $(name $d) input on the non-uniform maps (below 0.8 times unwarped)" \
	    "$(vals $d blob ramp environment) / unwarped $u" "$(all $d "x < 0.8 * $u" blob ramp environment) == 1"
done
u=$(v halton uniform)
check "HSW loses the density of Halton input on the non-uniform maps (below unwarped)" \
    "$(vals halton blob ramp environment) / unwarped $u" "$(all halton "x < $u" blob ramp environment) == 1"
# Jittered FRS slightly below FRS (the thesis: in 4 of 5 maps, by 0.016 on
# average).
jl=$(for m in $MAPS; do holds "$(v jfrs $m) < $(v frs $m)" && echo $m; done | wc -l)
jd=$(for m in $MAPS; do echo "$(v frs $m) $(v jfrs $m)"; done |
    awk '{ s += $1 - $2; k++ } END { printf "%.3f", s / k }')
check_order "Jittered FRS below FRS (in at least 3 of 5 maps)" \
    "$jl of 5: $(vals jfrs $MAPS)" "$jl >= 3"
check "Jittered FRS only slightly below FRS (on average by 0 to 0.05)" "$jd" "$jd >= 0 && $jd <= 0.05"
fu=$(v frs uniform) fc=$(v frs constant)
observe "$fu == $fc" "Uniform and Constant give the same FRS value ($fu; the thesis 0.650 and 0.681): frs-sample without a map samples the constant map, so they are the same sets."
# The environment map as the tools read it (128x64): its peak over its mean.
cached "$D/env-128x64.exr" imap convert -q -s 128x64 --format exr "$ENVMAP" -
cached "$D/env-128x64.info" imap info "$D/env-128x64.exr"
pk=$(awk '$1 == "max" { m = $2 } $1 == "mean" { a = $2 } END { printf "%.0f", m / a }' "$D/env-128x64.info")
fe=$(v frs environment) pe=$(v pfrs environment)
observe "$fe < 0.6" "FRS's rho on the environment map is $fe (the thesis 0.644); at 128x64 our map's maximum is $pk times its mean."
vl=$(frs-sample -q -i "$ENVMAP" -s 128x64 -n "$N" --tiles plain -v -o /dev/null 2>&1)
win=$(echo "$vl" | sed -n 's/.*window \([0-9x]*\) at.*/\1/p' | head -n 1)
mat=$(echo "$vl" | sed -n 's/.*matrix [^ ]* \([0-9x]*\),.*/\1/p')
observe "$fe > $pe" "On the environment map the multi-level window gives rho $fe, the thesis's window (plain tiles) $pe: the thesis's window is $win elements for a $mat matrix, repeated as it is where the map is dark."
exp_note "Environment: $(basename "$ENVMAP") resampled to 128x64 for every tool, not the thesis' Grace Cathedral probe."
exp_end
