#!/bin/sh
# Thesis Sec. 4.7 "Dither Matrix Size S_M", Fig. 4.4: differential domain
# analysis (DDA, Wei and Wang) of uniform FRS sets and of jittered FRS
# sets (random offset in the window element, --jitter random) made with
# threshold matrices of several sizes S_M, with dart throwing
# (ref-sample -k dart) as the reference, the first row of the figure.
# Every setting: SETS sets of n = 1024 uniform samples (-i const), seeds
# 1..SETS, sigma 8; the map is const at 256x256 pixels, so that n_s = 1
# and the window is 256x256 elements at any offset.  The matrices are made
# by frd-gen -s S_M -p 0.5 -S 1 (cached), data/default.frd for 2048.
# dda --dda (eps 12 spacings, 257x257 image) averages each setting's sets;
# its radial mean and anisotropy are the numbers.
#   tiny:  S_M 64 2048, 3 sets
#   quick: S_M 64 256 512 2048, 10 sets (first run makes the 64..512
#          matrices, ~3 s of CPU)
#   full:  S_M 64 128 256 512 1024 2048, 10 sets (the 1024 matrix ~30 s)
# Output ($OUT): radial.tsv (sampler S_M dist power aniso_db),
# stats.tsv (sampler S_M sets points peak_dist peak_power aniso_db
# rms_vs_dart rms_frs_jitter), fig4.4-dda.png (the DDA images, +-6 spacings),
# fig4.4-radial.png (radial means), img/*.png (each DDA image, +-12).
# ids: fig4.4
. "$(dirname "$0")/explib.sh"
exp_begin fig4.4 "DDA of FRS and jittered FRS for matrix sizes S_M" \
    "Sec. 4.7, Fig. 4.4: S_M = 64..2048, 10 sets of 1024 uniform samples, sigma 8, dart throwing as reference" \
    "about 30 s on 2 cores (measured)"

SIZES=$(pick "64 2048" "64 256 512 2048" "64 128 256 512 1024 2048")
SETS=$(pick 3 10 10)
N=1024
SIG=8
MAP=$((32 * SIG))
matrix() {
	if [ "$1" = 2048 ]; then echo "$FRS_MATRIX"; else echo "$CACHE/frd/s$1-p0.5-S1.frd"; fi
}
C=$CACHE/fig4
mkdir -p "$C" "$CACHE/frd" "$OUT/img"

# 1. the matrices (largest first)
for s in $(echo $SIZES | tr ' ' '\n' | sort -rn); do
	[ "$s" = 2048 ] && continue
	echo "$J $(matrix $s) frd-gen -q -j 1 -s $s -p 0.5 -S 1"
done | par_run

# 2. the sets: FRS and jittered FRS per size and seed, dart throwing
pts() { fig4_pts $1 $SIG $2 $3; }	# pts S_M JIT SEED (set_points)
{
	for s in $SIZES; do fig4_jobs $s $SIG "$(matrix $s)"; done
	echo "$J $C/dart-n$N-sets$SETS.pts ref-sample -q -k dart -n $N --sets $SETS -S 1"
} | par_run

# 3. one DDA per setting: radial statistics (cached) and the image
{
	for s in $SIZES; do
		for jit in none random; do
			dda_line "dda-m$s-sig$SIG-$jit-sets$SETS" "" \
			    $(for seed in $(seq 1 $SETS); do pts $s $jit $seed; done)
		done
	done
	dda_line "dda-dart-sets$SETS" "--sets $N" "$C/dart-n$N-sets$SETS.pts"
} | par_run

# 4. tables
printf 'sampler\tS_M\tdist\tpower\taniso_db\n' >"$OUT/radial.tsv"
rad dart 0 "$C/dda-dart-sets$SETS.tsv" >>"$OUT/radial.tsv"
cp "$C/dda-dart-sets$SETS.png" "$OUT/img/dart.png"
for jit in none random; do
	for s in $SIZES; do
		rad "$(jit_name $jit)" $s "$C/dda-m$s-sig$SIG-$jit-sets$SETS.tsv" >>"$OUT/radial.tsv"
		cp "$C/dda-m$s-sig$SIG-$jit-sets$SETS.png" "$OUT/img/$(jit_name $jit)-m$s.png"
	done
done
# peak of the radial mean beyond 0.3 spacings, mean anisotropy of the
# annuli from 0.5 to 6 spacings, RMS difference to dart's radial mean
# from 0 to 6 spacings (over dart's annuli; an annulus that dda leaves
# out, all zero, counts as 0), RMS difference between FRS and jittered FRS
# of the same S_M (NaN for dart), and beyond 2 spacings (2.2 to 6, dart's
# annuli) the strongest value (spike, where: spike_dist) and the RMS
# deviation from the Poisson level 1 (sd_beyond2): a ring of FRS there
# that dart lacks is one of the matrix
radial_stats 'sampler\tS_M\tsets\tpoints\tpeak_dist\tpeak_power\taniso_db\trms_vs_dart\trms_frs_jitter\tspike_dist\tspike\tsd_beyond2' "$SIZES" '
	$1 == "dart" { ref[$3 + 0] = $4 + 0 }
	END {
		for (i = 1; i <= no; i++) {
			key = order[i]; s2 = 0; t2 = 0
			other = (nm[key] == "frs" ? "frs-jitter" : "frs") SUBSEP pm[key]
			for (j = 1; j <= nd; j++) {
				d = ds[j]; e = val[key, d] - ref[d]; s2 += e * e
				e = val[key, d] - val[other, d]; t2 += e * e
			}
			beyond(key)
			pn = nm[key] == "dart" ? n : np[key]
			printf "%s\t%s\t%d\t%s\t%.4g\t%.4g\t%.2f\t%.4f\t%s\t%.4g\t%.4f\t%.4f\n", nm[key], pm[key], sets, pn,
			    pd[key], pk[key], an[key] / na[key], sqrt(s2 / nd),
			    nm[key] == "dart" ? "NaN" : sprintf("%.4f", sqrt(t2 / nd)),
			    sq, sp, sdv
		}
	}'

# 5. figures
{
	dda_grid "$OUT/fig4.4-dda.png" $(($(echo $SIZES | wc -w) + 1)) 'DDA, +-6 spacings (grey: -10..+10 dB; top: FRS, bottom: jittered FRS)'
	dda_img "$OUT/img/dart.png" "dart throwing"
	for s in $SIZES; do dda_img "$OUT/img/frs-m$s.png" "FRS S_M=$s"; done
	echo "set multiplot next"
	for s in $SIZES; do dda_img "$OUT/img/frs-jitter-m$s.png" "jittered S_M=$s"; done
	echo "unset multiplot"
} | gnuplot
{
	gp_png "$OUT/fig4.4-radial.png"
	echo "set multiplot layout 1,2"
	echo "set xlabel 'distance (mean spacings)'; set ylabel 'DDA radial mean'"
	echo "set xrange [0:6]; set yrange [0:*]; set key top right"
	for jit in none random; do
		n=$(jit_name $jit)
		echo "set title '$n'"
		printf "plot '%s' u (strcol(1) eq 'dart' ? \$3 : NaN):4 w l lw 2 lc rgb 'black' t 'dart'" "$OUT/radial.tsv"
		for s in $SIZES; do
			printf ", '' u (strcol(1) eq '%s' && \$2 == %s ? \$3 : NaN):4 w l t 'S_M=%s'" "$n" "$s" "$s"
		done
		echo
	done
	echo "unset multiplot"
} | gnuplot

# 6. summary
# elem DIST: a distance in mean spacings as window elements (the window
# is MAP elements a side, n_s = 1)
elem() { awk -v d="$1" -v n=$N -v w=$MAP 'BEGIN { printf "%.1f", d * sqrt(2 / (sqrt(3) * n)) * w }'; }
row "dart: radial peak (spacings, height)" "$(st dart 0 peak_dist), $(st dart 0 peak_power)" "reference row: dark disc, bright annulus"
for s in $SIZES; do
	row "S_M=$s: anisotropy FRS / jittered (dB)" "$(st frs $s aniso_db) / $(st frs-jitter $s aniso_db) (dart $(st dart 0 aniso_db))" \
	    "$([ $s -le 256 ] && echo 'FRS: strong regularities' || echo 'FRS close to jittered and dart')"
	row "S_M=$s: RMS of radial mean - dart's, FRS / jittered" "$(st frs $s rms_vs_dart) / $(st frs-jitter $s rms_vs_dart)" \
	    "$([ $s -le 256 ] && echo 'jittered: too random, deviates' || echo 'close to the reference')"
	row "S_M=$s: RMS of radial mean FRS - jittered" "$(st frs $s rms_frs_jitter)" \
	    "$([ $s -le 256 ] && echo 'differ (FRS regular)' || echo 'FRS closely matches jittered FRS')"
	row "S_M=$s: strongest value beyond 2 spacings, FRS / jittered (at spacings)" \
	    "$(st frs $s spike) ($(st frs $s spike_dist)) / $(st frs-jitter $s spike) ($(st frs-jitter $s spike_dist))" \
	    "$([ $s -le 256 ] && echo 'regularities expected' || echo "no artifacts; dart: $(st dart 0 spike) ($(st dart 0 spike_dist))")"
done

# The thesis' claims on S_M, checked for every S_M run: up to 256 FRS is
# regular (its anisotropy 3 dB above that of every S_M >= 512), jitter
# lowers that, but jittered FRS deviates strongly from dart throwing (its
# RMS at least 1.2 times the largest of S_M >= 512); from 512 on FRS and
# jittered FRS are close to dart (RMS below 0.1, a tenth of the Poisson
# level), match each other (their RMS below half the RMS to dart) and
# show no ring beyond 2 spacings that dart lacks (at most dart's strongest
# value there plus 2 of dart's deviations from 1 there).
exp_note "Dart throwing is the reference; $SETS sets of n = $N per setting; close to dart means an RMS of the radial mean below 0.1 (a tenth of the Poisson level) from 0 to 6 spacings."
amax=$(for s in $SIZES; do [ $s -ge 512 ] && st frs $s aniso_db; done | sort -g | tail -n 1)
rmax=$(for s in $SIZES; do [ $s -ge 512 ] && st frs-jitter $s rms_vs_dart; done | sort -g | tail -n 1)
dsp=$(st dart 0 spike)
lim=$(dart_limit)
for s in $SIZES; do
	af=$(st frs $s aniso_db)
	aj=$(st frs-jitter $s aniso_db)
	rf=$(st frs $s rms_vs_dart)
	rj=$(st frs-jitter $s rms_vs_dart)
	if [ $s -le 256 ]; then
		check "S_M = $s: \"For small matrix sizes, the power spectra of FRS exhibit strong regularities\" (Sec. 4.7): anisotropy at least 3 dB above the largest of S_M >= 512, $amax dB" \
		    "$af dB" "$af >= $amax + 3"
		check_order "S_M = $s: \"Jittering adds variation to the differentials and leads to a more random distribution\" (Sec. 4.7): jittered FRS less anisotropic than FRS" \
		    "$aj / $af dB" "$aj < $af"
		check "S_M = $s: \"Still, the results of S_M <= 256 strongly deviate from the reference and seem too random\" (Sec. 4.7): jittered FRS's RMS to dart at least 1.2 times the largest of S_M >= 512, $rmax" \
		    "$rj" "$rj >= 1.2 * $rmax"
	else
		t=$(st frs $s rms_frs_jitter)
		check "S_M = $s: \"From a matrix size of 512 on, the results of FRS ... are also close to the reference\" (Sec. 4.7): FRS's and jittered FRS's RMS to dart below 0.1" \
		    "$rf / $rj" "$rf < 0.1 && $rj < 0.1"
		check "S_M = $s: \"From a matrix size of 512 on, the results of FRS closely match those of jittered FRS\" (Sec. 4.7): their RMS below half jittered FRS's to dart" \
		    "$t / $rj" "$t < 0.5 * $rj"
		sf=$(st frs $s spike)
		sj=$(st frs-jitter $s spike)
		check "S_M = $s: no ring beyond 2 spacings that dart lacks (FRS and jittered at most $lim: dart's $dsp + 2 sd)" \
		    "$sf / $sj" "$sf <= $lim && $sj <= $lim"
		d=$(st frs $s spike_dist)
		observe "$sf > $lim" \
		    "At S_M = $s FRS has a ring at $d spacings ($(elem $d) window elements) of height $sf, where dart stays below $dsp."
	fi
done
exp_end
