#!/bin/sh
# Thesis Sec. 4.7 "Sparsity sigma", Fig. 4.5 (FRS) and Fig. 4.6 (jittered
# FRS, --jitter random): differential domain analysis (DDA, Wei and Wang)
# of uniform FRS sets for sigma in {1, 2, 4, 8, 16} with a matrix of
# S_M = 512 (frd-gen -s 512 -p 0.5 -S 1, cached; shared with fig4.4).
# Every setting: SETS sets of n = 1024 uniform samples (-i const), seeds
# 1..SETS.  The const map has 32*sigma pixels a side, so that n_s = 1 and
# the window is 32 sigma elements a side (w_min of Eq. 4.12): sigma = 1
# then thresholds every element of a 32x32 window, the regular grid the
# thesis names; the window offset is free.  References: the 32x32
# regular grid and jittered grid (ref-sample -k regular|jittered) that
# the thesis says sigma = 1 equals, and dart throwing.  dda --dda (eps 12
# spacings, 257x257 image) averages each setting's sets.
#   tiny:  S_M 128, 2 sets
#   quick: S_M 512, 10 sets (the thesis parameters; the 512^2 matrix takes
#          ~3 s once)
#   full:  S_M 512, 10 sets
# Output ($OUT): radial.tsv (sampler sigma dist power aniso_db),
# stats.tsv (sampler sigma sets points peak_dist peak_power aniso_db
# rms_vs_grid rms_vs_dart), fig4.5-4.6-dda.png (the DDA images, +-6
# spacings: row 1 Fig. 4.5, row 2 Fig. 4.6), fig4.5-4.6-radial.png
# (radial means), img/*.png (each DDA image, +-12 spacings).
# ids: fig4.5-4.6 fig4.5 fig4.6
. "$(dirname "$0")/explib.sh"
exp_begin fig4.5-4.6 "DDA of FRS and jittered FRS for sparsity sigma" \
    "Sec. 4.7, Figs. 4.5 and 4.6: sigma = 1, 2, 4, 8, 16, S_M = 512, 10 sets of 1024 uniform samples" \
    "about 15 s (measured)"

SM=$(pick 128 512 512)
SETS=$(pick 2 10 10)
SIGMAS="1 2 4 8 16"
N=1024
M=$CACHE/frd/s$SM-p0.5-S1.frd
C=$CACHE/fig4
mkdir -p "$C" "$CACHE/frd" "$OUT/img"

# 1. the matrix
echo "$J $M frd-gen -q -s $SM -p 0.5 -S 1" | par_run

# 2. the sets (names shared with fig4.4) and the references
pts() { fig4_pts $SM $1 $2 $3; }	# pts SIG JIT SEED (set_points)
{
	for sig in $SIGMAS; do fig4_jobs $SM $sig "$M"; done
	echo "$J $C/regular-n$N.pts ref-sample -q -k regular -n $N"
	echo "$J $C/jittered-n$N-sets$SETS.pts ref-sample -q -k jittered -n $N --sets $SETS -S 1"
	echo "$J $C/dart-n$N-sets$SETS.pts ref-sample -q -k dart -n $N --sets $SETS -S 1"
} | par_run

# 3. one DDA per setting: radial statistics (cached) and the image
dname() { echo "dda-m$SM-sig$1-$2-sets$SETS"; }
{
	for sig in $SIGMAS; do
		for jit in none random; do
			dda_line "$(dname $sig $jit)" "" $(for seed in $(seq 1 $SETS); do pts $sig $jit $seed; done)
		done
	done
	dda_line "dda-regular-n$N" "" "$C/regular-n$N.pts"
	dda_line "dda-jittered-sets$SETS" "--sets $N" "$C/jittered-n$N-sets$SETS.pts"
	dda_line "dda-dart-sets$SETS" "--sets $N" "$C/dart-n$N-sets$SETS.pts"
} | par_run

# 4. tables
{
	printf 'sampler\tsigma\tdist\tpower\taniso_db\n'
	rad regular 0 "$C/dda-regular-n$N.tsv"
	rad jittered-grid 0 "$C/dda-jittered-sets$SETS.tsv"
	rad dart 0 "$C/dda-dart-sets$SETS.tsv"
	for jit in none random; do
		for sig in $SIGMAS; do
			rad "$(jit_name $jit)" $sig "$C/$(dname $sig $jit).tsv"
		done
	done
} >"$OUT/radial.tsv"
cp "$C/dda-regular-n$N.png" "$OUT/img/regular.png"
cp "$C/dda-jittered-sets$SETS.png" "$OUT/img/jittered-grid.png"
cp "$C/dda-dart-sets$SETS.png" "$OUT/img/dart.png"
for jit in none random; do
	for sig in $SIGMAS; do
		cp "$C/$(dname $sig $jit).png" "$OUT/img/$(jit_name $jit)-sigma$sig.png"
	done
done
# peak of the radial mean beyond 0.3 spacings, mean anisotropy of the
# annuli from 0.5 to 6 spacings, RMS differences of the radial mean from
# 0 to 6 spacings to the grid (FRS: regular, jittered FRS: jittered grid)
# and to dart throwing, over dart's annuli (an annulus that dda leaves
# out, all zero, counts as 0), and beyond 2 spacings (2.2 to 6, dart's
# annuli) the strongest value (spike, where: spike_dist) and the RMS
# deviation from the Poisson level 1 (sd_beyond2): a ring of FRS there
# that dart lacks is one of the matrix
radial_stats 'sampler\tsigma\tsets\tpoints\tpeak_dist\tpeak_power\taniso_db\trms_vs_grid\trms_vs_dart\tspike_dist\tspike\tsd_beyond2' "$SIGMAS" '
	END {
		for (i = 1; i <= no; i++) {
			key = order[i]; s2 = 0; t2 = 0
			g = (nm[key] == "frs" || nm[key] == "regular" ? "regular" : "jittered-grid") SUBSEP 0
			r = "dart" SUBSEP 0
			for (j = 1; j <= nd; j++) {
				d = ds[j]
				e = val[key, d] - val[g, d]; s2 += e * e
				e = val[key, d] - val[r, d]; t2 += e * e
			}
			beyond(key)
			printf "%s\t%s\t%d\t%s\t%.4g\t%.4g\t%.2f\t%s\t%.4f\t%.4g\t%.4f\t%.4f\n", nm[key], pm[key],
			    nm[key] == "regular" ? 1 : sets, nm[key] == "regular" || nm[key] == "dart" || nm[key] == "jittered-grid" ? n : np[key],
			    pd[key], pk[key], an[key] / na[key],
			    nm[key] == "dart" ? "NaN" : sprintf("%.4f", sqrt(s2 / nd)), sqrt(t2 / nd),
			    sq, sp, sdv
		}
	}'

# 5. figures
{
	dda_grid "$OUT/fig4.5-4.6-dda.png" $(($(echo $SIGMAS | wc -w) + 1)) "DDA, S_M=$SM, +-6 spacings (grey: -10..+10 dB; top: FRS (Fig. 4.5), bottom: jittered FRS (Fig. 4.6))"
	dda_img "$OUT/img/regular.png" "regular grid"
	for sig in $SIGMAS; do dda_img "$OUT/img/frs-sigma$sig.png" "FRS sigma=$sig"; done
	dda_img "$OUT/img/jittered-grid.png" "jittered grid"
	for sig in $SIGMAS; do dda_img "$OUT/img/frs-jitter-sigma$sig.png" "jittered FRS sigma=$sig"; done
	echo "unset multiplot"
} | gnuplot
{
	gp_png "$OUT/fig4.5-4.6-radial.png"
	echo "set multiplot layout 1,2"
	echo "set xlabel 'distance (mean spacings)'; set ylabel 'DDA radial mean'"
	echo "set xrange [0:6]; set yrange [0:3]; set key top right"
	for jit in none random; do
		n=$(jit_name $jit)
		ref=$([ $jit = none ] && echo regular || echo jittered-grid)
		echo "set title '$n, S_M=$SM'"
		printf "plot '%s' u (strcol(1) eq 'dart' ? \$3 : NaN):4 w l lw 2 lc rgb 'black' t 'dart'" "$OUT/radial.tsv"
		printf ", '' u (strcol(1) eq '%s' ? \$3 : NaN):4 w l dt 2 lw 2 lc rgb 'grey50' t '%s'" "$ref" "$ref"
		for sig in $SIGMAS; do
			printf ", '' u (strcol(1) eq '%s' && \$2 == %s ? \$3 : NaN):4 w l t 'sigma=%s'" "$n" "$sig" "$sig"
		done
		echo
	done
	echo "unset multiplot"
} | gnuplot

# 6. summary
# elem SIGMA DIST: a distance in mean spacings as window elements (the
# window is 32 sigma elements a side)
elem() { awk -v w=$((32 * $1)) -v d="$2" -v n=$N 'BEGIN { printf "%.1f", d * sqrt(2 / (sqrt(3) * n)) * w }'; }
row "sigma=1 FRS: RMS of radial mean - regular grid's" "$(st frs 1 rms_vs_grid) (regular grid's - dart's: $(st regular 0 rms_vs_dart))" "equals regular sampling"
row "sigma=1 jittered FRS: RMS - jittered grid's" "$(st frs-jitter 1 rms_vs_grid) (jittered grid's - dart's: $(st jittered-grid 0 rms_vs_dart))" "equals jittered grid sampling"
for sig in $SIGMAS; do
	row "sigma=$sig: anisotropy FRS / jittered (dB)" "$(st frs $sig aniso_db) / $(st frs-jitter $sig aniso_db) (dart $(st dart 0 aniso_db))" \
	    "$(case $sig in 1) echo 'regular (peaks)';; 8) echo 'fair compromise, annulus a bit frayed';; *) echo 'regularity decreases with sigma';; esac)"
	row "sigma=$sig: RMS of radial mean - dart's, FRS / jittered" "$(st frs $sig rms_vs_dart) / $(st frs-jitter $sig rms_vs_dart)" \
	    "jittered acceptable at smaller sigma than FRS"
	row "sigma=$sig: strongest value beyond 2 spacings, FRS / jittered (at spacings)" \
	    "$(st frs $sig spike) ($(st frs $sig spike_dist)) / $(st frs-jitter $sig spike) ($(st frs-jitter $sig spike_dist))" \
	    "$([ $sig = 8 ] && echo "no artifacts at the thesis' sigma; dart: $(st dart 0 spike) ($(st dart 0 spike_dist))" || echo '-')"
done

# The thesis' claims, checked: sigma = 1 equals the regular resp.
# jittered grid (its RMS to the grid below a tenth of the grid's to dart);
# the anisotropy of FRS falls with every step of sigma; jittered FRS is
# closer to dart than FRS at sigma 2 and 4; at sigma 8 both are close to
# dart (RMS below 0.1, a tenth of the Poisson level) and show no ring
# beyond 2 spacings that dart lacks (at most dart's strongest value there
# plus 2 of dart's deviations from 1 there).
exp_note "S_M = $SM, $SETS sets of n = $N per sigma; the window is 32 sigma elements a side; close to dart means an RMS of the radial mean below 0.1 (a tenth of the Poisson level) from 0 to 6 spacings."
g=$(st frs 1 rms_vs_grid)
gr=$(st regular 0 rms_vs_dart)
check "sigma = 1: \"Unsurprisingly, the power spectra for sigma=1 equal those of regular sampling\" (Sec. 4.7): FRS's RMS to the grid below a tenth of the grid's to dart, $gr" "$g" "$g < 0.1 * $gr"
g=$(st frs-jitter 1 rms_vs_grid)
gr=$(st jittered-grid 0 rms_vs_dart)
check "sigma = 1: \"... resp. jittered grid sampling\" (Sec. 4.7): jittered FRS's RMS to the jittered grid below a tenth of its to dart, $gr" "$g" "$g < 0.1 * $gr"
prev=
for sig in $SIGMAS; do
	if [ -n "$prev" ]; then
		a=$(st frs $prev aniso_db)
		b=$(st frs $sig aniso_db)
		check_order "\"it can be seen how the regularity of the samples decreases as sigma increases\" (Sec. 4.7): FRS less anisotropic at sigma = $sig than at $prev" "$b / $a dB" "$b < $a"
		# a window of the matrix's size or more: the same elements
		[ $((32 * sig)) -ge "$SM" ] && observe "$b >= $a" \
		    "At sigma = $sig the window ($((32 * sig)) elements a side) covers the whole $SM^2 matrix (n_max = S_M^2 / sigma^2 = $((SM * SM / (sig * sig))), n = $N; Table 4.1): every set thresholds the same matrix elements, shifted$([ $((32 * sig)) -gt "$SM" ] && echo ' and tiled'), so the average over the sets keeps the anisotropy of one ($b dB against $a at sigma $prev)."
	fi
	prev=$sig
done
for sig in 2 4; do
	f=$(st frs $sig rms_vs_dart)
	j=$(st frs-jitter $sig rms_vs_dart)
	check_order "sigma = $sig: \"the power spectrum of jittered FRS looks acceptable for smaller sigma as compared to FRS\" (Sec. 4.7): jittered FRS closer to dart than FRS (RMS)" "$j / $f" "$j < $f"
done
f=$(st frs 8 rms_vs_dart)
j=$(st frs-jitter 8 rms_vs_dart)
check "sigma = 8: \"sigma=8 seems like a fair compromise between quality and computational effort\" (Sec. 4.7): FRS and jittered FRS within an RMS of 0.1 of dart" "$f / $j" "$f < 0.1 && $j < 0.1"
dsp=$(st dart 0 spike)
lim=$(dart_limit)
f=$(st frs 8 spike)
j=$(st frs-jitter 8 spike)
check "sigma = 8: no ring beyond 2 spacings that dart lacks (FRS and jittered at most $lim: dart's $dsp + 2 sd)" \
    "$f / $j" "$f <= $lim && $j <= $lim"
for sig in 4 8 16; do
	f=$(st frs $sig spike)
	d=$(st frs $sig spike_dist)
	observe "$f > $lim" \
	    "At sigma = $sig FRS has a ring at $d spacings ($(elem $sig $d) window elements) of height $f, where dart stays below $dsp."
done
exp_end
