#!/bin/sh
# frs-sample: the analogue of thesis Table 6.2 and Fig. 6.13 (hsw-sample's
# part is scripts/bench-hsw.sh).  n = 2^0 ..
# 2^24 samples from four 128^2 maps, S_M = 2048 (data/default.frd
# prepared as a .frp), sigma 8, every implementation on one thread and on
# all; the thresholding time reported by -v (output to /dev/null) and
# the whole process.  BENCH_QUICK=1: the blob map, fewer counts.
set -eu
. "$(dirname "$0")/benchlib.sh"
BUILD=${1:-build/rel}
FRS=$BUILD/bin/frs-sample
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
TIME=/usr/bin/time
ALL=$(nproc)

"$BUILD/bin/frd-prep" -a all data/default.frd -o "$T/M.frp"
"$BUILD/bin/imap" convert --equirect -s 128x128 data/sunset.exr "$T/sunset.exr" 2>/dev/null
bench_sizes

# row NAME LOG2N ALGO MAXNAIVE ARGS...: one implementation on one thread
# and on all, a table row each; the naive time of the same n (set by its
# one-thread row, skipped past 2^MAXNAIVE) gives the ratio.
row() {
	name=$1 e=$2 a=$3 maxnaive=$4
	shift 4
	[ "$a" = naive ] && naive=""
	[ "$a" = naive ] && [ "$e" -gt "$maxnaive" ] && return 0
	for j in 1 $ALL; do
		$TIME -f "%e" -o "$T/t" "$FRS" -q "$@" -n $((1 << e)) -a "$a" \
		    -j $j -v -o /dev/null 2>"$T/v"
		# -v's summary, not its levels' lines ("... samples (38.0 % ...")
		line=$(grep -E '^frs-sample: [0-9]+ samples \(' "$T/v")
		cnt=$(echo "$line" | awk '{ print $2 }')
		th=$(echo "$line" | sed 's/.*thresholding \([0-9.]*\) s.*/\1/')
		[ "$a" = naive ] && [ $j = 1 ] && naive=$th
		awk -v m="$name" -v e="$e" -v a="$a" -v j=$j -v c="$cnt" -v t="$th" \
		    -v p="$(cat "$T/t")" -v nv="$naive" 'BEGIN {
			r = (nv != "" && t > 0) ? sprintf("%.1f", nv / t) : "-"
			rate = (t > 0) ? c / t / 1e6 : 0
			printf "%-7s %-6s %-7s %3s %10d %11.6f %9.1f %9.2f %9s\n", m, e, a, j, c, t, rate, p, r }'
		if [ "$j" = "$ALL" ]; then break; fi
	done
}

echo "frs-sample: seconds to threshold (-v) and whole process, S_M 2048, sigma 8"
printf '%-7s %-6s %-7s %3s %10s %11s %9s %9s %9s\n' map log2n algo thr \
    samples threshold_s Msamp/s process_s vs_naive
for map in $MAPS; do
	imp=$map
	[ "$map" = sunset ] && imp=$T/sunset.exr
	for e in $NS; do
		# Naive visits every window element: 10 s at 2^24.
		for a in naive stack level1 level2 sorted; do
			row "$map" "$e" $a 20 -m "$T/M.frp" -i "$imp"
		done
	done
done

echo
echo "3-D FRS: data/default3.frd (64^3), blob3 and shell3 volumes at 32^3, sigma 8"
printf '%-7s %-6s %-7s %3s %10s %11s %9s %9s %9s\n' volume log2n algo thr \
    samples threshold_s Msamp/s process_s vs_naive
if [ -n "${BENCH_QUICK:-}" ]; then NS3="10 16"; else NS3="10 14 18 22"; fi
for vol in blob3 shell3; do
	for e in $NS3; do
		# Naive visits sigma^3 n max/mean elements: minutes past 2^18.
		for a in naive sorted; do row $vol "$e" $a 14 -i $vol; done
	done
done

echo
echo "Sorted, 2^24 samples from the blob map, one thread, against the thesis"
# The thesis's window is one level (plain tiles); ours by default has
# levels too.  The time is -v's summary line ("N samples (sorted); ...",
# not the levels' lines, which also say "samples (").
for tiles in plain levels; do
	"$FRS" -q -m "$T/M.frp" -i blob -n 16777216 -j 1 -v --tiles $tiles \
	    -o /dev/null 2>"$T/v"
	th=$(sed -n 's/^frs-sample: [0-9]* samples (.*thresholding \([0-9.]*\) s.*/\1/p' "$T/v")
	awk -v t="$th" -v tiles=$tiles 'BEGIN {
		if (t == "") { print "thresholding, --tiles " tiles ": no time in -v"; exit }
		printf "thresholding, --tiles %-6s %.4f s (target 0.1 s: %s); thesis 0.883 s on a Q6600: %.1fx\n", tiles, t, t <= 0.1 ? "met" : "missed", 0.883 / t }'
done
$TIME -f "%M" -o "$T/mem" "$FRS" -q -m "$T/M.frp" -i blob -n 16777216 -j 1 -o "$T/out.pts"
awk -v mem="$(cat "$T/mem")" -v out="$(wc -c <"$T/out.pts")" 'BEGIN {
	printf "peak memory %.0f MiB; the output is %.0f MiB, the matrix 16 MiB (target: at most output + 2 x matrix = %.0f MiB)\n", mem / 1024, out / 1048576, out / 1048576 + 32 }'
