#!/bin/sh
# The build users get (issue 34): the programs of make (and make install,
# BUILD, -O3 with the FRS_WIDE loops cloned for AVX2 and AVX-512 and
# picked at run time) against the bench build beside it (build/bench,
# -O3 -march=native) and against the make build of the commit this work
# started from (BENCH_BUILD_BASE, 807ddb5), in one run, interleaved:
# whole processes, blob 128x128, one thread, binary points to /dev/null,
# medians of R runs.  Then the costs the issue bounds: jitter (random,
# Halton) against none at 2^24, and HSW against FRS at 2^24.
# BENCH_QUICK=1: fewer runs.
set -eu
. "$(dirname "$0")/benchlib.sh"
BUILD=${1:-build/rel}
OURS=$BUILD/bin
WIDE=${BENCH_WIDE:-build/bench/bin}	# the -march=native build
BASE_COMMIT=${BENCH_BUILD_BASE:-807ddb5}
bench_setup bench-build "$OURS/frs-sample" "$OURS/hsw-sample"
if [ -n "${BENCH_QUICK:-}" ]; then R=3; else R=5; fi
[ -x "$WIDE/frs-sample" ] || WIDE=""
BASE=$(baseline_build $BASE_COMMIT rel) || BASE=""

# one FILE PROG ARGS...: one run's seconds, appended to FILE.
one() {
	_f=$1
	shift
	timed /dev/null "$@" -o /dev/null
	echo "$SEC" >>"$_f"
}
verdict() { awk -v v="$1" -v t="$2" 'BEGIN { print (v > 0 && v <= t) ? "met" : "missed" }'; }

# three PROG ARGS...: "OURS WIDE BASE", the medians of R interleaved runs
# of the three builds (0 for one that is missing).
three() {
	: >"$T/o"; : >"$T/w"; : >"$T/b"
	for _r in $(seq $R); do
		one "$T/o" "$OURS/$@"
		[ -z "$WIDE" ] || one "$T/w" "$WIDE/$@"
		[ -z "$BASE" ] || one "$T/b" "$BASE/$@"
	done
	for _x in w b; do [ -s "$T/$_x" ] || echo 0 >"$T/$_x"; done
	echo "$(median_of "$T/o") $(median_of "$T/w") $(median_of "$T/b")"
}

echo "The make build ($OURS) against -march=native ($WIDE) and the make build"
echo "of $BASE_COMMIT (the start of issue 34); whole processes, blob 128x128, -j 1,"
echo "to /dev/null, medians of $R runs interleaved; load average $(cut -d' ' -f1-3 /proc/loadavg)"
[ -n "$BASE" ] || echo "(the baseline could not be built: its column is 0)"
[ -n "$WIDE" ] || echo "(no build/bench: make bench builds it; its column is 0)"
printf '%-44s %8s %8s %8s %8s %7s %8s\n' command make_s native_s base_s \
    make/nat target speedup
N=16777216
A="-q -i blob -s 128x128 -j 1 -n $N"
for c in "hsw-sample $A" "frs-sample $A" \
    "frs-sample $A --sigma 4 --jitter random" \
    "frs-sample $A --sigma 4 --jitter halton" "frs-sample $A --sigma 4"; do
	# shellcheck disable=SC2086
	set -- $(three $c)
	o=$1 w=$2 b=$3
	r=$(ratio "$o" "$w")
	printf '%-44s %8.3f %8.3f %8.3f %8s %7s %8s\n' \
	    "$(echo "$c" | sed "s/ $A/ 2^24/; s/-q -i blob.*-n $N/2^24/")" \
	    "$o" "$w" "$b" "$r" "1.10 $(verdict "$r" 1.10)" "$(ratio "$b" "$o")"
	case $c in
	"hsw-sample $A") hsw=$o ;;
	"frs-sample $A") frs=$o ;;
	*random) jr=$o ;;
	*halton) jh=$o ;;
	*) j0=$o ;;
	esac
done
echo
printf '%-44s %8s %8s %7s\n' "cost (make build, 2^24, -j 1)" ratio target verdict
row() { printf '%-44s %8s %8s %7s\n' "$1" "$2" "$3" "$(verdict "$2" "$3")"; }
row "jitter random / none (--sigma 4)" "$(ratio "$jr" "$j0")" 2
row "jitter halton / none (--sigma 4)" "$(ratio "$jh" "$j0")" 2
row "hsw-sample / frs-sample" "$(ratio "$hsw" "$frs")" 2

# What the target leaves HSW: each level of the descent keeps two
# correctly rounded quotients, so code making the same points spends at
# least 2 L n divisions at the divider's rate (test/bench/divrate); the
# rest (input, the descent's loads, placing, output) must fit in what
# 2 x frs-sample leaves.  Its other work alone is hsw-sample on a 1x1
# map (no level).
DIV=$(dirname "$OURS")/test/divrate
if [ -x "$DIV" ]; then
	d=$("$DIV" | awk '{ print $2 }')
	: >"$T/h0"
	for _r in $(seq $R); do
		one "$T/h0" "$OURS/hsw-sample" -q -i blob -s 1x1 -j 1 -n $N
	done
	L=7	# levels of the 128x128 quadtree
	echo
	awk -v d="$d" -v l=$L -v n=$N -v f="$frs" \
	    -v o="$(median_of "$T/h0")" 'BEGIN {
		dv = 2 * l * n * d * 1e-9; left = 2 * f - dv
		printf "HSW at 2^24: its divisions alone (2 x %d x 2^24 at %.3f ns, the divider'"'"'s\n", l, d
		printf "rate) take %.3f s, %.2f x frs-sample; the target 2 leaves %.3f s beside them,\n", dv, dv / f, left
		printf "and the work outside the descent (a 1x1 map) alone takes %.3f s: ", o
		if (left <= 0)
			print "out of reach\nwithout changing the points"
		else if (o > left)
			printf "out of reach\nunless it hides behind the divider or gets %.1f times faster\n", o / left
		else
			print "within reach"
	}'
fi

echo
echo "Shuffled tiles on the HDR maps of data/ (--equirect, n = 262144, -j 1):"
echo "whole processes against plain tiles, medians of $R runs (make build; base: $BASE_COMMIT's)"
printf '%-44s %8s %8s %8s %8s %7s %8s\n' map shuf_s plain_s base_s shuf/pl \
    target speedup
for m in forest sunset interior; do
	A2="-q -i data/$m.exr --equirect -n 262144 -j 1"
	# shellcheck disable=SC2086
	set -- $(three frs-sample $A2 --tiles shuffled)
	o=$1 b=$3
	# shellcheck disable=SC2086
	set -- $(three frs-sample $A2 --tiles plain)
	p=$1
	r=$(ratio "$o" "$p")
	printf '%-44s %8.3f %8.3f %8.3f %8s %7s %8s\n' "$m shuffled" "$o" "$p" \
	    "$b" "$r" "1 $(verdict "$r" 1)" "$(ratio "$b" "$o")"
done
