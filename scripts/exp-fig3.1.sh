#!/bin/sh
# Thesis Sec. 3.2 "Randomized Minimum Selection", Fig. 3.1: power spectra
# of Forced Random Dithering results for matrices made with candidate
# fractions p in {0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 1} (frd-gen -p).  As
# in the thesis, an image of the matrix's size and a constant intensity
# of 97.5 % is dithered with each matrix.  The thesis does not say which
# cells become the 2.5 % dots, so both are analysed: "last", the cells of
# the largest values, the black dots of ordered dithering that leaves a
# pixel white when its intensity exceeds the threshold M/N (the standard
# rule; the primary reading), and "first", the cells of the smallest
# values, those FRS takes at low density (frd-gen's lowpass_/peak_first
# and _last figures take the same dots).  The dots become points at the
# cell centres ((i+0.5)/S, (j+0.5)/S), by od and awk from the .frd values
# (frd(5)).  dda --fourier (exact sums, K = S/2, up to the
# Nyquist frequency of the matrix grid) averages the periodograms of the
# MATS matrices (seeds 1..MATS) of each p.
#   tiny:  S = 64, 1 matrix per p (102 dots)
#   quick: S = 256, 2 matrices per p (1638 dots; ~25 s of CPU, p = 0.01
#          being the slowest at ~6 s a matrix)
#   full:  S = 512, 10 matrices per p (6554 dots), the thesis' parameters
#          (~30 s a matrix for p = 0.01; 656 s on 2 cores in all)
# Output ($OUT): radial.tsv (dots_of p freq f_over_fp power aniso_db),
# dots_of last or first, f_p = sqrt(dots) the principal frequency;
# stats.tsv (dots_of p size matrices dots lowpass peak peak_f_over_fp
# aniso_db), fig3.1-spectra.png (the averaged spectra, grey -10..+10 dB;
# row 1 last, row 2 first), fig3.1-radial.png (radial means),
# img/{last,first}-p*.png (each spectrum).
# ids: fig3.1
. "$(dirname "$0")/explib.sh"
exp_begin fig3.1 "FRD spectra for candidate fractions p" \
    "Sec. 3.2, Fig. 3.1: p = 0.01..1, 10 matrices of 512x512 per p, a 512x512 image of constant intensity 97.5 % dithered" \
    "about 7 minutes on 2 cores (measured; 70 matrices of 512^2)"

PS="0.01 0.05 0.1 0.25 0.5 0.75 1"
S=$(pick 64 256 512)
MATS=$(pick 1 2 10)
K=$((S / 2))
DOTS=$(awk -v n=$((S * S)) 'BEGIN { printf "%d", 0.025 * n + 0.5 }')
C=$CACHE/fig3.1
mkdir -p "$C" "$CACHE/frd" "$OUT/img"
mat() { echo "$CACHE/frd/s$S-p$1-S$2.frd"; }

# 1. the matrices, slowest (small p) first
for p in $PS; do
	for seed in $(seq 1 $MATS); do
		echo "$J $(mat $p $seed) frd-gen -q -j 1 -s $S -p $p -S $seed"
	done
done | par_run

# 2. the dots of the 97.5 % grey: the cells whose values are among the
# DOTS largest (last) or smallest (first), as text points (the values are
# the last 4 S^2 bytes, x fastest, row 0 on top)
KINDS="last first"
dots() { # last|first MATRIX
	tail -c $((4 * S * S)) "$2" | od -A n -t u4 -v |
	    awk -v S=$S -v K=$DOTS -v lo=$([ "$1" = first ] && echo 0 || echo $((S * S - DOTS))) '
	BEGIN { print "#pts dims=2 extra=0 count=" K }
	{ for (f = 1; f <= NF; f++) { if ($f >= lo && $f < lo + K) printf "%.17g %.17g\n", (i % S + 0.5) / S, (int(i / S) + 0.5) / S; i++ } }'
}
dfile() { echo "$C/dots-$1-s$S-p$2-S$3-n$DOTS.pts"; }
for k in $KINDS; do
	for p in $PS; do
		for seed in $(seq 1 $MATS); do
			cached "$(dfile $k $p $seed)" dots $k "$(mat $p $seed)"
		done
	done
done

# 3. the averaged spectrum of each p: radial statistics (cached), image
sname() { echo "spec-$1-s$S-p$2-m$MATS-K$K"; }
for k in $KINDS; do
	for p in $PS; do
		name=$(sname $k $p)
		[ -s "$C/$name.png" ] || rm -f "$C/$name.tsv"
		printf '%s %s sh -c '\''dda --fourier -q -j 1 --size %s --radial "$0.r" --png %s -o /dev/null "$@" && cat "$0.r" && rm -f "$0.r"'\'' %s %s\n' \
		    "$J" "$C/$name.tsv" $K "$C/$name.png" "$C/$name" \
		    "$(for seed in $(seq 1 $MATS); do printf '%s ' "$(dfile $k $p $seed)"; done)"
	done
done | par_run

# 4. tables
{
	printf 'dots_of\tp\tfreq\tf_over_fp\tpower\taniso_db\n'
	for k in $KINDS; do
		for p in $PS; do
			awk -F '\t' -v k=$k -v p=$p -v fp="$(awk -v n=$DOTS 'BEGIN { print sqrt(n) }')" \
			    'NR > 1 { printf "%s\t%s\t%s\t%.4f\t%s\t%s\n", k, p, $1, ($1 + 1) / fp, $2, $3 }' "$C/$(sname $k $p).tsv"
			cp "$C/$(sname $k $p).png" "$OUT/img/$k-p$p.png"
		done
	done
} >"$OUT/radial.tsv"
# lowpass: mean power below 0.5 f_p (DC annulus left out) over the mean
# power between 1.5 and 2.5 f_p (the plateau), weighted by the pixels of
# the annuli, as frd-gen's lowpass figure; peak: the highest radial mean
# between 0.5 and 3 f_p over the plateau, and where it lies; aniso_db:
# mean anisotropy of the annuli from 1.5 to 2.5 f_p (background for m
# matrices: 10 log10(1/m) dB)
{
	printf 'dots_of\tp\tsize\tmatrices\tdots\tlowpass\tpeak\tpeak_f_over_fp\taniso_db\n'
	for k in $KINDS; do for p in $PS; do
		awk -F '\t' -v k=$k -v p=$p -v S=$S -v m=$MATS -v n=$DOTS '
		BEGIN { fp = sqrt(n) }
		NR > 1 {
			lo = $1 / fp; hi = ($1 + 2) / fp; c = ($1 + 1) / fp
			if ($1 > 0 && hi <= 0.5) { lw += $4 * $2; lc += $4 }
			if (c >= 1.5 && c <= 2.5) { pw += $4 * $2; pc += $4; an += $3; na++ }
			if (c >= 0.5 && c <= 3) { r[++nr] = $2; rc[nr] = c }
		}
		END {
			pl = pw / pc; pk = 0
			for (i = 1; i <= nr; i++) if (r[i] > pk) { pk = r[i]; pf = rc[i] }
			printf "%s\t%s\t%d\t%d\t%d\t%.4f\t%.3f\t%.3f\t%.2f\n", k, p, S, m, n,
			    lw / lc / pl, pk / pl, pf, an / na
		}' "$C/$(sname $k $p).tsv"
	done; done
} >"$OUT/stats.tsv"

# 5. figures
NP=$(echo $PS | wc -w)
FP=$(awk -v n=$DOTS 'BEGIN { printf "%.1f", sqrt(n) }')
{
	gp_png "$OUT/fig3.1-spectra.png"
	echo "set terminal png size $((150 * NP)),380 font ',9'"
	echo "set multiplot layout 2,$NP title 'FRD power spectra of a 97.5 % grey, $MATS matrices of ${S}x$S per p (grey: -10..+10 dB, +-$K cycles); top: dots = largest 2.5 % (last), bottom: smallest (first)'"
	echo "unset key; unset tics; unset border; set size ratio -1"
	for k in $KINDS; do
		for p in $PS; do
			echo "set title '$k, p = $p'; plot '$OUT/img/$k-p$p.png' binary filetype=png with rgbimage notitle"
		done
	done
	echo "unset multiplot"
} | gnuplot
{
	gp_png "$OUT/fig3.1-radial.png"
	echo "set multiplot layout 1,2"
	echo "set xlabel 'frequency / f_p  (f_p = sqrt(dots) = $FP)'"
	echo "set ylabel 'radial mean power'"
	echo "set xrange [0:*]; set yrange [0:3]; set key top right title 'p'"
	for k in $KINDS; do
		echo "set title 'dots: $k 2.5 % of the values, $MATS matrices of ${S}x$S'"
		printf "plot "
		sep=
		for p in $PS; do
			printf "%s'%s' u (strcol(1) eq '%s' && \$2 == %s ? \$4 : NaN):5 w l lw 2 t '%s'" "$sep" "$OUT/radial.tsv" "$k" "$p" "$p"
			sep=", "
		done
		echo ", 1 w l dt 2 lc rgb 'grey50' t 'white noise'"
	done
	echo "unset multiplot"
} | gnuplot

# 6. summary
for p in $PS; do
	row "p = $p: lowpass / peak (at f/f_p) / aniso dB, last \| first" \
	    "$(st last $p lowpass) / $(st last $p peak) ($(st last $p peak_f_over_fp)) / $(st last $p aniso_db) \| $(st first $p lowpass) / $(st first $p peak) ($(st first $p peak_f_over_fp)) / $(st first $p aniso_db)" \
	    "$(case $p in 0.01 | 0.05) echo 'outer annulus almost lost in noise';; 0.1 | 0.25) echo 'more random than 0.5';; 0.5) echo 'distinct blue noise (Purgathofer et al.)';; *) echo 'blue noise, no regular patterns or anisotropy';; esac)"
done
bg=$(awk -v m=$MATS 'BEGIN { printf "%.2f", -10 * log(m) / log(10) + 0 }')
row "anisotropy background for $MATS matrices" "$bg dB" "p = 1: no anisotropic artifacts"

# The thesis' claims on the primary reading (last), checked: blue noise
# is a lowpass of at most 0.6 and a peak of at least 1.2 (white noise: 1
# and 1); noise a lowpass of at least 0.8; a regular pattern would put
# far more than 2.5 into the peak; anisotropy within 3 dB of the
# background of MATS matrices.
exp_note "The thesis does not say which cells become the 2.5 % dots: the checks take the largest values (last, the black dots of ordered dithering), the smallest (first) are reported beside them.  Per p: $MATS matrices of ${S}x$S."
exp_note "Blue noise here means a lowpass of at most 0.6 and a peak of at least 1.2 over the plateau (white noise: 1 and 1)."
l5=$(st last 0.5 lowpass)
k5=$(st last 0.5 peak)
check 'p = 0.5: "As shown already by Purgathofer et al. for p=0.5, the power spectra of the results show very distinct blue-noise properties" (Sec. 3.2): blue noise, lowpass at most 0.6 and peak at least 1.2' "$l5 / $k5" "$l5 <= 0.6 && $k5 >= 1.2"
for p in 0.01 0.05; do
	l=$(st last $p lowpass)
	check "p = $p: \"For p <= 0.05, the outer annulus of high energy is almost completely lost in uncorrelated noise\" (Sec. 3.2): lowpass at least 0.8 (white noise 1)" "$l" "$l >= 0.8"
done
for p in 0.1 0.25; do
	l=$(st last $p lowpass)
	check "p = $p: \"the placement of values in M becomes more random as p decreases\" (Sec. 3.2): lowpass at least 1.1 times p = 0.5's" "$l" "$l >= 1.1 * $l5"
done
amax=$(awk -v b=$bg 'BEGIN { printf "%.2f", b + 3 }')
for p in 0.75 1; do
	l=$(st last $p lowpass)
	k=$(st last $p peak)
	a=$(st last $p aniso_db)
	check "p = $p: \"More surprising are the blue-noise properties of matrices for p>0.5 ... there are no noticeable regular patterns or other anisotropic artifacts\" (Sec. 3.2): lowpass at most 0.6, peak 1.2 to 2.5, anisotropy within 3 dB of the background of $MATS matrices" \
	    "$l / $k / $a dB" "$l <= 0.6 && $k >= 1.2 && $k <= 2.5 && $a <= $amax"
done
l1=$(st last 0.01 lowpass)
observe "$l1 < 0.8 && $l1 < 1.1 * $l5 && $l1 > $l5 / 1.1" \
    "At p = 0.01 the lowpass of the last 2.5 % ($l1) is within 10 % of p = 0.5's ($l5): the candidate fraction barely changes them."
f1=$(st first 0.01 lowpass)
g1=$(st first 0.01 peak)
observe "$f1 <= 0.6 && $g1 >= 1.2" \
    "The first 2.5 % stay blue noise even at p = 0.01 (lowpass $f1, peak $g1)."
f5=$(st first 0.5 lowpass)
observe "$l5 > 2 * $f5" \
    "The last 2.5 % are noisier than the first (lowpass $l5 against $f5 at p = 0.5)."
observe "$l1 < 0.8" \
    "Why the thesis saw the annulus vanish at p <= 0.05 we cannot tell: it describes its selection as the same random subset."
exp_end
