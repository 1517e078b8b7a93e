#!/bin/sh
# Thesis Sec. 6.3 (Spectral analysis, Differential Domain Analysis),
# Fig. 6.10 and 6.11: DDA power spectra (Wei and Wang, Gaussian kernel,
# eps = 12) of adaptive sample distributions for the importance maps
# Gaussian blob, linear gradient (ramp), the environment map ($ENVMAP)
# and constant: relaxation dart throwing (the reference, ref-sample -k
# relaxed-dart), FRS (the multi-level window, the default), FRS with the
# thesis's window (--tiles plain), jittered FRS (sigma 8, random jitter)
# and HSW with
# random, regular, Halton (Cranley-Patterson rotated per seed, warped
# from a file) and Poisson-disk (dart) input; Fig. 6.11, the radial means
# of FRS and relaxation dart throwing for uniform (constant) sampling.
# dda --dda -i MAP --png --radial averages the sets.
#   tiny : 1 set of 128 points, DDA images 65 pixels a side
#   quick: 6 sets of 1024 points, DDA images 513 pixels a side
#   full : 10 sets of 1024 points (the thesis'), images 1025 pixels
# Writes radial-MAP-DIST.tsv (dist, power, aniso_db, count: dda
# --radial; dist in mean spacings), peaks.tsv (per map and
# distribution: the radial-mean peaks and the mean anisotropy),
# dda/MAP-DIST.png (the DDA images), fig6.10.png (the DDA images, the
# centre +-3 spacings) and fig6.11.png (radial means, constant map).
# ids: fig6.10-6.11 fig6.10 fig6.11
. "$(dirname "$0")/explib.sh"
exp_begin fig6.10-6.11 "DDA power spectra of adaptive sampling" \
    "Sec. 6.3, Fig. 6.10 and 6.11: 10 sets of 1024 points, maps Gaussian blob, linear gradient, environment, constant; relaxation dart throwing, FRS, jittered FRS (sigma 8), HSW with random, regular, Halton and Poisson-disk input; DDA with a Gaussian kernel and eps = 12" \
    "about 80 s (measured)"

N=$(pick 128 1024 1024)
M=$(pick 1 6 10)
K=$(pick 32 256 512)
# The environment map: explib.sh's one setup (env_map, ENV_SIZE), shared
# with Table 6.1.
ES=$ENV_SIZE
C=$CACHE/fig6.10-6.11
mkdir -p "$C" "$OUT/dda"
MAPS="blob ramp env const"
DISTS="ref frs frs-plain frs-jit hsw-random hsw-regular hsw-halton hsw-dart"
envname=$(basename "$ENVMAP" | sed 's/\.[^.]*$//')
mapspec() {
	case $1 in
	env) env_map ;;
	*) echo "$1" ;;
	esac
}
# the cache name of a map: the environment map by its file name
mapkey() {
	case $1 in
	env) echo "env-$envname-$ES" ;;
	*) echo "$1" ;;
	esac
}

# Stage 1: the rotated Halton input of HSW.
for s in $(seq 1 "$M"); do
	echo "$J $C/halton-n$N-S$s.pts ref-sample -q -k halton -n $N -S $s"
done | par_run

# Stage 2: the point sets, one file per map, distribution and seed
# (relaxation dart throwing all sets in one file).
for m in $MAPS; do
	i=$(mapspec $m)
	k=$(mapkey $m)
	echo "$J $C/$k-ref-n$N-m$M.pts ref-sample -q -k relaxed-dart -i $i -n $N --sets $M -S 1"
	for s in $(seq 1 "$M"); do
		echo "$J $C/$k-frs-n$N-S$s.pts frs-sample -q -i $i -n $N -S $s"
		echo "$J $C/$k-frs-plain-n$N-S$s.pts frs-sample -q -i $i -n $N -S $s --tiles plain"
		echo "$J $C/$k-frs-jit-n$N-S$s.pts frs-sample -q -i $i -n $N -S $s --jitter random --sigma 8"
		for inp in random regular dart; do
			echo "$J $C/$k-hsw-$inp-n$N-S$s.pts hsw-sample -q -i $i -n $N -S $s --input $inp"
		done
		echo "$J $C/$k-hsw-halton-n$N-S$s.pts hsw-sample -q -i $i -n $N -S $s --input $C/halton-n$N-S$s.pts"
	done
done | par_run

# Stage 3: the DDA of every map and distribution.
for m in $MAPS; do
	i=$(mapspec $m)
	k=$(mapkey $m)
	for d in $DISTS; do
		dda_sets "$C/$k" $d "$i"
	done
done | par_run
for m in $MAPS; do
	k=$(mapkey $m)
	for d in $DISTS; do
		dda_copy "$C/$k" $d $m-$d
	done
done

# The FRS window per map (frs-sample -v): a window larger than the
# matrix repeats its tiles (thesis Table 4.1).
{
	printf 'map\tn_s\twindow\tmatrix\n'
	for m in $MAPS; do
		i=$(mapspec $m)
		k=$(mapkey $m)
		cached "$C/$k-frs-n$N-setup.txt" sh -c "frs-sample -v -i $i -n $N -S 1 -o /dev/null 2>&1"
		sed -n 's/.*matrix [^ ]* \([0-9x]*\),.*/\1/p' "$C/$k-frs-n$N-setup.txt" | head -n 1 >"$C/mat.$$"
		sed -n "s/.*n_s \([0-9]*\), window \([0-9x]*\) .*/$m\t\1\t\2\t$(cat "$C/mat.$$")/p" "$C/$k-frs-n$N-setup.txt" | head -n 1
		rm -f "$C/mat.$$"
	done
} >"$OUT/frs-window.tsv"

# Peaks of the radial mean (dist in mean spacings): the first is the
# largest value, the second the largest within [1.5, 2.5) times its
# distance; the mean anisotropy is over the annuli from the reference's
# first peak (Wei and Wang ignore the empty disc inside the minimum
# distance) to 6 spacings.
{
	printf 'map\tdist\tpeak1_dist\tpeak1_power\tpeak2_dist\tpeak2_power\tmean_aniso_db\n'
	for m in $MAPS; do
		r1=$(awk -F '\t' 'NR > 1 && $2 > bp { bp = $2; bf = $1 } END { print bf }' "$OUT/radial-$m-ref.tsv")
		for d in $DISTS; do
			awk -F '\t' -v m="$m" -v d="$d" -v r1="$r1" "$BEST_AWK"'
			NR > 1 { n++; f[n] = $1; p[n] = $2 }
			NR > 1 && $1 >= r1 && $1 <= 6 { na++; a += $3 }
			END {
				f1 = best(0, 1e9); p1 = bp
				f2 = best(1.5 * f1, 2.5 * f1); p2 = bp
				printf "%s\t%s\t%.4f\t%.4f\t%.4f\t%.4f\t%.2f\n", m, d, f1, p1, f2, p2, a / na
			}' "$OUT/radial-$m-$d.tsv"
		done
	done
} >"$OUT/peaks.tsv"

# Fig. 6.10: rows the distributions, columns the maps; the centre of
# each DDA image, +-3 of the eps = 12 spacings.
{
	gp_page "$OUT/fig6.10.png" 1000,1700 9 7,4 "Fig. 6.10: DDA (n = $N, $M sets; centre +-3 spacings; -10..+10 dB)"
	gp_pictures
	gp_centre $K
	for d in $DISTS; do
		for m in $MAPS; do
			echo "set title '$d, $m'"
			echo "plot '$OUT/dda/$m-$d.png' binary filetype=png with rgbimage"
		done
	done
	echo "unset multiplot"
} | gnuplot
{
	gp_png "$OUT/fig6.11.png"
	echo "set title 'Fig. 6.11: DDA radial mean, uniform sampling (n = $N, $M sets)'"
	echo "set xlabel 'differential (mean spacings)'; set ylabel 'radial mean (1 = Poisson)'"
	echo "set y2label 'anisotropy (dB)'; set y2tics; set ytics nomirror; set y2range [-30:10]"
	echo "set xrange [0:4]; set key top right"
	echo "plot '$OUT/radial-const-ref.tsv' u 1:2 w lp pt 7 ps 0.5 lc rgb 'blue' t 'relaxation dart throwing', '$OUT/radial-const-frs.tsv' u 1:2 w lp pt 7 ps 0.5 lc rgb 'red' t 'FRS', '$OUT/radial-const-ref.tsv' u 1:3 axes x1y2 w l lc rgb 'light-blue' t 'anisotropy, reference', '$OUT/radial-const-frs.tsv' u 1:3 axes x1y2 w l lc rgb 'pink' t 'anisotropy, FRS', 1 w l lc rgb 'gray' dt 2 notitle"
} | gnuplot

v() { awk -F '\t' -v m="$1" -v d="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i } $1 == m && $2 == d { print $h[c] }' "$OUT/peaks.tsv"; }
row "uniform: first peak, relaxation dart (dist, power)" "$(v const ref peak1_dist), $(v const ref peak1_power)" "sharp transition (Fig. 6.11, blue)"
row "uniform: first peak, FRS (dist, power)" "$(v const frs peak1_dist), $(v const frs peak1_power)" "same position, fringed outwardly (Fig. 6.11, red)"
row "uniform: second peak, FRS / reference (power)" "$(v const frs peak2_power) / $(v const ref peak2_power)" "clearly visible second peak at twice the distance for FRS"
# The strongest value beyond 2.2 spacings, uniform map: "dist elements
# power", the distance also in window elements.  A ring there in FRS and
# not in the reference would be the matrix's (frd-gen(1): a force cut off
# at R leaves a ring at R).
WC=$(awk -F '\t' '$1 == "const" { split($3, a, "x"); print a[1] }' "$OUT/frs-window.tsv")
RU=$(awk -v n="$N" 'BEGIN { printf "%.6f", sqrt(2 / (sqrt(3) * n)) }')
beyond2() {
	awk -F '\t' -v ru="$RU" -v w="$WC" '
	NR > 1 && $1 >= 2.2 && $2 > bp { bp = $2; bf = $1 }
	END { printf "%.2f %.1f %.3f", bf, bf * ru * w, bp }' "$1"
}
# shellcheck disable=SC2046
set -- $(beyond2 "$OUT/radial-const-frs.tsv")
sd=$1 se=$2 sp=$3
# shellcheck disable=SC2046
set -- $(beyond2 "$OUT/radial-const-ref.tsv")
rsd=$1 rsp=$3
row "uniform: strongest FRS peak beyond 2 spacings (dist, power)" "$sd spacings ($se window elements), $sp" "not in the thesis (FRS: no isolated peaks); the reference: $rsd spacings, $rsp"
# The radius at which the matrix's force was cut off for the values of
# the uniform FRS sets' level (frd-gen(1): R = min(cap S, max(reach
# spacing, R_eps)), the spacing r_u W cells), from its header; 0 when the
# header does not give it.
RCUT=$(cut_radius "$(awk -v a="$RU" -v b="$WC" 'BEGIN { print a * b }')")
RCUT=${RCUT% *}
CUTOFF=$(frd_param cutoff)
for m in blob ramp env; do
	row "$m: first peak FRS / reference (dist)" "$(v $m frs peak1_dist) / $(v $m ref peak1_dist)" "very similar spectra for all maps"
done
for m in $MAPS; do
	row "$m: mean anisotropy (dB) ref / FRS / FRS plain / jit. FRS / HSW dart / HSW Halton" "$(v $m ref mean_aniso_db) / $(v $m frs mean_aniso_db) / $(v $m frs-plain mean_aniso_db) / $(v $m frs-jit mean_aniso_db) / $(v $m hsw-dart mean_aniso_db) / $(v $m hsw-halton mean_aniso_db)" "FRS close to the reference; HSW distorts even Poisson-disk input"
done
for m in blob ramp env; do
	row "$m: first-peak power ref / FRS / HSW dart" "$(v $m ref peak1_power) / $(v $m frs peak1_power) / $(v $m hsw-dart peak1_power)" "FRS like the reference; HSW blurs the ring of its Poisson-disk input"
done
row "FRS window per map (blob / ramp / env / const; matrix $(awk -F '\t' 'NR == 2 { print $4 }' "$OUT/frs-window.tsv"))" "$(awk -F '\t' 'NR > 1 { printf "%s%s", s, $3; s = " / " }' "$OUT/frs-window.tsv")" "a window beyond the matrix repeats its tiles (Table 4.1)"

# The claims of Sec. 6.3 (differential domain analysis), checked.
# Every map: FRS's ring where the reference has it; its anisotropy close
# to the reference's (no anisotropic artifacts).
for m in $MAPS; do
	fd=$(v $m frs peak1_dist) jd=$(v $m frs-jit peak1_dist) rd=$(v $m ref peak1_dist)
	check "$m: \"The power spectra of relaxation dart throwing and FRS are very similar for all importance maps\" (Sec. 6.3, Differential Domain Analysis): the first peak of FRS and jittered FRS within 20 % of the reference's distance" \
	    "$fd, $jd / $rd" \
	    "$fd >= 0.8 * $rd && $fd <= 1.2 * $rd && $jd >= 0.8 * $rd && $jd <= 1.2 * $rd"
done
# num X...: every X is a number (the mean anisotropy is nan where no
# annulus lies between the reference's first peak and 6 spacings).
num() {
	for x in "$@"; do
		case $x in '' | *[!0-9.eE+-]*) return 1 ;; esac
	done
}
NOANN="not measured: no annulus from the reference's first peak to 6 spacings in a DDA image of $K pixels"
for m in $MAPS; do
	fa=$(v $m frs mean_aniso_db) ra=$(v $m ref mean_aniso_db)
	num "$fa" "$ra" || { fa=0 ra=99; }
	check "$m: \"its good spectral properties are preserved locally when adapting to a non-uniform importance function\" (Sec. 6.3, Differential Domain Analysis): FRS's anisotropy within 3 dB of the reference's" \
	    "$(v $m frs mean_aniso_db) / $(v $m ref mean_aniso_db) dB" "$fa - $ra < 3 && $ra - $fa < 3" \
	    "$(num "$(v $m frs mean_aniso_db)" "$(v $m ref mean_aniso_db)" || echo "$NOANN")"
done
# The adaptive maps: HSW blurs even Poisson-disk input, FRS keeps the
# reference's ring (the height of the first peak).
for m in blob ramp env; do
	fp=$(v $m frs peak1_power) hp=$(v $m hsw-dart peak1_power) rp=$(v $m ref peak1_power)
	check_order "$m: \"Even with blue-noise input samples, adaptive blue-noise sampling with HSW is impossible\" (Sec. 6.3, Differential Domain Analysis): FRS's ring closer to the reference's than HSW's with Poisson-disk input (first-peak height)" \
	    "FRS $fp, HSW $hp / reference $rp" \
	    "($fp - $rp) * ($fp - $rp) < ($hp - $rp) * ($hp - $rp)"
done
# HSW keeps its input's structure: the lattice of regular input; Halton's
# patterns less anisotropic on the blob and the environment map than
# uniform.
gs="" gx="" gc=""
for m in $MAPS; do
	a=$(v $m hsw-regular mean_aniso_db) b=$(v $m ref mean_aniso_db)
	gs="$gs${gs:+, }$m $a/$b"
	if num "$a" "$b"; then gx="$gx${gx:+ && }$a > $b + 6"; else gx="$gx${gx:+ && }0"; gc=$NOANN; fi
done
check "\"It is obvious that uniform random and regular sampling are not useful for blue-noise sampling\" (Sec. 6.3, Differential Domain Analysis): HSW with regular input keeps its lattice on every map, anisotropy 6 dB above the reference's" "$gs dB" "$gx" "$gc"
hc=$(v const hsw-halton mean_aniso_db) rc=$(v const ref mean_aniso_db)
for m in blob env; do
	hm=$(v $m hsw-halton mean_aniso_db) hr=$(v $m ref mean_aniso_db)
	if num "$hm" "$hr" "$hc" "$rc"; then
		check_order "$m: HSW with Halton input: \"the power spectra for the Gaussian blob and the environment importance maps are much closer to the reference than in the uniform case\" (Sec. 6.3, Differential Domain Analysis) (anisotropy above the reference's)" \
		    "$m $hm/$hr, const $hc/$rc dB" "$hm - $hr < $hc - $rc"
	else
		check "$m: HSW with Halton input: \"the power spectra for the Gaussian blob and the environment importance maps are much closer to the reference than in the uniform case\" (Sec. 6.3, Differential Domain Analysis) (anisotropy above the reference's)" \
		    "$m $hm/$hr, const $hc/$rc dB" 0 "$NOANN"
	fi
done
# Uniform sampling (Fig. 6.11): the first peak fringed outwardly (the
# distance from the peak to where it has fallen half way to 1), a clearly
# visible second peak, no isolated peaks beyond 2 spacings.
fringe() {	# (interpolated between the annuli)
	awk -F '\t' 'NR > 1 { n++; d[n] = $1; p[n] = $2; if ($2 > bp) { bp = $2; bi = n } }
	    END { h = 1 + (bp - 1) / 2
		for (i = bi; i < n && p[i + 1] > h; i++) ;
		x = (i < n) ? d[i] + (d[i + 1] - d[i]) * (p[i] - h) / (p[i] - p[i + 1]) : d[n]
		printf "%.3f", x - d[bi] }' "$OUT/radial-const-$1.tsv"
}
ff=$(fringe frs) rf=$(fringe ref)
check "uniform: \"a high-energy annulus, which is slightly fringed outwardly as compared to the sharp transition in the reference spectrum\" (Sec. 6.3, Differential Domain Analysis): the half fall beyond FRS's first peak wider than the reference's" \
    "$ff / $rf spacings" "$ff > $rf"
f2=$(v const frs peak2_power) r2=$(v const ref peak2_power)
check "uniform: \"the clearly visible second peak in the radial mean corresponding to the double of the minimum differential\" (Sec. 6.3, Differential Domain Analysis): its excess over 1 above 0.02 and at least twice the reference's" \
    "$f2 at $(v const frs peak2_dist) / $r2 at $(v const ref peak2_dist)" "$f2 - 1 > 0.02 && $f2 - 1 >= 2 * ($r2 - 1)" \
    "$(holds "$f2 < 0" && echo "no peak within 1.5 to 2.5 times the first's distance")"
check "uniform: no isolated peaks in FRS (its strongest value beyond 2.2 spacings at most 0.02 above the reference's)" \
    "$sp at $sd / $rsp at $rsd spacings" "$sp <= $rsp + 0.02"
observe "$sp > $rsp + 0.02 && $RCUT > 0 && $se > 0.9 * $RCUT && $se < 1.1 * $RCUT" \
    "FRS's strongest value beyond 2.2 spacings lies at $se window elements, within 10 % of the radius at which the matrix's force was cut off for this level ($RCUT cells, cutoff=$CUTOFF, from the header of $(basename "$FRS_MATRIX"); frd-gen(1): a force cut off at R leaves a ring at R)."
env_w=$(awk -F '\t' '$1 == "env" { split($3, a, "x"); print a[1] }' "$OUT/frs-window.tsv")
mat_w=$(awk -F '\t' '$1 == "env" { split($4, a, "x"); print a[1] }' "$OUT/frs-window.tsv")
observe "$env_w > $mat_w" "On the environment map the thesis's FRS window (${env_w}x$env_w) exceeds the matrix (${mat_w}x$mat_w), so with plain tiles the matrix's tiles repeat (the limit of thesis Table 4.1): FRS's anisotropy there is $(v env frs-plain mean_aniso_db) dB with plain tiles and $(v env frs mean_aniso_db) dB with the multi-level window (the default), against the reference's $(v env ref mean_aniso_db)."
env_setup
exp_note "The DDA is dda(1), not Wei's tool."
exp_end
