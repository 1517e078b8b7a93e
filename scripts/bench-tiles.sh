#!/bin/sh
# Tiles: frs-sample --tiles plain against shuffled on the HDR maps of data/
# (forest, sunset, interior; --equirect, no jitter, the default matrix)
# and on a constant map with 2^20 samples, in one run on one build.  Per
# case: the tiles of the window; the share of samples whose 4-neighbour
# difference vectors recur up to the 8 symmetries (ref_tiles repeat;
# target 2 %); the seam ratio, the 1st percentile of the nearest-neighbour
# distance in local spacings of the samples within half a spacing of a
# tile border over that of the others (ref_tiles seams; target 0.8); the
# thresholding time of sorted (-j 1, frs-sample -v), shuffled over plain
# (target 1.10).  Then a block chi-square (16 x 8 blocks, 200000 samples)
# of the counts against each map, shuffled (target p > 1e-4).
# usage: scripts/bench-tiles.sh BUILD
set -eu
cd "$(dirname "$0")/.."
B=${1:-build/rel}
FRS=$B/bin/frs-sample
REF=$B/test/ref_tiles
ENV=data
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT INT TERM

# v ARGS...: frs-sample -v's window, offset and thresholding seconds
run() {
	"$FRS" -q -v -j 1 --pdf "$@" -o "$W/p.pts" 2>"$W/v.txt"
	WIN=$(sed -n 's/.*window \([0-9]*\)x\([0-9]*\) at (\([0-9]*\), \([0-9]*\)).*/\1 \2 \3 \4/p' "$W/v.txt")
	TILES=$(sed -n 's/.*: \([0-9]*\) tiles.*/\1/p' "$W/v.txt")
	THR=$(sed -n 's/.*thresholding \([0-9.]*\) s.*/\1/p' "$W/v.txt")
}

# measure: the repeated share and the seam ratio of $W/p.pts
measure() {
	set -- $WIN
	REP=$("$REF" repeat "$1" "$2" "$W/p.pts" | awk '{ print $6 }')
	SEAM=$("$REF" seams "$1" "$2" 2048 2048 "$3" "$4" "$W/p.pts" |
	    awk '{ print $NF }')
}

echo "tiles: plain vs shuffled (sorted, -j 1, default matrix 2048^2)"
printf '%-10s %7s %6s %9s %9s %8s %8s %9s %9s %6s\n' map n tiles \
    rep_plain rep_shuf seam_pl seam_sh thr_pl_s thr_sh_s ratio
one() {	# name n map options...
	name=$1 n=$2
	shift 2
	run "$@" -n "$n" --tiles plain
	measure
	rp=$REP sp=$SEAM tp=$THR t=$TILES
	run "$@" -n "$n" --tiles shuffled
	measure
	printf '%-10s %7s %6s %9s %9s %8s %8s %9s %9s %6s\n' "$name" "$n" "$t" \
	    "$rp" "$REP" "$sp" "$SEAM" "$tp" "$THR" \
	    "$(awk -v a="$tp" -v b="$THR" 'BEGIN { printf "%.2f", (a > 0 ? b / a : 0) }')"
}
for m in forest sunset interior; do
	[ -f "$ENV/$m.exr" ] || { echo "$m: $ENV/$m.exr missing, skipped"; continue; }
	for n in 4096 16384 65536; do
		one "$m" "$n" -i "$ENV/$m.exr" --equirect
	done
done
one const 1048576 -i const
echo
echo "counts against the map, shuffled, 200000 samples, 16x8 blocks:"
for m in forest sunset interior; do
	[ -f "$ENV/$m.exr" ] || continue
	"$FRS" -q -i "$ENV/$m.exr" --equirect -n 200000 --tiles shuffled -o "$W/c.pts"
	printf '%-10s %s\n' "$m" "$("$REF" chi2 16 8 "$ENV/$m.exr" --equirect "$W/c.pts")"
done
