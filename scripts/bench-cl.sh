#!/bin/sh
# OpenCL: the analogue of thesis Table 6.3 and Fig. 6.14 on whatever
# OpenCL device there is (PoCL on the CPU here; run it on a GPU machine
# for the thesis' comparison: GTX 680, Sorted 2^24 in 21.3 ms, HSW
# 145.5 ms).  128^2 blob, plain tiles (the thesis' one window), S_M =
# 2048 (data/default.frd prepared), sigma 8; per implementation and n
# the CPU thresholding time (all threads) beside the device's kernels
# alone and with the transfers (building the program, cached by the
# runtime, left out), in milliseconds.
#   scripts/bench-cl.sh [BUILD]        BENCH_QUICK=1: fewer counts
set -eu
BUILD=${1:-build/rel}
FRS=$BUILD/bin/frs-sample
HSW=$BUILD/bin/hsw-sample
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ALL=$(nproc)
for p in "$FRS" "$HSW"; do
	[ -x "$p" ] || { echo "bench-cl: $p: missing"; exit 1; }
done
if ! "$FRS" --list-devices >"$T/dev" 2>"$T/err"; then
	echo "bench-cl: no OpenCL device: $(cat "$T/err")"
	exit 0
fi
if [ -n "${BENCH_QUICK:-}" ]; then
	NS="0 16 20"
else
	NS="0 4 8 12 16 20 22 24"
fi
"$BUILD/bin/frd-prep" -a all data/default.frd -o "$T/M.frp"
# Warm the kernel cache so that no timing below pays for a build.
"$FRS" -q -m "$T/M.frp" -i blob -n 16 --device cl -o /dev/null
"$HSW" -q -i blob -n 16 --device cl -o /dev/null

echo "OpenCL device: $(head -n 1 "$T/dev" | cut -f 2-)"
echo "FRS thresholding, 128^2 blob, plain tiles, S_M 2048, sigma 8, milliseconds"
printf '%-7s %5s %10s %10s %10s %10s %8s\n' algo log2n samples cpu_ms \
    cl_kern_ms cl_total_ms total/cpu
for e in $NS; do
	n=$((1 << e))
	for a in naive stack level1 level2 sorted flat1; do
		# the slow ones visit most of the window: seconds at 2^22
		case $a in naive | level1 | level2) [ "$e" -gt 20 ] && continue ;; esac
		cpu=-
		if [ $a != flat1 ]; then
			"$FRS" -q -m "$T/M.frp" -i blob -n $n -a $a --tiles plain -j "$ALL" -v \
			    -o /dev/null 2>"$T/v"
			cpu=$(sed -n 's/.*thresholding \([0-9.]*\) s.*/\1/p' "$T/v")
		fi
		"$FRS" -q -m "$T/M.frp" -i blob -n $n -a $a --tiles plain --device cl -v \
		    -o /dev/null 2>"$T/v"
		cnt=$(sed -n "s/^[^ ]*: \([0-9]*\) samples (.*/\1/p" "$T/v")
		awk -v a=$a -v e=$e -v c="$cnt" -v cpu="$cpu" '
			/OpenCL device/ {
				for (i = 1; i <= NF; i++) {
					if ($i == "device" && $(i+1) ~ /^[0-9.]+$/) up = $(i+1)
					if ($i == "kernels") k = $(i+1)
					if ($i == "back") b = $(i+3)
				}
			}
			END {
				tot = up + k + b
				r = cpu == "-" ? "-" : sprintf("%.1f", tot / (cpu > 0 ? cpu : 1e-9))
				cs = cpu == "-" ? "-" : sprintf("%.3f", cpu * 1000)
				printf "%-7s %5s %10s %10s %10.3f %10.3f %8s\n", a, e, c, cs, k * 1000, tot * 1000, r
			}' "$T/v"
	done
done
echo "(cl_total: to the device + kernels + back and offsets; total/cpu > 1"
echo " means the CPU is faster; on PoCL the device is this machine's CPU)"

echo
echo "HSW warp, Halton input, 128^2 blob, milliseconds"
printf '%-5s %10s %10s %10s %8s\n' log2n cpu_ms cl_kern_ms cl_total_ms total/cpu
for e in $NS; do
	n=$((1 << e))
	"$HSW" -q -i blob -n $n -j "$ALL" -v -o /dev/null 2>"$T/v"
	cpu=$(sed -n 's/.*warping \([0-9.]*\) s.*/\1/p' "$T/v")
	"$HSW" -q -i blob -n $n --device cl -v -o /dev/null 2>"$T/v"
	awk -v e=$e -v cpu="$cpu" '
		/program and tree/ {
			for (i = 1; i <= NF; i++) {
				if ($i == "written") w = $(i+1)
				if ($i == "kernel") k = $(i+1)
				if ($i == "read") r = $(i+1)
			}
		}
		END {
			tot = w + k + r
			printf "%-5s %10.3f %10.3f %10.3f %8.1f\n", e, cpu * 1000, k * 1000, tot * 1000, tot / (cpu > 0 ? cpu : 1e-9)
		}' "$T/v"
done
