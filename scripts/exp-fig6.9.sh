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
		echo "$J $C/frs-n$N-S$s.pts frs-sample -q -n $N -S $s"
		echo "$J $C/frs-jit-n$N-S$s.pts frs-sample -q -n $N -S $s --jitter random --sigma 8"
		s=$((s + 1))
	done
	for k in random regular halton dart; do
		echo "$J $C/$k-n$N-m$M.pts ref-sample -q -k $k -n $N --sets $M -S 1"
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
	echo "$J $b.tsv dda -q --fourier --size $K $sets --png $b.png --radial $b.rad $files"
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
	gp_page "$OUT/fig6.9.png" 1800,640 9 2,6 "Fig. 6.9: power spectra (n = $N, $M sets), radial mean (red) and anisotropy (blue, dB, right axis)"
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

# The claims of Sec. 6.3 (Fourier analysis), checked on this run.
# The dark centre: the mean radial power from 4 up to half the first peak's
# frequency (white noise: 1).
centre() {
	awk -F '\t' -v f1="$(v "$1" peak1_freq)" 'NR > 1 && $1 >= 4 && $1 < f1 / 2 {
	    s += $2; k++ } END { printf "%.3f", (k ? s / k : -1) }' "$OUT/radial-$1.tsv"
}
fc=$(centre frs) jc=$(centre frs-jit) dc=$(centre dart)
f1=$(v frs peak1_freq) fp1=$(v frs peak1_power) fp2=$(v frs peak2_power) fp3=$(v frs peak3_power) fa=$(v frs mean_aniso_db)
j1=$(v frs-jit peak1_freq) jp1=$(v frs-jit peak1_power) ja=$(v frs-jit mean_aniso_db)
d1=$(v dart peak1_freq) dp1=$(v dart peak1_power) dp2=$(v dart peak2_power) dp3=$(v dart peak3_power) da=$(v dart mean_aniso_db)
rp1=$(v random peak1_power) ra=$(v random mean_aniso_db)
ga=$(v regular mean_aniso_db) ha=$(v halton mean_aniso_db)
check "\"the power spectra of both FRS variants have distinct blue-noise characteristics\" (Sec. 6.3, Fourier Analysis): a dark centre, the mean power below half the first peak's frequency under 0.5" \
    "$fc, $jc (dart $dc)" "$fc >= 0 && $fc < 0.5 && $jc >= 0 && $jc < 0.5"
check "\"While the first peak is almost identical in both plots\" (Sec. 6.3, Fourier Analysis): FRS's first radial-mean peak within 15 % of dart throwing's in frequency and power" \
    "$fp1 at $f1 / $dp1 at $d1" \
    "$f1 >= 0.85 * $d1 && $f1 <= 1.15 * $d1 && $fp1 >= 0.85 * $dp1 && $fp1 <= 1.15 * $dp1"
check_order "\"the second and third peak ... are significantly weaker in the case of FRS\" (Sec. 6.3, Fourier Analysis): the second below dart throwing's" "$fp2 / $dp2" "$fp2 < $dp2"
# (no third peak within 3.5 times the first's frequency: -1 in peaks.tsv)
if holds "$fp3 >= 0 && $dp3 >= 0"; then
	check_order "\"the second and third peak ... are significantly weaker in the case of FRS\" (Sec. 6.3, Fourier Analysis): the third below dart throwing's" "$fp3 / $dp3" "$fp3 < $dp3"
else
	check "\"the second and third peak ... are significantly weaker in the case of FRS\" (Sec. 6.3, Fourier Analysis): the third below dart throwing's" "$fp3 / $dp3 (-1: none)" "0" \
	    "no third peak within 3.5 times the first's frequency (the spectra end at $K)"
fi
check "\"significantly weaker\" (Sec. 6.3, Fourier Analysis): the excess of FRS's second and third peaks over white noise at most 3/4 of dart's" \
    "$fp2, $fp3 / $dp2, $dp3" "$fp2 - 1 <= 0.75 * ($dp2 - 1) && $fp3 >= 0 && $fp3 - 1 <= 0.75 * ($dp3 - 1)"
check "\"In its power spectrum, the third annulus is barely distinguishable from uncorrelated noise\" (Sec. 6.3, Fourier Analysis): at most 0.02 above uniform random's strongest annulus" \
    "$fp3 / random $rp1" "$fp3 >= 0 && $fp3 <= $rp1 + 0.02"
check_order "FRS: \"the anisotropy is lower\" (than the reference's, dart throwing; Sec. 6.3, Fourier Analysis)" "$fa / $da dB" "$fa < $da"
check_order "jittered FRS: \"the anisotropy is lower\" (than the reference's, dart throwing; Sec. 6.3, Fourier Analysis)" "$ja / $da dB" "$ja < $da"
check "FRS and jittered FRS artifact-free: mean anisotropy at the $BG dB background of $M periodograms (within 1 dB)" \
    "$fa, $ja dB" "$fa - $BG < 1 && $BG - $fa < 1 && $ja - $BG < 1 && $BG - $ja < 1"
check "\"there is no significant difference between the results of FRS and jittered FRS\" (Sec. 6.3, Fourier Analysis): first peak's frequency and power within 10 %, anisotropy within 1 dB" \
    "$fp1 at $f1, $fa dB / $jp1 at $j1, $ja dB" \
    "$j1 >= 0.9 * $f1 && $j1 <= 1.1 * $f1 && $jp1 >= 0.9 * $fp1 && $jp1 <= 1.1 * $fp1 && $ja - $fa < 1 && $fa - $ja < 1"
check "dart throwing and uniform random at the $BG dB background (within 1 dB)" \
    "$da / $ra dB" "$da - $BG < 1 && $BG - $da < 1 && $ra - $BG < 1 && $BG - $ra < 1"
check "\"Halton sampling is highly anisotropic\" (Sec. 6.3, Fourier Analysis): mean anisotropy 6 dB above the background" "$ha dB" "$ha > $BG + 6"
check "regular highly anisotropic (mean anisotropy 6 dB above the background)" "$ga dB" "$ga > $BG + 6"
observe "$fa >= $da && $fa - $da < 0.5" "FRS's mean anisotropy is above dart throwing's by less than 0.5 dB ($fa against $da dB)."
observe "$fp2 < $dp2 && $fp2 - 1 > 0.75 * ($dp2 - 1)" "FRS's second peak is weaker than dart throwing's, but only slightly ($fp2 against $dp2)."
exp_note "FRS thresholds $(basename "$FRS_MATRIX") (made by frd-gen(1)), not the thesis authors' matrix."
exp_end
