#!/bin/sh
# Thesis Sec. 6.3 (Differential Domain Analysis), Fig. 6.12: adaptive
# sampling of a highly anisotropic importance map (imap spec aniso, a
# thin ridge along a line through the centre): HSW warping Poisson-disk
# (dart) input, FRS (sigma 8) and relaxation dart throwing (the
# reference); point pictures (pts-render -i aniso, the first set) and
# the DDA (dda --dda -i aniso --png --radial, all sets), with its
# anisotropy averaged over the annuli from the reference's first peak
# to 6 spacings.
#   tiny : 2 sets of 256 points, DDA images 129 pixels a side
#   quick: 10 sets of 1024 points, DDA images 513 pixels a side
#   full : 10 sets of 1024 points, DDA images 1025 pixels a side
# Writes radial-DIST.tsv (dist, power, aniso_db, count: dda --radial;
# dist in mean spacings), aniso.tsv (per distribution: the first
# radial-mean peak, the mean and largest annulus anisotropy, and the
# elongation and angle of the DDA's empty disc), points/DIST.png,
# dda/DIST.png, fig6.12.png (points above the DDA, centre +-3 spacings)
# and fig6.12-radial.png (radial mean and anisotropy).
# ids: fig6.12
. "$(dirname "$0")/explib.sh"
exp_begin fig6.12 "a highly anisotropic importance map: HSW against FRS" \
    "Sec. 6.3, Fig. 6.12: HSW with Poisson-disk input, FRS and relaxation dart throwing on an artificial anisotropic map; HSW's set highly anisotropic, FRS close to the reference" \
    "about 15 s (measured)"

N=$(pick 256 1024 1024)
M=$(pick 2 10 10)
K=$(pick 64 256 512)
MAP=aniso
C=$CACHE/fig6.12
mkdir -p "$C" "$OUT/points" "$OUT/dda"
DISTS="ref frs hsw-dart"

{
	echo "$J $C/$MAP-ref-n$N-m$M.pts ref-sample -q -k relaxed-dart -i $MAP -n $N --sets $M -S 1"
	echo "$J $C/$MAP-ref-n$N-S1.pts ref-sample -q -k relaxed-dart -i $MAP -n $N -S 1"
	for s in $(seq 1 "$M"); do
		echo "$J $C/$MAP-frs-n$N-S$s.pts frs-sample -q -i $MAP -n $N -S $s"
		echo "$J $C/$MAP-hsw-dart-n$N-S$s.pts hsw-sample -q -i $MAP -n $N -S $s --input dart"
	done
} | par_run

for d in $DISTS; do
	dda_sets "$C/$MAP" $d $MAP
	echo "$J $C/$MAP-$d-n$N-S1.png pts-render -q -i $MAP $C/$MAP-$d-n$N-S1.pts"
done | par_run
for d in $DISTS; do
	dda_copy "$C/$MAP" $d $d
	cp "$C/$MAP-$d-n$N-S1.png" "$OUT/points/$d.png"
done

r1=$(awk -F '\t' 'NR > 1 && $2 > bp { bp = $2; bf = $1 } END { print bf }' "$OUT/radial-ref.tsv")
{
	printf 'dist\tpeak1_dist\tpeak1_power\tmean_aniso_db\tmax_aniso_db\telongation\tangle_deg\n'
	for d in $DISTS; do
		# the shape of the empty disc: second moments of the deficit
		# max(0, 0.5 - value) of the DDA within 2 spacings (the empty part); elongation
		# sqrt(l1 / l2) of their eigenvalues (1 for a round disc, at
		# most 99),
		# angle of the long axis from dx towards dy
		el=$(awk -F '\t' 'NR > 1 && $1 * $1 + $2 * $2 < 4 && $3 < 0.5 {
			w = 0.5 - $3; sxx += w * $1 * $1; syy += w * $2 * $2; sxy += w * $1 * $2 }
		END {
			t = (sxx + syy) / 2; q = sqrt(((sxx - syy) / 2) ^ 2 + sxy * sxy)
			e = (t <= 0) ? 1 : (t - q <= t / 9801) ? 99 : sqrt((t + q) / (t - q))
			printf "%.3f\t%.1f", e, 0.5 * atan2(2 * sxy, sxx - syy) * 45 / atan2(1, 1)
		}' "$C/$MAP-$d-n$N-m$M-K$K.tsv")
		awk -F '\t' -v d="$d" -v r1="$r1" -v el="$el" '
		NR > 1 && $2 > bp { bp = $2; bf = $1 }
		NR > 1 && $1 >= r1 && $1 <= 6 { n++; a += $3; if (n == 1 || $3 > mx) mx = $3 }
		END { printf "%s\t%.4f\t%.4f\t%.2f\t%.2f\t%s\n", d, bf, bp, a / n, mx, el }' "$OUT/radial-$d.tsv"
	done
} >"$OUT/aniso.tsv"

{
	gp_page "$OUT/fig6.12.png" 1200,820 10 2,3 "Fig. 6.12: anisotropic importance map (n = $N); DDA of $M sets, centre +-3 spacings"
	gp_pictures
	for d in $DISTS; do
		echo "set title '$d: points (first set)'; set autoscale xy"
		echo "plot '$OUT/points/$d.png' binary filetype=png with rgbimage"
	done
	gp_centre $K
	for d in $DISTS; do
		echo "set title '$d: DDA'"
		echo "plot '$OUT/dda/$d.png' binary filetype=png with rgbimage"
	done
	echo "unset multiplot"
} | gnuplot
{
	gp_png "$OUT/fig6.12-radial.png"
	echo "set multiplot layout 1,2 title 'DDA radial statistics, anisotropic map (n = $N, $M sets)'"
	echo "set xlabel 'differential (mean spacings)'; set xrange [0:6]; set key top right"
	echo "set title 'radial mean (1 = Poisson)'; set yrange [0:2]"
	echo "plot '$OUT/radial-ref.tsv' u 1:2 w l lw 2 lc rgb 'blue' t 'relaxation dart', '$OUT/radial-frs.tsv' u 1:2 w l lw 2 lc rgb 'red' t 'FRS', '$OUT/radial-hsw-dart.tsv' u 1:2 w l lw 2 lc rgb 'dark-green' t 'HSW, dart input', 1 w l lc rgb 'gray' dt 2 notitle"
	echo "set title 'anisotropy (dB)'; set yrange [-30:20]"
	echo "plot '$OUT/radial-ref.tsv' u 1:3 w l lw 2 lc rgb 'blue' t 'relaxation dart', '$OUT/radial-frs.tsv' u 1:3 w l lw 2 lc rgb 'red' t 'FRS', '$OUT/radial-hsw-dart.tsv' u 1:3 w l lw 2 lc rgb 'dark-green' t 'HSW, dart input'"
	echo "unset multiplot"
} | gnuplot

v() { awk -F '\t' -v d="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i } $1 == d { print $h[c] }' "$OUT/aniso.tsv"; }
row "elongation of the DDA's empty disc (1 = round): ref / FRS / HSW dart" "$(v ref elongation) / $(v frs elongation) / $(v hsw-dart elongation) (HSW's long axis at $(v hsw-dart angle_deg) deg)" "HSW's set highly anisotropic; FRS close to the reference"
row "mean DDA anisotropy, $r1..6 spacings (dB): ref / FRS / HSW dart" "$(v ref mean_aniso_db) / $(v frs mean_aniso_db) / $(v hsw-dart mean_aniso_db)" "not in the thesis (it shows the DDA images)"
row "first radial-mean peak (dist, power): ref / FRS / HSW" "$(v ref peak1_dist), $(v ref peak1_power) / $(v frs peak1_dist), $(v frs peak1_power) / $(v hsw-dart peak1_dist), $(v hsw-dart peak1_power)" "FRS's ring like the reference's; HSW's distorted"


# The sharpest peak beyond FRS's first ring: from where the first peak has
# fallen below 1 out to 4 spacings, the largest height above the mean of
# the annuli 0.2 spacings either side; "dist prominence" (-1: none).
prom() {
	awk -F '\t' 'NR > 1 { n++; d[n] = $1; p[n] = $2; if ($2 > bp) { bp = $2; bi = n } }
	END {
		k = int(0.2 / (d[2] - d[1]) + 0.5); if (k < 1) k = 1
		for (i = bi; i <= n && p[i] >= 1; i++) ;
		best = -1; bd = -1
		for (; i + k <= n && d[i] <= 4; i++)
			if (i > k && p[i] - (p[i - k] + p[i + k]) / 2 > best) {
				best = p[i] - (p[i - k] + p[i + k]) / 2; bd = d[i]
			}
		printf "%.2f %.3f", bd, best
	}' "$OUT/radial-$1.tsv"
}
# shellcheck disable=SC2046
set -- $(prom frs)
fsd=$1 fsp=$2
# shellcheck disable=SC2046
set -- $(prom ref)
rsd=$1 rsp=$2
row "sharpest peak beyond the first ring (dist, height above its surroundings): FRS / ref" "$fsd, $fsp / $rsd, $rsp" "FRS: no isolated peaks"
# Where the matrix's force was cut off, seen from the ridge (most points):
# R = min(cap S, max(reach spacing, R_eps)) cells (frd-gen(1)), the
# spacing there r_u W / sqrt(max / mean) cells of the window W; in
# spacings.  0 when the matrix's header does not give it.
cached "$C/$MAP-frs-n$N-setup.txt" sh -c "frs-sample -v -i $MAP -n $N -S 1 -o /dev/null 2>&1"
cached "$C/$MAP-info.txt" imap info $MAP
W=$(sed -n 's/.*window \([0-9]*\)x.*/\1/p' "$C/$MAP-frs-n$N-setup.txt" | head -n 1)
RING=$(cut_radius "$(awk -v n="$N" -v w="$W" \
    -v mx="$(awk '$1 == "max" { print $2 }' "$C/$MAP-info.txt")" \
    -v mn="$(awk '$1 == "mean" { print $2 }' "$C/$MAP-info.txt")" \
    'BEGIN { printf "%.17g", sqrt(2 / (sqrt(3) * n)) * w / sqrt(mx / mn) }')")
RCELLS=${RING% *}
RSP=${RING#* }

# The claims of Sec. 6.3 on Fig. 6.12, checked.
re=$(v ref elongation) fe=$(v frs elongation) he=$(v hsw-dart elongation)
rd=$(v ref peak1_dist) rp=$(v ref peak1_power)
fd=$(v frs peak1_dist) fp=$(v frs peak1_power)
hd=$(v hsw-dart peak1_dist) hp=$(v hsw-dart peak1_power)
check "\"Although the input sample distribution has optimal blue-noise properties, the sample distribution after warping is highly anisotropic\" (Sec. 6.3, Differential Domain Analysis): HSW's empty disc elongated beyond 1.5 : 1" \
    "$he : 1 (long axis at $(v hsw-dart angle_deg) deg)" "$he > 1.5"
check "\"FRS, in contrast, is able to achieve a result close to the reference\" (Sec. 6.3, Differential Domain Analysis): its empty disc's elongation within 0.15 of the reference's" \
    "$fe / $re" "$fe - $re < 0.15 && $re - $fe < 0.15"
check_order "\"FRS, in contrast, is able to achieve a result close to the reference\" (Sec. 6.3, Differential Domain Analysis): closer than HSW (elongation of the empty disc)" \
    "FRS $fe, HSW $he / reference $re" "($fe - $re) * ($fe - $re) < ($he - $re) * ($he - $re)"
check "\"a result close to the reference\" (Sec. 6.3, Differential Domain Analysis): FRS's first peak within 20 % of the reference's distance and height" \
    "$fd, $fp / $rd, $rp" \
    "$fd >= 0.8 * $rd && $fd <= 1.2 * $rd && $fp >= 0.8 * $rp && $fp <= 1.2 * $rp"
check "\"distorted anisotropically\" (HSW, Sec. 6.3, Differential Domain Analysis): its first peak 20 % off the reference's distance, or 0.2 lower" \
    "$hd, $hp / $rd, $rp" "$hd < 0.8 * $rd || $hd > 1.2 * $rd || $hp < $rp - 0.2"
check "\"no isolated peaks of high energy or any other anisotropic artifacts could be observed\" (Sec. 6.3, Summary): FRS's sharpest peak beyond the first ring at most 0.05 higher above its surroundings than the reference's" \
    "$fsp at $fsd / $rsp at $rsd spacings" "$fsp <= $rsp + 0.05"
observe "$fsp > $rsp + 0.05 && $RSP > 0 && $fsd > 0.9 * $RSP && $fsd < 1.1 * $RSP" \
    "FRS's sharpest peak beyond its first ring, at $fsd spacings, lies within 10 % of where the matrix's force was cut off, seen from the ridge: $RCELLS cells, $RSP spacings of the ridge's points (cutoff=$(frd_param cutoff), from the header of $(basename "$FRS_MATRIX"); frd-gen(1): a force cut off at R leaves a ring at R)."
fa=$(v frs mean_aniso_db) ra=$(v ref mean_aniso_db) ha=$(v hsw-dart mean_aniso_db)
observe "$he > 1.5 && $ha - $fa < 2 && $fa - $ha < 2" \
    "The mean anisotropy over the annuli from $r1 to 6 spacings does not separate HSW from FRS ($ha against $fa dB); the elongation of the empty disc does."
observe "$fa > $ra + 2" "FRS's mean anisotropy is $fa dB against the reference's $ra dB."
exp_end
