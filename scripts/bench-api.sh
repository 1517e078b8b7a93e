#!/bin/sh
# libfrs through its API (src/lib/frs.h, test/bench/bench_api.c):
# samples per second of frs_draw into the caller's buffer and of
# frs_draw_each, on one thread and on all, beside frs-sample's own
# figures for the same matrix (data/default.frd), map (blob), n and
# seed.  The ratio is samples/s over that of the whole frs-sample
# process with the .frd
# (which prepares the sorted lists each run, as the API's first call
# does once).  Best of R runs.  BENCH_QUICK=1: n = 10^6 only.
set -eu
. "$(dirname "$0")/benchlib.sh"
BUILD=${1:-build/rel}
FRS=$BUILD/bin/frs-sample
DRV=$BUILD/test/bench_api
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ALL=$(nproc)
MAT=data/default.frd
SEED=1
if [ -n "${BENCH_QUICK:-}" ]; then
	NS="1000000"
	R=3
	BLOCKS=256
else
	NS="100000 1000000 16777216"
	R=5
	BLOCKS=64,256,1024	# n_s of those counts: the lists they use
fi
# The same matrix prepared: frs-sample without list preparation.
"$BUILD/bin/frd-prep" -q -a sorted --blocks $BLOCKS "$MAT" -o "$T/M.frp"

# best CMD...: the least wall-clock seconds of R runs, in BEST.
best() {
	BEST=""
	for r in $(seq "$R"); do
		timed "$T/out" "$@"
		BEST=$(awk -v a="$SEC" -v b="$BEST" 'BEGIN {
			print (b == "" || a < b) ? a : b }')
	done
}

# row PATH THREADS SAMPLES SECONDS: a line of the table against BASE
# (samples/s of the frs-sample process).
row() {
	awk -v p="$1" -v j="$2" -v c="$3" -v t="$4" -v b="$BASE" 'BEGIN {
		rate = t > 0 ? c / t : 0
		printf "%-28s %3s %10d %9.4f %12.4g %7s\n", p, j, c, t, rate,
		    (b > 0 && rate > 0) ? sprintf("%.2f", rate / b) : "-" }'
}

echo "libfrs API against frs-sample: blob 128x128, $MAT, seed $SEED," \
    "best of $R; load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-28s %3s %10s %9s %12s %7s\n' path thr samples seconds samples/s \
    ratio
for n in $NS; do
	for j in 1 $ALL; do
		"$FRS" -q -m "$MAT" -i blob -n "$n" -S $SEED -j "$j" -v \
		    -o /dev/null 2>"$T/v"
		# -v's summary line, not its levels' lines
		cnt=$(sed -n 's/^frs-sample: \([0-9]*\) samples (.*/\1/p' "$T/v")
		best "$FRS" -q -m "$MAT" -i blob -n "$n" -S $SEED -j "$j" \
		    -o /dev/null
		BASE=$(awk -v c="$cnt" -v t="$BEST" 'BEGIN { print c / t }')
		row "frs-sample .frd, process" "$j" "$cnt" "$BEST"
		best "$FRS" -q -m "$T/M.frp" -i blob -n "$n" -S $SEED -j "$j" \
		    -o /dev/null
		row "frs-sample .frp, process" "$j" "$cnt" "$BEST"
		"$FRS" -q -m "$T/M.frp" -i blob -n "$n" -S $SEED -j "$j" -v \
		    -o /dev/null 2>"$T/v"
		th=$(sed -n 's/.*thresholding \([0-9.]*\) s.*/\1/p' "$T/v")
		row "frs-sample .frp, -v thresh." "$j" "$cnt" "${th:-0}"
		"$DRV" "$MAT" blob "$n" $SEED "$j" "$R" >"$T/api" 2>/dev/null
		while read -r what c s; do
			case $what in
			setup) p="api setup (mask, map)" ;;
			first) p="api first call (lists made)" ;;
			draw) p="api frs_draw" ;;
			each) p="api frs_draw_each" ;;
			*) p=$what ;;
			esac
			row "$p" "$j" "$c" "$s"
		done <"$T/api"
		if [ "$ALL" = 1 ]; then break; fi
	done
done
