#!/bin/sh
# Beyond the thesis (issue 13): what the forced-random construction buys
# over the best-known dither mask.  FRS thresholds a matrix; the thesis
# builds it by Forced Random Dithering (frd-gen, Ch. 3), the classical
# alternative is Ulichney's void-and-cluster (frd-gen --method vac, 1993).
# Both matrices are made here at the same size S with seed 1 (timed, one
# thread for vac, all cores for frd), and FRS runs on each (frs-sample -m):
# m sets of n ~ N for the maps uniform (const), blob and ramp.  Measured:
#   gen_s          the matrix's generation time (wall clock)
#   gen_cpu_s      its CPU time (user + system)
#   rho_*          the density rho of Table 6.1 (dda --density, with -i
#                  the Wei-Wang transformed distance for blob and ramp)
#   d2, dinf       star discrepancy of the uniform sets (discrepancy -c
#                  star --exact, the mean over the sets)
#   low            the radial mean power of the uniform sets' spectrum
#                  (dda --fourier) below half the expected peak frequency
#                  sqrt(N) / 2 (without DC): the blue-noise criterion, 1
#                  for white noise
#   peak           the height of the spectrum's first peak (as fig6.9)
#   spread, lowpass  frd-gen --quality of the matrix: the spread of its
#                  first 64 values and the low-pass energy of its first
#                  2.5 %
# Dart throwing (ref-sample -k dart, relaxed-dart for the maps) is the
# reference row.
#
# Parameters per mode:
#   tiny:  S = 64, n = 256, m = 3
#   quick: S = 512, n = 1024, m = 10
#   full:  S = 2048 (the size of the shipped matrix), n = 1024, m = 10;
#          frd at 2048^2 takes minutes, vac about a minute
# Output (RES/vac/): vac.tsv (the table above), vac.md, radial.png
#   (radial means of FRS on both matrices and of dart throwing), blob.png
#   (one FRS set of the blob on each matrix).
# ids: vac void-and-cluster
. "$(dirname "$0")/explib.sh"

S=$(pick 64 512 2048)
N=$(pick 256 1024 1024)
M=$(pick 3 10 10)
K=$(pick 32 96 96)
METHODS="frd vac"
MAPS="uniform blob ramp"
D=$CACHE/vac

mapopt() { [ "$1" = uniform ] || echo "-i $1"; }
matrix() { echo "$D/$1-$S.frd"; }

# gen_matrix METHOD: make the matrix; prints its generation time, wall
# clock and CPU (user + system of frd-gen, from the shell's times, which
# must not run in a subshell).
gen_matrix() {
	mf=$(matrix "$1")	# not f: cached's variable
	opt=""
	[ "$1" = vac ] && opt="--method vac"
	times >"$mf.cpu.$$"
	t0=$(date +%s.%N)
	# shellcheck disable=SC2086
	frd-gen -q $opt -s "$S" -S 1 -o "$mf"
	t1=$(date +%s.%N)
	times >>"$mf.cpu.$$"
	awk -v a="$t0" -v b="$t1" '
	    function sec(t,  m) { m = t; sub(/m.*/, "", m); sub(/^[0-9]*m/, "", t); sub(/s$/, "", t); return 60 * m + t }
	    NR % 2 == 0 { c[NR] = sec($1) + sec($2) }
	    END { printf "%.3f %.3f\n", b - a, c[4] - c[2] }' "$mf.cpu.$$"
	rm -f "$mf.cpu.$$"
}

# sets METHOD MAP: the per-set files (FRS) or the one file (dart).
sets() {
	b=$D/$1-$2-S$S-n$N-m$M
	case $1 in
	dart)
		k=dart
		[ "$2" = uniform ] || k=relaxed-dart
		# shellcheck disable=SC2046
		cached "$b.pts" ref-sample -q -k $k $(mapopt "$2") -n "$N" \
		    --sets "$M"
		echo "--sets $N $b.pts" ;;
	*)
		# shellcheck disable=SC2046
		cached "$b/list" split_frs "$b" -m "$(matrix "$1")" \
		    $(mapopt "$2") -n "$N" --sets "$M" >/dev/null
		cat "$b/list" ;;
	esac
}

# job METHOD MAP: every analysis of one cell.
job() {
	b=$D/$1-$2-S$S-n$N-m$M
	# shellcheck disable=SC2046
	cached "$b-rho.tsv" dda --density -q -j 1 $(mapopt "$2") $(sets "$1" "$2")
	[ "$2" = uniform ] || return 0
	# shellcheck disable=SC2046
	cached "$b-star.tsv" discrepancy -q -j 1 -c star --exact --group all \
	    $(sets "$1" "$2")
	# shellcheck disable=SC2046
	cached "$b-fourier.tsv" dda -q -j 1 --fourier --size "$K" \
	    --radial "$b.rad" $(sets "$1" "$2")
}

if [ "${1:-}" = job ]; then	# worker: sh exp-vac.sh job METHOD MAP
	job "$2" "$3"
	exit 0
fi
if [ "${1:-}" = matrix ]; then	# worker: sh exp-vac.sh matrix METHOD
	cached "$(matrix "$2").time" gen_matrix "$2"
	exit 0
fi

exp_begin vac "FRS on a void-and-cluster matrix against FRS on FRD" \
    "beyond the thesis (Ch. 3 builds FRD; void-and-cluster is Ulichney 1993); $M sets of n ~ $N, matrices of $S^2" \
    "about 90 s (measured; the 2048^2 FRD matrix)"
mkdir -p "$D"
# vac is one thread, frd uses them all: one after the other, so that
# each time is its own.
for m in $METHODS; do sh "$0" matrix "$m"; done
for m in $METHODS dart; do for p in $MAPS; do echo "sh $0 job $m $p"; done; done |
    par_run

# The table.
mean_col() {	# mean_col FILE COLUMN: the "mean" row's value of a column
	awk -F '\t' -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
	    $1 == "mean" { print $h[c]; exit }' "$1"
}
avg_col() {	# avg_col FILE COLUMN: the mean of a column over the rows
	awk -F '\t' -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
	    { s += $h[c]; k++ } END { printf "%.6g\n", s / k }' "$1"
}
radial() {	# radial FILE: "low peak" of a radial mean
	awk -F '\t' -v lim="$(awk -v n="$N" 'BEGIN { print sqrt(n) / 2 }')" \
	    "$BEST_AWK"'
	    NR > 1 && $1 >= 1 && $1 < lim { lo += $2; nl++ }
	    NR > 1 && $1 >= 4 { n++; f[n] = $1; p[n] = $2 }
	    END { best(0, 1e9); printf "%.4f %.4f\n", lo / nl, bp }' "$1"
}
{
	printf 'method\tgen_s\tgen_cpu_s\tspread\tlowpass\trho_uniform\trho_blob\trho_ramp\td2\tdinf\tlow\tpeak\n'
	for m in $METHODS dart; do
		b=$D/$m
		if [ "$m" = dart ]; then
			g=-; gc=-; sp=-; lp=-
		else
			read -r g gc <"$(matrix "$m").time"
			cached "$(matrix "$m").quality" frd-gen --quality "$(matrix "$m")"
			q=$(matrix "$m").quality
			sp=$(awk '$1 == "spread_64" { print $2 }' "$q")
			lp=$(awk '$1 == "lowpass_first_2.5%" { print $2 }' "$q")
		fi
		printf '%s\t%s\t%s\t%s\t%s' "$m" "$g" "$gc" "${sp:--}" "${lp:--}"
		for p in $MAPS; do
			printf '\t%.4f' "$(mean_col "$b-$p-S$S-n$N-m$M-rho.tsv" rho)"
		done
		u=$b-uniform-S$S-n$N-m$M
		printf '\t%.5f\t%.5f' "$(avg_col "$u-star.tsv" D2)" "$(avg_col "$u-star.tsv" Dinf_mean)"
		set -- $(radial "$u.rad")
		printf '\t%s\t%s\n' "$1" "$2"
	done
} >"$OUT/vac.tsv"
awk -F '\t' 'NR == 1 { printf "|"; for (i = 1; i <= NF; i++) printf " %s |", $i
	print ""; printf "|"; for (i = 1; i <= NF; i++) printf " --- |"; print ""; next }
    { printf "|"; for (i = 1; i <= NF; i++) printf " %s |", $i; print "" }' \
    "$OUT/vac.tsv" >"$OUT/vac.md"

{
	gp_png "$OUT/radial.png"
	echo "set title 'Radial mean power of FRS on FRD and on void-and-cluster ($S^2), n = $N, $M sets; 1 = white noise'"
	echo "set xlabel 'frequency'; set ylabel 'radial mean power'"
	echo "set xrange [0:$K]; set yrange [0:3]; set key top right"
	echo "plot '$D/dart-uniform-S$S-n$N-m$M.rad' u 1:2 w l lc rgb 'blue' t 'dart throwing', '$D/frd-uniform-S$S-n$N-m$M.rad' u 1:2 w l lc rgb 'red' t 'FRS on FRD', '$D/vac-uniform-S$S-n$N-m$M.rad' u 1:2 w l lc rgb 'dark-green' t 'FRS on void-and-cluster', 1 w l lc rgb 'gray' dt 2 t 'white noise'"
} | gnuplot
for m in $METHODS; do
	one=$(head -n 1 "$D/$m-blob-S$S-n$N-m$M/list")
	cached "$D/$m-blob.png" pts-render -q -i blob -s 384 "$one"
done
{
	echo "set terminal png size 800,420 font ',10'"
	echo "set output '$OUT/blob.png'"
	echo "set multiplot layout 1,2 title 'One FRS set of the blob (n about $N)'"
	echo "unset key; unset tics; unset border; set size ratio -1"
	echo "set title 'FRD matrix'; plot '$D/frd-blob.png' binary filetype=png with rgbimage"
	echo "set title 'void-and-cluster matrix'; plot '$D/vac-blob.png' binary filetype=png with rgbimage"
	echo "unset multiplot"
} | gnuplot

v() { awk -F '\t' -v m="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i } $1 == m { print $h[c] }' "$OUT/vac.tsv"; }
row "generation time of the $S^2 matrix, FRD / vac (s, wall clock)" "$(v frd gen_s) / $(v vac gen_s)" "not measured (Ch. 3 reports hours for 2048^2)"
row "generation CPU time of the $S^2 matrix, FRD / vac (s)" "$(v frd gen_cpu_s) / $(v vac gen_cpu_s)" "not in the thesis"
row "rho, uniform: FRS on FRD / on vac / dart" "$(v frd rho_uniform) / $(v vac rho_uniform) / $(v dart rho_uniform)" "0.650 for FRS (Table 6.1)"
row "rho, blob: FRS on FRD / on vac / relaxed dart" "$(v frd rho_blob) / $(v vac rho_blob) / $(v dart rho_blob)" "0.643 for FRS"
row "rho, ramp: FRS on FRD / on vac / relaxed dart" "$(v frd rho_ramp) / $(v vac rho_ramp) / $(v dart rho_ramp)" "0.662 for FRS"
row "star D2, FRS on FRD / on vac / dart" "$(v frd d2) / $(v vac d2) / $(v dart d2)" "-"
row "low-frequency power, FRS on FRD / on vac / dart" "$(v frd low) / $(v vac low) / $(v dart low)" "-"
row "first spectral peak, FRS on FRD / on vac / dart" "$(v frd peak) / $(v vac peak) / $(v dart peak)" "-"
# The claims of frs(7), checked: void-and-cluster is cheaper to build;
# its first values are poorly spread (spread_64 below FRD's); adaptive
# FRS, which lives on the first values in dim regions, keeps its density
# on FRD (blob, ramp: rho above vac's) where on void-and-cluster it
# falls apart (below half of FRD's).
exp_note "Not a thesis experiment: the checks are the claims of frs(7) on the void-and-cluster baseline (Ulichney 1993); both matrices ${S}x$S, seed 1; $M sets of n ~ $N per map; vac is built on one thread, FRD on all $(nproc) cores."
a=$(v vac gen_cpu_s)
b=$(v frd gen_cpu_s)
check_order "void-and-cluster cheaper to build than FRD (CPU seconds, ${S}x$S)" "$a / $b" "$a < $b"
a=$(v vac gen_s)
b=$(v frd gen_s)
observe "$a >= $b" "In wall-clock time FRD, on all $(nproc) cores, is built the sooner ($b s against $a s for void-and-cluster on one)."
a=$(v frd spread)
b=$(v vac spread)
check_order "FRD spreads its first 64 values better than void-and-cluster (spread_64, 1 is perfect)" "$a / $b" "$a > $b"
for p in blob ramp; do
	a=$(v frd rho_$p)
	b=$(v vac rho_$p)
	check_order "adaptive FRS ($p) denser on FRD than on void-and-cluster (rho)" "$a / $b" "$a > $b"
	check "adaptive FRS ($p) on void-and-cluster falls apart (rho below half of FRD's)" "$b / $a" "$b < 0.5 * $a"
done
a=$(v frd rho_uniform)
b=$(v vac rho_uniform)
observe "$b > 0.9 * $a" "On the uniform map void-and-cluster keeps FRS's density within 10 % of FRD's (rho $b against $a)."
a=$(v frd low)
b=$(v vac low)
observe "$a < $b" "FRS on FRD has the lower low-frequency power on the uniform map ($a against $b on void-and-cluster)."
observe "$a >= $b" "FRS on void-and-cluster has the lower low-frequency power on the uniform map ($b against $a on FRD)."
exp_end
