#!/bin/sh
# hsw-sample: the HSW part of thesis Table 6.2 and Fig. 6.13 (n = 2^0 ..
# 2^24 Halton points warped by four 128^2 maps, the warping time of -v and
# the whole process, output to /dev/null), then 2^20 and 2^24 points from
# the blob map against hsw-sample of commit $BENCH_HSW_BASE (034c211, where
# issue 22 starts), built here in build/base-hsw if it is not there yet:
# the same run, one thread and all, the best of $BENCH_HSW_RUNS (3)
# interleaved runs of each.  BENCH_QUICK=1: the blob map, fewer counts.
set -eu
. "$(dirname "$0")/benchlib.sh"
BUILD=${1:-build/rel}
HSW=$BUILD/bin/hsw-sample
BASE_REV=${BENCH_HSW_BASE:-034c211}
BASE_DIR=build/base-hsw
RUNS=${BENCH_HSW_RUNS:-3}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ALL=$(nproc)

bench_sizes

# base_hsw DIR REV: the path of hsw-sample built (VARIANT=rel, as make
# bench builds ours) from the
# tree of commit REV in DIR/src, made unless DIR/rev already names REV.
base_hsw() {
	_dir=$1 _rev=$(git rev-parse --verify -q "$2^{commit}" 2>/dev/null) || {
		echo "bench-hsw: $2: no such commit" >&2
		return 1
	}
	_bin=$_dir/src/build/rel/bin/hsw-sample
	if [ ! -x "$_bin" ] || [ "$(cat "$_dir/rev" 2>/dev/null)" != "$_rev" ]; then
		rm -rf "$_dir"
		mkdir -p "$_dir/src"
		git archive "$_rev" | tar -x -C "$_dir/src"
		make -C "$_dir/src" -j"$ALL" VARIANT=rel progs >"$_dir/build.log" 2>&1 || {
			echo "bench-hsw: $_dir: building $2 failed (see $_dir/build.log)" >&2
			return 1
		}
		echo "$_rev" >"$_dir/rev"
	fi
	echo "$_bin"
}

"$BUILD/bin/imap" convert --equirect -s 128x128 data/sunset.exr "$T/sunset.exr" 2>/dev/null

echo "hsw-sample (Halton input): seconds to warp (-v) and whole process, 128^2 maps"
printf '%-7s %-6s %3s %10s %11s %9s %9s\n' map log2n thr samples warp_s Msamp/s process_s
for map in $MAPS; do
	imp=$map
	[ "$map" = sunset ] && imp=$T/sunset.exr
	for e in $NS; do
		n=$((1 << e))
		for j in 1 $ALL; do
			timed /dev/null "$HSW" -q -i "$imp" -n $n -j $j -v -o /dev/null 2>"$T/v"
			w=$(sed -n 's/.*warping \([0-9.]*\) s.*/\1/p' "$T/v")
			awk -v m=$map -v e=$e -v j=$j -v n=$n -v w="$w" -v p="$SEC" 'BEGIN {
				rate = (w > 0) ? n / w / 1e6 : 0
				printf "%-7s %-6s %3s %10d %11.6f %9.1f %9.2f\n", m, e, j, n, w, rate, p }'
			if [ "$j" = "$ALL" ]; then break; fi
		done
	done
done

# Without git or the commit (a release tarball) the comparison is skipped.
if ! BASE=$(base_hsw "$BASE_DIR" "$BASE_REV"); then
	echo "bench-hsw: no hsw-sample of $BASE_REV: the comparison is skipped" >&2
	exit 0
fi

# best LOG2N THREADS: the least whole-process seconds of ours and of the
# base over RUNS runs, each run one of ours then one of the base; sets
# OURS and THEIRS.
best() {
	OURS="" THEIRS=""
	_r=0
	while [ $_r -lt "$RUNS" ]; do
		timed /dev/null "$HSW" -q -i blob -n $((1 << $1)) -j "$2" -o /dev/null
		OURS=$(awk -v a="$OURS" -v b="$SEC" 'BEGIN { print (a == "" || b < a) ? b : a }')
		timed /dev/null "$BASE" -q -i blob -n $((1 << $1)) -j "$2" -o /dev/null
		THEIRS=$(awk -v a="$THEIRS" -v b="$SEC" 'BEGIN { print (a == "" || b < a) ? b : a }')
		_r=$((_r + 1))
	done
}

echo
echo "hsw-sample against $BASE_REV ($BASE): Halton points from the blob map, binary to /dev/null, whole process, best of $RUNS interleaved runs"
printf '%-6s %3s %9s %9s %9s\n' log2n thr ours_s base_s base/ours
for e in 20 24; do
	for j in 1 $ALL; do
		best $e $j
		awk -v e=$e -v j=$j -v o="$OURS" -v b="$THEIRS" 'BEGIN {
			printf "%-6s %3s %9.3f %9.3f %9.2f\n", e, j, o, b, b / o }'
		[ $e = 24 ] && [ $j = 1 ] && one=$OURS
		[ $e = 24 ] && all=$OURS
		if [ "$j" = "$ALL" ]; then break; fi
	done
done
"$HSW" -q -i blob -n 16777216 -j 1 -v -o /dev/null 2>"$T/v"
w=$(sed -n 's/.*warping \([0-9.]*\) s.*/\1/p' "$T/v")
awk -v w="$w" -v one="$one" -v all="$all" -v t="$ALL" 'BEGIN {
	printf "HSW 2^24 from the blob map: whole process %.3f s on one thread (target 1 s), %.3f s on %d (target 0.6 s on two); warping %.3f s on one thread, thesis 100 s on a Q6600: %.0fx\n", one, all, t, w, 100 / w }'
