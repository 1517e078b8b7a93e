#!/bin/sh
# The speed of the main job (issue 22), ours against the programs of
# commit 034c211 (where that work started), built beside ours and run in
# the same run, interleaved: Sorted FRS on the 128^2 blob map from the
# shipped matrix (data/default.frd, no .frp), binary points to
# /dev/null; the setup, thresholding and output phases (-v) on one
# thread and two; the output to /dev/null and to a pipe; the same draw in
# memory through libfrs (test/bench/bench_api.c); OpenCL Sorted against the CPU
# path.  Medians of R runs.  FRS_AUTHORS: a command that times the thesis
# authors' Sorted sampler for N samples (it is run as "$FRS_AUTHORS N"
# and prints seconds), timed in the same run when set.
# BENCH_QUICK=1: fewer runs.
set -eu
. "$(dirname "$0")/benchlib.sh"
BUILD=${1:-build/rel}
OURS=$BUILD/bin
BASE_COMMIT=${BENCH_BASE:-034c211}	# BENCH_BASE: another commit to compare with
MAT=data/default.frd
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
if [ -n "${BENCH_QUICK:-}" ]; then R=3; else R=7; fi
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$T/pocl}"

BASE=$(baseline_build $BASE_COMMIT) || BASE=""
if [ -n "$BASE" ] && [ ! -x "$BASE/../test/bench_api" ]; then
	make -C "$BASE/../../.." VARIANT=rel build/rel/test/bench_api \
	    >/dev/null 2>&1 || true
fi

# med CMD...: the median wall seconds of R runs of CMD (output dropped).
med() {
	: >"$T/runs"
	for _r in $(seq "$R"); do
		timed /dev/null "$@"
		echo "$SEC" >>"$T/runs"
	done
	median_of "$T/runs"
}

# med_both ARGS...: "OURS BASE", the median wall seconds of R runs of
# frs-sample ARGS, ours and the baseline's in turn (BASE 0 without one).
med_both() {
	: >"$T/mo"
	: >"$T/mb"
	for _r in $(seq "$R"); do
		timed /dev/null "$OURS/frs-sample" "$@"
		echo "$SEC" >>"$T/mo"
		if [ -n "$BASE" ]; then
			timed /dev/null "$BASE/frs-sample" "$@"
			echo "$SEC" >>"$T/mb"
		fi
	done
	[ -s "$T/mb" ] || echo 0 >"$T/mb"
	echo "$(median_of "$T/mo") $(median_of "$T/mb")"
}

# phase_run BIN NAME N J OUT: one run's -v time of phase NAME, added to OUT.
phase_run() {
	"$1/frs-sample" -q -m "$MAT" -i blob -n "$3" -j "$4" -v \
	    -o /dev/null 2>"$T/v"
	sed -n "s/.* $2 \\([0-9.]*\\) s.*/\\1/p" "$T/v" >>"$5"
}

# phases NAME N J: "OURS BASE", the medians of 3R runs of one -v phase,
# ours and the baseline's in turn (BASE 0 without one).  A phase of a few
# milliseconds on two threads varies by 3x between runs here: fewer runs,
# or all of one build before the other, can flip the verdict.
phases() {
	: >"$T/po"
	: >"$T/pb"
	for _r in $(seq $((3 * R))); do
		phase_run "$OURS" "$1" "$2" "$3" "$T/po"
		[ -n "$BASE" ] && phase_run "$BASE" "$1" "$2" "$3" "$T/pb"
	done
	[ -s "$T/pb" ] || echo 0 >"$T/pb"
	echo "$(median_of "$T/po") $(median_of "$T/pb")"
}

verdict() { awk -v v="$1" -v t="$2" 'BEGIN { print (v <= t) ? "met" : "missed" }'; }

echo "Speed of Sorted FRS, blob 128x128, $MAT (no .frp), one thread unless said;"
echo "medians of $R runs, ours and the baseline's in turn ($BASE_COMMIT);" \
    "load average $(cut -d' ' -f1-3 /proc/loadavg)"
[ -n "$BASE" ] || echo "(the baseline could not be built: its columns are 0)"
printf '%-40s %10s %10s %8s %9s %7s\n' what ours_s base_s speedup target verdict
row() {	# WHAT OURS BASE TARGET
	printf '%-40s %10.4f %10.4f %8s %9s %7s\n' "$1" "$2" "$3" \
	    "$(ratio "$3" "$2")" "${4:--}" \
	    "$([ -n "${4:-}" ] && verdict "$2" "$4" || echo -)"
}
for e in 20 24; do
	n=$((1 << e))
	for j in 1 2; do
		set -- $(med_both -q -m "$MAT" -i blob -n $n -j $j -o /dev/null)
		o=$1 b=$2
		tgt=""
		[ $j = 1 ] && [ $e = 24 ] && tgt=0.6
		[ $j = 1 ] && [ $e = 20 ] && tgt=0.1
		row "process 2^$e, -j $j, to /dev/null" "$o" "$b" "$tgt"
	done
done
for e in 20 24; do
	n=$((1 << e))
	o=$(med "$OURS/frs-sample" -q -m "$MAT" -i blob -n $n -j 1 --exact-count -o /dev/null)
	d=$(med "$OURS/frs-sample" -q -m "$MAT" -i blob -n $n -j 1 -o /dev/null)
	printf '%-40s %10.4f s (%.2fx the run of about n)\n' \
	    "process 2^$e --exact-count, -j 1" "$o" "$(ratio "$o" "$d")"
done

echo
echo "Phases (-v) at 2^24, medians of $((3 * R)) runs, ours and the baseline's in turn;"
echo "the thresholding includes the conversion to points (ours converts each"
echo "chunk where it is thresholded; the baseline in its output)"
for p in setup thresholding output; do
	for j in 1 2; do
		set -- $(phases $p 16777216 $j)
		o=$1 b=$2
		tgt=""
		[ $p = setup ] && tgt=0.15
		row "$p, -j $j" "$o" "$b" "$tgt"
		[ $j = 1 ] && o1=$o
	done
	if [ $p = thresholding ]; then
		r=$(ratio "$o1" "$o")
		printf '%-40s %10s  target 1.5: %s\n' \
		    "thresholding -j 1 / -j 2 (ours)" "$r" \
		    "$(awk -v r="$r" 'BEGIN { print (r >= 1.5) ? "met" : "missed" }')"
	fi
done
for e in 10 16; do
	set -- $(phases setup $((1 << e)) 1)
	o=$1 b=$2
	row "setup, 2^$e" "$o" "$b" 0.15
done

echo
echo "Output of 2^24 points (268 MB binary): to /dev/null, through a pipe, text"
bytes=$("$OURS/frs-sample" -q -m "$MAT" -i blob -n 16777216 | wc -c)
o=$(med "$OURS/frs-sample" -q -m "$MAT" -i blob -n 16777216 -o /dev/null)
c=$(med "$OURS/frs-sample" -q -m "$MAT" -i blob -n 16777216 --count-only)
w=$(awk -v a="$o" -v b="$c" 'BEGIN { print a - b }')
printf '%-40s %10.4f s  %6.2f GB/s (target 1 GB/s)\n' "binary to /dev/null, beyond --count-only" \
    "$w" "$(awk -v s="$w" -v b="$bytes" 'BEGIN { print (s > 0) ? b / s / 1e9 : 0 }')"
sh -c "exec \"$OURS/frs-sample\" -q -m \"$MAT\" -i blob -n 16777216 | cat >/dev/null" &&
    p=$(med sh -c "exec \"$OURS/frs-sample\" -q -m \"$MAT\" -i blob -n 16777216 | cat >/dev/null")
printf '%-40s %10.4f s  %6.2f GB/s (whole process)\n' "binary through a pipe to cat" "$p" \
    "$(awk -v s="$p" -v b="$bytes" 'BEGIN { print (s > 0) ? b / s / 1e9 : 0 }')"
set -- $(med_both -q -m "$MAT" -i blob -n 1048576 -T -o /dev/null)
tx=$1 tb=$2
row "text, 2^20, to /dev/null" "$tx" "$tb" ""

echo
echo "In memory through libfrs (bench_api: frs_draw into the caller's buffer,"
echo "best of $R, once the sampler and its lists are made), beside the process"
for e in 20 24; do
	n=$((1 << e))
	"$BUILD/test/bench_api" "$MAT" blob $n 1 1 "$R" >"$T/api"
	o=$(awk '$1 == "draw" { print $3 }' "$T/api")
	b=0
	if [ -n "$BASE" ] && [ -x "$BASE/../test/bench_api" ]; then
		"$BASE/../test/bench_api" "$MAT" blob $n 1 1 "$R" >"$T/apib"
		b=$(awk '$1 == "draw" { print $3 }' "$T/apib")
	fi
	tgt=""
	[ $e = 24 ] && tgt=0.2
	row "frs_draw 2^$e, 1 thread" "$o" "$b" "$tgt"
done

echo
echo "OpenCL Sorted (PoCL, the CPU) against the CPU path, 2^20, -j 2"
if "$OURS/frs-sample" -q -i const -n 16 --device cl -o /dev/null 2>/dev/null; then
	"$OURS/frs-sample" -q -m "$MAT" -i blob -n 1048576 --device cl -v -o /dev/null 2>"$T/cl"
	"$OURS/frs-sample" -q -m "$MAT" -i blob -n 1048576 -j 2 -v -o /dev/null 2>"$T/cpu"
	sed -n 's/^frs-sample: OpenCL device [^:]*: /  device phases: /p' "$T/cl"
	clth=$(sed -n 's/.* thresholding \([0-9.]*\) s.*/\1/p' "$T/cl")
	cpth=$(sed -n 's/.* thresholding \([0-9.]*\) s.*/\1/p' "$T/cpu")
	clb=$(sed -n 's/.* build \([0-9.]*\) s.*/\1/p' "$T/cl")
	printf '%-40s %10.4f s, of which %.4f s program build\n' "OpenCL thresholding" "$clth" "$clb"
	printf '%-40s %10.4f s (OpenCL without the build: %.2fx the CPU time)\n' "CPU thresholding" "$cpth" \
	    "$(awk -v a="$clth" -v b="$clb" -v c="$cpth" 'BEGIN { print (c > 0) ? (a - b) / c : 0 }')"
	set -- $(med_both -q -m "$MAT" -i blob -n 1048576 --device cl -o /dev/null)
	o=$1 b=$2
	c=$(med "$OURS/frs-sample" -q -m "$MAT" -i blob -n 1048576 -j 2 -o /dev/null)
	row "process, --device cl" "$o" "$b" ""
	printf '%-40s %10.4f s (the OpenCL process: %.2fx the CPU one)\n' "process, CPU -j 2" "$c" "$(ratio "$o" "$c")"
else
	echo "  no OpenCL device"
fi

if [ -n "${FRS_AUTHORS:-}" ]; then
	echo
	echo "The thesis authors' Sorted sampler (FRS_AUTHORS), same matrix and map"
	for e in 20 24; do
		n=$((1 << e))
		: >"$T/runs"
		for _r in $(seq "$R"); do $FRS_AUTHORS $n >>"$T/runs"; done
		a=$(median_of "$T/runs")
		o=$(med "$OURS/frs-sample" -q -m "$MAT" -i blob -n $n -j 1 -o /dev/null)
		printf '%-40s %10.4f %10.4f %8s  (authors_s, ours faster by)\n' "2^$e, one thread" "$o" "$a" "$(ratio "$a" "$o")"
	done
fi
