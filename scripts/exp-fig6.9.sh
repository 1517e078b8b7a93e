#!/bin/sh
# Thesis Sec. 6.3 (Spectral analysis, Fourier analysis), Fig. 6.9:
# estimated Fourier power spectra, with radial mean and anisotropy, of
# uniform sample distributions: FRS, jittered FRS (sigma 8, random
# jitter, the same window offsets as FRS: same seeds), uniform random,
# regular, Halton (Cranley-Patterson rotated per seed) and dart throwing
# (the reference).  dda --fourier --png --radial averages the
# periodograms of the sets.
#   tiny : 2 sets of 256 points, frequencies up to 32
#   quick: 10 sets of 1024 points, frequencies up to 128 (the thesis')
#   full : the same as quick (it takes seconds)
# Writes radial-DIST.tsv (freq, power, aniso_db, count: dda --radial),
# peaks.tsv (the radial-mean peaks and mean anisotropy per
# distribution), spectra/DIST.png (the spectrum images), fig6.9.png (the
# figure: spectra over radial mean and anisotropy) and
# fig6.9-radial.png (radial means of FRS, jittered FRS and dart
# throwing on one plot).
# ids: fig6.9
. "$(dirname "$0")/explib.sh"
SELF=$TOP/scripts/exp-fig6.9.sh
if [ "${1:-}" = --cached ]; then
	shift
	cached "$@"
	exit 0
fi
exp_begin fig6.9 "Fourier power spectra of uniform sampling" \
    "Sec. 6.3, Fig. 6.9: 10 sets of 1024 points, FRS and jittered FRS (sigma 8) against random, regular, Halton and dart throwing" \
    "a few seconds"

N=$(pick 256 1024 1024)
M=$(pick 2 10 10)
K=$(pick 32 128 128)
C=$CACHE/fig6.9
mkdir -p "$C" "$OUT/spectra"
DISTS="frs frs-jit random regular halton dart"

# The point sets: FRS one file per seed (its sets differ in size), the
# reference generators all sets in one file.
{
	s=1
	while [ $s -le "$M" ]; do
		echo "sh $SELF --cached $C/frs-n$N-S$s.pts frs-sample -q -n $N -S $s"
		echo "sh $SELF --cached $C/frs-jit-n$N-S$s.pts frs-sample -q -n $N -S $s --jitter random --sigma 8"
		s=$((s + 1))
	done
	for k in random regular halton dart; do
		echo "sh $SELF --cached $C/$k-n$N-m$M.pts ref-sample -q -k $k -n $N --sets $M -S 1"
	done
} | par_run

# The spectra, one dda run per distribution.
for d in $DISTS; do
	case $d in
	frs | frs-jit)
		files=""
		s=1
		while [ $s -le "$M" ]; do
			files="$files $C/$d-n$N-S$s.pts"
			s=$((s + 1))
		done
		sets="" ;;
	*)
		files=$C/$d-n$N-m$M.pts
		sets="--sets $N" ;;
	esac
	b=$C/$d-n$N-m$M-K$K
	echo "sh $SELF --cached $b.tsv dda -q --fourier --size $K $sets --png $b.png --radial $b.rad $files"
done | par_run
for d in $DISTS; do
	b=$C/$d-n$N-m$M-K$K
	cp "$b.rad" "$OUT/radial-$d.tsv"
	cp "$b.png" "$OUT/spectra/$d.png"
done

# Peaks of the radial mean: the first is the largest value beyond the DC
# annulus (freq >= 4), the second and third the largest within
# [1.5, 2.5) and [2.5, 3.5) times its frequency; the mean anisotropy is
# over the annuli with freq >= 4.
{
	printf 'dist\tpeak1_freq\tpeak1_power\tpeak2_freq\tpeak2_power\tpeak3_freq\tpeak3_power\tmean_aniso_db\n'
	for d in $DISTS; do
		awk -F '\t' -v d="$d" "$BEST_AWK"'
		NR > 1 && $1 >= 4 { n++; f[n] = $1; p[n] = $2; a += $3 }
		END {
			f1 = best(0, 1e9); p1 = bp
			f2 = best(1.5 * f1, 2.5 * f1); p2 = bp
			f3 = best(2.5 * f1, 3.5 * f1); p3 = bp
			printf "%s\t%d\t%.4f\t%d\t%.4f\t%d\t%.4f\t%.2f\n", d, f1, p1, f2, p2, f3, p3, a / n
		}' "$OUT/radial-$d.tsv"
	done
} >"$OUT/peaks.tsv"

# The figure: the spectra above their radial mean (red) and anisotropy
# (blue), as in the thesis.
{
	gp_png "$OUT/fig6.9.png"
	echo "set terminal png size 1800,640 font ',9'"
	echo "set output '$OUT/fig6.9.png'"
	echo "set multiplot layout 2,6 title 'Fig. 6.9: power spectra (n = $N, $M sets), radial mean (red) and anisotropy (blue, dB, right axis)'"
	for d in $DISTS; do
		echo "set title '$d'; unset key; set size ratio -1; unset xtics; unset ytics; unset y2tics; unset border"
		echo "plot '$OUT/spectra/$d.png' binary filetype=png with rgbimage"
	done
	echo "set border; set size noratio; set xtics; set ytics nomirror; set y2tics"
	echo "set xrange [0:$K]; set yrange [0:4]; set y2range [-20:20]; set xlabel 'frequency'"
	for d in $DISTS; do
		echo "set title '$d'"
		echo "plot '$OUT/radial-$d.tsv' u 1:2 w l lc rgb 'red' notitle, '' u 1:3 axes x1y2 w l lc rgb 'blue' notitle, 1 w l lc rgb 'gray' dt 2 notitle, -10 axes x1y2 w l lc rgb 'gray' dt 3 notitle"
	done
	echo "unset multiplot"
} | gnuplot
{
	gp_png "$OUT/fig6.9-radial.png"
	echo "set title 'Radial mean of the power spectrum (n = $N, $M sets); 1 = white noise'"
	echo "set xlabel 'frequency (cycles per unit square)'; set ylabel 'radial mean power'"
	echo "set xrange [0:$K]; set yrange [0:3]; set key top right"
	echo "plot '$OUT/radial-dart.tsv' u 1:2 w lp pt 7 ps 0.5 lc rgb 'blue' t 'dart throwing (reference)', '$OUT/radial-frs.tsv' u 1:2 w lp pt 7 ps 0.5 lc rgb 'red' t 'FRS', '$OUT/radial-frs-jit.tsv' u 1:2 w l lc rgb 'orange' t 'jittered FRS', 1 w l lc rgb 'gray' dt 2 t 'white noise'"
} | gnuplot

v() { awk -F '\t' -v d="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i } $1 == d { print $h[c] }' "$OUT/peaks.tsv"; }
row "first radial-mean peak, FRS (freq, power)" "$(v frs peak1_freq), $(v frs peak1_power)" "almost identical to dart throwing"
row "first radial-mean peak, jittered FRS (freq, power)" "$(v frs-jit peak1_freq), $(v frs-jit peak1_power)" "no significant difference from FRS"
row "first radial-mean peak, dart throwing (freq, power)" "$(v dart peak1_freq), $(v dart peak1_power)" "reference"
row "second / third peak power, FRS" "$(v frs peak2_power) / $(v frs peak3_power)" "significantly weaker than dart throwing; third barely above noise"
row "second / third peak power, dart throwing" "$(v dart peak2_power) / $(v dart peak3_power)" "reference"
BG=$(awk -v m="$M" 'BEGIN { printf "%.0f", 10 * log(1 / m) / log(10) }')
row "mean anisotropy, FRS / jittered FRS (freq >= 4)" "$(v frs mean_aniso_db) / $(v frs-jit mean_aniso_db) dB" "lower than dart throwing's; $BG dB is the background of an isotropic set of $M periodograms"
row "mean anisotropy, dart / random (freq >= 4)" "$(v dart mean_aniso_db) / $(v random mean_aniso_db) dB" "about -10 dB (10 sets)"
row "mean anisotropy, regular / Halton" "$(v regular mean_aniso_db) / $(v halton mean_aniso_db) dB" "highly anisotropic, regular patterns"

# The thesis' three observations, checked.
checks=$(awk -F '\t' '
	$1 == "frs" { f1 = $2; fp1 = $3; fp2 = $5; fp3 = $7; fa = $8 }
	$1 == "dart" { d1 = $2; dp1 = $3; dp2 = $5; dp3 = $7; da = $8 }
	END {
		a = (f1 >= 0.85 * d1 && f1 <= 1.15 * d1)
		b = (fp2 < dp2 && fp3 < dp3)
		c = (fa <= da + 0.5)
		printf "%d%d%d", a, b, c
	}' "$OUT/peaks.tsv")
row "thesis observations held (first peak at dart's frequency / weaker 2nd+3rd peaks / anisotropy not above dart's)" "$(echo "$checks" | sed 's/1/yes /g; s/0/no /g; s/ $//')" "yes yes yes"
if [ "$checks" = 111 ]; then
	exp_end reproduced "FRS and jittered FRS have blue-noise spectra: a dark centre, the first radial-mean peak at the frequency of dart throwing's, weaker second and third peaks than dart throwing (more random), and anisotropy at the background of an isotropic set; regular and Halton show the strong peaks and anisotropy of the thesis.$( [ "$MODE" = tiny ] && echo '  (Tiny mode: too few points and sets for the numbers to mean much.)')"
else
	exp_end differs "FRS and jittered FRS have blue-noise spectra, but not every observation of the thesis holds (table, from this run): FRS's first radial-mean peak $(v frs peak1_power) at $(v frs peak1_freq) against dart throwing's $(v dart peak1_power) at $(v dart peak1_freq) (the thesis: at the same frequency, within 15 %: $(echo "$checks" | cut -c1 | sed 's/1/holds/; s/0/fails/')); second and third peaks $(v frs peak2_power) / $(v frs peak3_power) against dart's $(v dart peak2_power) / $(v dart peak3_power) (weaker: $(echo "$checks" | cut -c2 | sed 's/1/holds/; s/0/fails/')); mean anisotropy $(v frs mean_aniso_db) dB against dart's $(v dart mean_aniso_db) dB (not above it: $(echo "$checks" | cut -c3 | sed 's/1/holds/; s/0/fails/')).  A matrix less random than the thesis authors' (frd-gen(1)) may have stronger second and third rings than Fig. 6.9 describes$( [ "$MODE" = tiny ] && echo '; tiny mode has too few sets and points to resolve the peaks')."
fi
