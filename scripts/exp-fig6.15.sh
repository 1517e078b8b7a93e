#!/bin/sh
# Thesis Sec. 6.4, Fig. 6.15: the share of the time that each task takes
# when sampling the Gaussian blob (128x128) adaptively: Sorted FRS with
# sigma 4 (S_M = 2048, data/default.frd prepared with frd-prep -a all,
# jittered with Halton points as in the thesis) and HSW with Halton input.
# The phases are those -v reports: setup (FRS: reading the matrix and its
# sorted lists, the map's mean and maximum, the window; HSW: the Haar
# tree of the map and the input points), thresholding / warping, and
# output (with the jitter; written to /dev/null).  The jitter's own share
# is estimated as the output time with --jitter halton minus that with
# --jitter none.  One thread, on the CPU (the thesis ran this on its GPU).
# Measurements run one after another, cached until the programs change;
# each is the minimum over REPS runs.
#   tiny:  n = 2^8, 2^12; matrix data/default.frd as it is; REPS 1
#   quick: n = 2^8, 2^12, 2^16, 2^20, 2^24; REPS 2
#   full:  n = 2^4, 2^8, ..., 2^24; REPS 5
# ids: fig6.15
. "$(dirname "$0")/explib.sh"
exp_begin fig6.15 "Share of time per task, Sorted FRS and HSW" \
    "Sec. 6.4, Fig. 6.15: proportional time of the tasks of Sorted (sigma 4) and HSW (Halton) on the Gaussian blob, GTX 680" \
    "about 1 minute"

NS=$(pick "8 12" "8 12 16 20 24" "4 8 12 16 20 24")
REPS=$(pick 1 2 5)
if [ "$MODE" = tiny ]; then
	FRP=$FRS_MATRIX
else
	FRP=$CACHE/default-all.frp
	cached "$FRP" frd-prep -q -a all "$FRS_MATRIX"
fi
TAG=$(basename "$FRP" | tr . _)

meas() { # frs|hsw jitter e
	i=0
	while [ $i -lt "$REPS" ]; do
		if [ "$1" = hsw ]; then
			hsw-sample -q -i blob --input halton -n $((1 << $3)) -j 1 -v -o /dev/null 2>&1 >/dev/null
		else
			frs-sample -q -m "$FRP" -i blob -n $((1 << $3)) -a sorted --sigma 4 \
			    --jitter "$2" -j 1 -v -o /dev/null 2>&1 >/dev/null
		fi
		i=$((i + 1))
	done
}
# minimum setup, main and output phase over the runs of a file
phases() {
	awk 'function num(k,   i) { for (i = 1; i < NF; i++) if ($i == k) return $(i + 1) + 0; return -1 }
	function mn(x, v) { return (x == "" || v < x) ? v : x }
	/samples \(/ { s = mn(s, num("setup")); t = mn(t, num("thresholding")); o = mn(o, num("output")) }
	/warping/ { s = mn(s, num("setup")); t = mn(t, num("warping")); o = mn(o, num("output")) }
	END { printf "%.6f\t%.6f\t%.6f", s, t, o }' "$1"
}

D=$CACHE/perf-share
printf 'method\tlog2n\tn\tsetup_s\tmain_s\toutput_s\tjitter_s\tsetup_pct\tmain_pct\toutput_pct\tjitter_pct\n' >"$OUT/shares.tsv"
for e in $NS; do
	fj=$D/frs_blob_${TAG}_s4_halton_n${e}_j1_x$REPS.v
	fn=$D/frs_blob_${TAG}_s4_none_n${e}_j1_x$REPS.v
	fh=$D/hsw_blob_halton_n${e}_j1_x$REPS.v
	cached "$fj" meas frs halton "$e"
	cached "$fn" meas frs none "$e"
	cached "$fh" meas hsw - "$e"
	for m in frs hsw; do
		if [ $m = frs ]; then p=$(phases "$fj"); o0=$(phases "$fn" | cut -f 3); lab="Sorted s4"; else p=$(phases "$fh"); o0=x; lab=HSW; fi
		echo "$p" | awk -F'\t' -v l="$lab" -v e="$e" -v o0="$o0" '{
			j = (o0 == "x") ? 0 : $3 - o0; if (j < 0) j = 0
			t = $1 + $2 + $3
			printf "%s\t%d\t%.0f\t%s\t%s\t%s\t%.6f\t%.1f\t%.1f\t%.1f\t%.1f\n", l, e, 2^e, $1, $2, $3, j, 100 * $1 / t, 100 * $2 / t, 100 * $3 / t, 100 * j / t }' >>"$OUT/shares.tsv"
	done
done

# The stacked bars: setup, main phase, output less jitter, jitter.
awk -F'\t' 'NR == 1 { print "label\tsetup\tthresholding/warping\toutput\tjitter"; next }
	{ printf "%s 2^%d\t%s\t%s\t%.1f\t%s\n", $1, $2, $8, $9, $10 - $11, $11 }' "$OUT/shares.tsv" >"$OUT/bars.tsv"
{
	gp_png "$OUT/fig6.15.png"
	cat <<EOF
set style data histograms
set style histogram rowstacked
set style fill solid 0.8 border -1
set boxwidth 0.7
set yrange [0:100]
set ylabel 'share of the time (%)'
set xtics rotate by -35 font ',9'
set key outside right
set title 'Fig. 6.15: share of time per task, blob 128x128, one CPU thread (Sorted: sigma 4, Halton jitter; HSW: Halton input)'
p '$OUT/bars.tsv' u 2:xtic(1), '' u 3, '' u 4, '' u 5
EOF
} | gnuplot

sh_() { awk -F'\t' -v l="$1" -v e="$2" -v c="$3" 'NR > 1 && $1 == l && $2 == e { print $c }' "$OUT/shares.tsv"; }
E0=$(echo $NS | cut -d' ' -f1)
EM=$(echo $NS | tr ' ' '\n' | tail -n 1)
for e in $E0 $EM; do
	row "Sorted s4, n = 2^$e: setup / thresholding / output (of which jitter) %" \
	    "$(sh_ "Sorted s4" "$e" 8) / $(sh_ "Sorted s4" "$e" 9) / $(sh_ "Sorted s4" "$e" 10) ($(sh_ "Sorted s4" "$e" 11))" \
	    "setup the largest task for small n; jitter more than a third of the time"
	row "HSW, n = 2^$e: setup / warping / output %" \
	    "$(sh_ HSW "$e" 8) / $(sh_ HSW "$e" 9) / $(sh_ HSW "$e" 10)" \
	    "the Haar basis (setup) the largest task for small n"
done
JM=$(sh_ "Sorted s4" "$EM" 11)
S0=$(sh_ "Sorted s4" "$E0" 8)
H0=$(sh_ HSW "$E0" 8)
exp_end "differs" "Shares on the CPU (one thread), not the thesis' GPU (this machine has none).  As in the thesis, the setup is the largest task for small n with both methods (2^$E0: Sorted $S0 %, HSW $H0 %), but for FRS the reason differs: our setup is mostly loading the 2048^2 matrix and its sorted lists, while the map's mean and maximum, which the thesis counted, cost almost nothing.  The jitter (Halton, made per sample with the output) takes $JM % of Sorted's time at 2^$EM, and more than a third from about 2^20 on, in line with the thesis' 'more than a third'; for small n it is negligible.  Jitter share = output time with --jitter halton minus with --jitter none."
