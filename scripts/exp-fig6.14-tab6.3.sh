#!/bin/sh
# Thesis Sec. 6.4 "GPU Implementations", Fig. 6.14 and Table 6.3: time of
# the OpenCL implementations Naive, Level 1, Flat 1, Stack and Sorted of
# FRS and of HSW (Halton input) for n = 2^0 .. 2^24 samples from 128x128
# maps, S_M = 2048 (data/default.frd prepared with frd-prep -a all),
# sigma 8, in milliseconds.  The thesis ran them on an NVIDIA GTX 680;
# here the OpenCL device is whatever --device cl finds first (on this
# machine PoCL on the CPU: NOT a GPU).  From -v we take the kernels alone
# ("kernels" / "kernel") and the kernels with the transfers (to the
# device + kernels + back and offsets; points written + kernel + read);
# building the program is left out.  The measurements run one after
# another, cached until the programs change.  For comparison the CPU
# path (--device cpu, all threads) is timed for Sorted and HSW at the
# largest n, and a check that the device gives the same bytes as the CPU
# (cmp) closes it.  The thesis' claims are about its GPU: the verdict is
# "not comparable" unless the device is one; on another device the same
# claims are only observed.
#   tiny:  map blob, n = 2^0, 2^8, 2^12, matrix data/default.frd as it is
#   quick: map blob; Sorted and HSW at n = 2^0, 2^8, 2^12, 2^14, 2^16,
#          2^18, 2^20, 2^22, 2^24; Naive, Level 1, Flat 1 and Stack up to
#          2^20 and a window of 2^30 elements (Stack, Flat 1: 2^34)
#   full:  maps const, blob, ramp and env, n = 2^0 .. 2^24, Naive and
#          Level 1 up to windows of 2^34 elements (Stack, Flat 1: 2^38)
# ids: fig6.14-tab6.3 fig6.14 tab6.3
. "$(dirname "$0")/explib.sh"
exp_begin fig6.14-tab6.3 "OpenCL time of the FRS implementations and HSW" \
    "Sec. 6.4, Fig. 6.14 and Table 6.3: Naive, Level 1, Flat 1, Stack, Sorted and HSW on an NVIDIA GTX 680, n = 2^5..2^24, 128x128 maps, S_M = 2048, sigma 8, averages of 1000 runs, milliseconds" \
    "about 11 minutes (measured)"

MAPS=$(pick "blob" "blob" "const blob ramp env")
NS=$(pick "0 8 12" "0 8 12 14 16 18 20 22 24" "$(seq 0 24)")
SLOWMAX=$(pick 12 20 24)
LIM=$(pick 26 30 34)

if ! frs-sample --list-devices >"$OUT/devices.txt" 2>&1; then
	printf 'map\talgo\tlog2n\tn\tsamples\tkernel_ms\ttotal_ms\n' >"$OUT/times.tsv"
	exp_hw "nothing: there is no OpenCL device here ($(head -n 1 "$OUT/devices.txt"))"
	exp_end
	exit 0
fi
DEV=$(head -n 1 "$OUT/devices.txt" | cut -f 3)
DEVTYPE=$(head -n 1 "$OUT/devices.txt" | cut -f 4)

timing_inputs "$MAPS"

# Warm the runtime's kernel cache (not timed anyway: -v reports the build
# apart).
frs-sample -q -m "$FRP" -i blob -n 16 --device cl -o /dev/null
hsw-sample -q -i blob -n 16 --device cl -o /dev/null

meas() { # algo map e
	if [ "$1" = hsw ]; then
		hsw-sample -q -i "$(mapin "$2")" --input halton -n $((1 << $3)) \
		    --device cl -v -o /dev/null 2>&1 >/dev/null
	else
		frs-sample -q -m "$FRP" -i "$(mapin "$2")" -n $((1 << $3)) \
		    --sigma 8 -a "$1" --device cl -v -o /dev/null 2>&1 >/dev/null
	fi
}

D=$CACHE/perf-cl
TAG=$(basename "$FRP" | tr . _)
DTAG=$(echo "$DEV" | tr -c 'A-Za-z0-9\n' _ | cut -c 1-40)
printf 'map\talgo\tlog2n\tn\tsamples\tkernel_ms\ttotal_ms\n' >"$OUT/times.tsv"
for m in $MAPS; do
	mk=$(mkey $m)
	for a in sorted naive level1 flat1 stack hsw; do
		for e in $NS; do
			case $a in naive | level1 | flat1 | stack)
				[ "$e" -gt "$SLOWMAX" ] && continue
				lim=$LIM
				case $a in stack | flat1) lim=$((LIM + 4)) ;; esac
				window_over "$D/sorted_${mk}_${TAG}_s8_n${e}_${DTAG}.v" $lim && continue ;;
			esac
			f=$D/${a}_${mk}_${TAG}_s8_n${e}_${DTAG}.v
			cached "$f" meas $a $m "$e"
			awk -v m=$m -v a=$a -v e="$e" '
			/samples \([a-z0-9 ]*\); setup / { c = $2 }
			/OpenCL device/ {
				for (i = 1; i <= NF; i++) {
					if ($i == "device" && $(i + 1) ~ /^[0-9.]+$/) up = $(i + 1)
					if ($i == "kernels") k = $(i + 1)
					if ($i == "back") b = $(i + 3)
				}
			}
			/program and tree/ {
				c = 2^e
				for (i = 1; i <= NF; i++) {
					if ($i == "written") up = $(i + 1)
					if ($i == "kernel") k = $(i + 1)
					if ($i == "read") b = $(i + 1)
				}
			}
			END { printf "%s\t%s\t%d\t%.0f\t%s\t%.4f\t%.4f\n", m, a, e, 2^e, c, k * 1000, (up + k + b) * 1000 }' "$f" >>"$OUT/times.tsv"
		done
	done
done

cat >"$OUT/thesis.tsv" <<'EOF'
log2n	n	naive	level1	flat1	stack	sorted	hsw
5	32	0.62	0.61	1.79	0.71	0.09	0.18
6	64	0.62	0.61	1.82	0.72	0.09	0.19
7	128	0.63	0.61	1.82	0.72	0.09	0.19
8	256	0.63	0.62	1.81	0.74	0.09	0.19
9	512	0.63	0.62	1.84	0.75	0.09	0.19
10	1024	0.63	0.62	1.99	0.76	0.09	0.19
11	2048	0.63	0.62	1.99	0.80	0.09	0.20
12	4096	0.64	0.63	2.00	0.83	0.10	0.21
13	8192	0.64	0.64	1.96	0.89	0.10	0.24
14	16384	0.66	0.69	1.78	1.00	0.13	0.31
15	32768	0.87	0.93	1.89	1.31	0.15	0.47
16	65536	0.95	0.99	2.01	1.63	0.20	0.78
17	131072	2.26	2.08	3.39	3.57	0.28	1.64
18	262144	2.31	2.61	3.59	5.12	0.43	2.92
19	524288	10.15	7.12	9.10	14.27	0.88	5.11
20	1048576	10.64	9.45	11.34	22.01	1.61	9.72
21	2097152	21.58	20.57	24.97	56.84	3.06	18.83
22	4194304	27.78	26.98	32.59	89.56	5.85	37.14
23	8388608	63.34	71.62	-	206.06	11.27	73.49
24	16777216	78.88	88.31	-	319.48	21.31	145.53
EOF

# Averages over the maps where every map was measured: kernels alone and
# with the transfers.
NMAPS=$(echo $MAPS | wc -w)
awk -F'\t' -v nm="$NMAPS" -v out="$OUT" '
NR == 1 { next }
{ k = $3 SUBSEP $2; sk[k] += $6; st[k] += $7; cnt[k]++; e[$3] = 1 }
END {
	split("naive level1 flat1 stack sorted hsw", A, " ")
	f = out "/avg.tsv"
	printf "log2n\tn" >f
	for (i = 1; i <= 6; i++) printf "\t%s_kernel_ms", A[i] >f
	for (i = 1; i <= 6; i++) printf "\t%s_total_ms", A[i] >f
	printf "\n" >f
	for (x = 0; x <= 40; x++) {
		if (!(x in e)) continue
		printf "%d\t%.0f", x, 2^x >f
		for (i = 1; i <= 6; i++) { k = x SUBSEP A[i]; printf "\t%s", (cnt[k] == nm ? sprintf("%.4f", sk[k] / nm) : "-") >f }
		for (i = 1; i <= 6; i++) { k = x SUBSEP A[i]; printf "\t%s", (cnt[k] == nm ? sprintf("%.4f", st[k] / nm) : "-") >f }
		printf "\n" >f
	}
}' "$OUT/times.tsv"

compare_thesis "naive level1 flat1 stack sorted hsw" %.2f \
    "$(printf 'log2n\talgo\tours_kernel_ms\tours_total_ms\tthesis_ms\tthesis_over_ours_kernel')" >"$OUT/compare.tsv"

{
	gp_png "$OUT/fig6.14.png"
	gp_loglog
	cat <<EOF
set xlabel 'samples n'
set ylabel 'milliseconds'
set key left top font ',8'
set grid
set title "Fig. 6.14: OpenCL on $DEVTYPE device $DEV (NOT the thesis' GTX 680)\\nkernels (points), with transfers (dotted); maps: $MAPS; thesis Table 6.3 thin lines" font ',9'
p '$OUT/avg.tsv' u 2:3 w lp lc 1 pt 7 t 'Naive', '' u 2:4 w lp lc 2 pt 7 t 'Level 1', '' u 2:5 w lp lc 6 pt 7 t 'Flat 1', \
  '' u 2:6 w lp lc 3 pt 7 t 'Stack', '' u 2:7 w lp lc 4 pt 7 lw 2 t 'Sorted', '' u 2:8 w lp lc 7 pt 7 lw 2 t 'HSW', \
  '' u 2:13 w l lc 4 dt 3 t 'Sorted + transfers', '' u 2:14 w l lc 7 dt 3 t 'HSW + transfers', \
  '$OUT/thesis.tsv' u 2:3 w l dt 2 lc 1 t 'thesis Naive', '' u 2:4 w l dt 2 lc 2 t 'thesis Level 1', '' u 2:5 w l dt 2 lc 6 t 'thesis Flat 1', \
  '' u 2:6 w l dt 2 lc 3 t 'thesis Stack', '' u 2:7 w l dt 2 lc 4 t 'thesis Sorted', '' u 2:8 w l dt 2 lc 7 t 'thesis HSW'
EOF
} | gnuplot

# The device gives the CPU's bytes (one case each).
CE=$(pick 8 16 16)
same() { # label cmd-cpu cmd-cl
	cached "$CACHE/perf-cl/cmp_$1_${TAG}_${DTAG}_n$CE.txt" sh -c "$2 -o \"\$0.cpu\" && $3 -o \"\$0.cl\" && { if cmp -s \"\$0.cpu\" \"\$0.cl\"; then echo identical; else echo differ; fi; rm -f \"\$0.cpu\" \"\$0.cl\"; }" "$CACHE/perf-cl/cmp_$1_${TAG}_${DTAG}_n$CE.work"
}
same sorted "frs-sample -q -m $FRP -i blob -n $((1 << CE)) -a sorted --device cpu" "frs-sample -q -m $FRP -i blob -n $((1 << CE)) -a sorted --device cl"
same flat1 "frs-sample -q -m $FRP -i blob -n $((1 << CE)) -a stack --device cpu" "frs-sample -q -m $FRP -i blob -n $((1 << CE)) -a flat1 --device cl"
same hsw "hsw-sample -q -i blob -n $((1 << CE)) --device cpu" "hsw-sample -q -i blob -n $((1 << CE)) --device cl"
CS=$(cat "$CACHE/perf-cl/cmp_sorted_${TAG}_${DTAG}_n$CE.txt")
CF=$(cat "$CACHE/perf-cl/cmp_flat1_${TAG}_${DTAG}_n$CE.txt")
CH=$(cat "$CACHE/perf-cl/cmp_hsw_${TAG}_${DTAG}_n$CE.txt")
printf 'case\tresult\nsorted cl vs cpu, blob, n = 2^%s\t%s\nflat1 cl vs stack cpu, blob, n = 2^%s\t%s\nhsw cl vs cpu, blob, n = 2^%s\t%s\n' \
    "$CE" "$CS" "$CE" "$CF" "$CE" "$CH" >"$OUT/cmp.tsv"

row "OpenCL device" "$DEV ($DEVTYPE)" "NVIDIA GeForce GTX 680 (GPU)"
EMAX=$(echo $NS | tr ' ' '\n' | tail -n 1)
RE="20 24"
case " $NS " in *" 20 "* | *" 24 "*) ;; *) RE=$EMAX ;; esac
for e in $RE; do
	for a in naive level1 flat1 stack sorted hsw; do
		k=$(get "$e" ${a}_kernel_ms)
		[ -z "$k" ] || [ "$k" = - ] && continue
		t=$(thv "$e" $a)
		row "$a, n = 2^$e: kernels / with transfers" "$k / $(get "$e" ${a}_total_ms) ms" "${t:--} ms (thesis/ours kernels $(ratio "$t" "$k"))"
	done
done
row "Sorted / HSW kernels, n = 2^$EMAX" "$(ratio "$(get "$EMAX" sorted_kernel_ms)" "$(get "$EMAX" hsw_kernel_ms)")" "$(ratio "$(thv "$EMAX" sorted)" "$(thv "$EMAX" hsw)") (Sorted faster than HSW for every n)"
row "device output = CPU output (cmp, blob, 2^$CE)" "Sorted $CS, Flat 1 vs Stack $CF, HSW $CH" "(not in the thesis: its GPU code was single precision)"

# The CPU path at the largest n, all threads (what the device competes
# with on this machine): thresholding / warping, in ms.
cpu_meas() { # algo e
	if [ "$1" = hsw ]; then
		hsw-sample -q -i blob --input halton -n $((1 << $2)) --device cpu -j "$(nproc)" -v -o /dev/null 2>&1 >/dev/null
	else
		frs-sample -q -m "$FRP" -i blob -n $((1 << $2)) --sigma 8 -a "$1" --device cpu -j "$(nproc)" -v -o /dev/null 2>&1 >/dev/null
	fi
}
cpu_ms() { # algo: the main phase in ms
	f=$D/cpu_$1_blob_${TAG}_s8_n${EMAX}_j$(nproc).v
	cached "$f" cpu_meas "$1" "$EMAX"
	awk '{ for (i = 1; i < NF; i++) if ($i == "thresholding" || $i == "warping") printf "%.4f", $(i + 1) * 1000 }' "$f"
}
PS=$(cpu_ms sorted)
PH=$(cpu_ms hsw)
KS=$(awk -F'\t' -v e="$EMAX" '$1 == "blob" && $2 == "sorted" && $3 == e { print $6 }' "$OUT/times.tsv")
KH=$(awk -F'\t' -v e="$EMAX" '$1 == "blob" && $2 == "hsw" && $3 == e { print $6 }' "$OUT/times.tsv")
row "blob, n = 2^$EMAX: OpenCL kernels / CPU path ($(nproc) threads)" "Sorted $KS / $PS ms, HSW $KH / $PH ms" "(not in the thesis)"

# What we can check: the device gives the CPU's bytes.
check "ours, not the thesis's: the OpenCL Sorted output equals the CPU's, byte for byte (blob, 2^$CE)" "$CS" "\"$CS\" == \"identical\""
check "ours, not the thesis's: the OpenCL Flat 1 output equals the CPU's Stack output (blob, 2^$CE)" "$CF" "\"$CF\" == \"identical\""
check "ours, not the thesis's: the OpenCL HSW output equals the CPU's (blob, 2^$CE)" "$CH" "\"$CH\" == \"identical\""

# The thesis' GPU claims, observed on this device: Sorted the fastest
# kernel at the largest n of the others and faster than HSW at every n;
# Flat 1 the slowest FRS kernel; Stack slower than Naive.
ES=$(awk -F'\t' 'NR > 1 && $3 != "-" { e = $1 } END { print e }' "$OUT/avg.tsv")
on="On this device ($DEVTYPE)"
if [ -n "$ES" ]; then
	set -- $(awk -F'\t' -v x="$ES" 'NR > 1 && $1 == x { n = split("naive level1 flat1 stack hsw", A, " "); split("3 4 5 6 8", C, " "); for (i = 1; i <= n; i++) if ($C[i] != "-" && (b == "" || $C[i] < b)) { b = $C[i]; ba = A[i] } print $7, b, ba }' "$OUT/avg.tsv")
	if [ $# = 3 ]; then
		observe "$1 < $2" "$on, as on the thesis' GPU, Sorted has the fastest kernels at 2^$ES ($1 ms; next $(pretty $3), $2 ms)."
		observe "$1 >= $2" "$on, unlike on the thesis' GPU, Sorted's kernels are not the fastest at 2^$ES ($1 ms; $(pretty $3) $2 ms)."
	fi
	set -- $(awk -F'\t' -v x="$ES" 'NR > 1 && $1 == x { print $5, $3, $6 }' "$OUT/avg.tsv")
	if [ $# = 3 ] && [ "$1" != - ]; then
		observe "$1 > $2 && $1 > $3" "$on, as on the thesis' GPU, Flat 1's kernels are slower than Naive's and Stack's at 2^$ES ($1 ms against $2 and $3 ms)."
		observe "!($1 > $2 && $1 > $3)" "$on, unlike on the thesis' GPU, Flat 1's kernels are not slower than both Naive's and Stack's at 2^$ES ($1 ms against $2 and $3 ms)."
		observe "$3 > $2" "$on, as on the thesis' GPU, Stack's kernels are slower than Naive's at 2^$ES ($3 against $2 ms)."
		observe "$3 <= $2" "$on, unlike on the thesis' GPU, Stack's kernels are faster than Naive's at 2^$ES ($3 against $2 ms)."
	fi
fi
set -- $(awk -F'\t' 'NR > 1 && $7 != "-" && $8 != "-" { c++; if ($7 < $8) w++ } END { print c + 0, w + 0 }' "$OUT/avg.tsv")
observe "$2 == $1" "$on, as on the thesis' GPU, Sorted's kernels are faster than HSW's at every measured n."
observe "$2 < $1" "$on, unlike on the thesis' GPU (every n), Sorted's kernels are faster than HSW's at only $2 of $1 measured n."
exp_hw "OpenCL on $DEV (type $DEVTYPE, $(head -n 1 "$OUT/devices.txt" | cut -f 5)), not the thesis' GTX 680; at 2^$EMAX on blob its Sorted kernels took $KS ms and its HSW kernels $KH ms, against $PS ms and $PH ms on the CPU path with $(nproc) threads"
exp_end
