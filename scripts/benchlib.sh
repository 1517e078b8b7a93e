# Helpers for the benchmark scripts (scripts/bench-*.sh); source it.
# Not named bench-*.sh, so that scripts/bench.sh does not run it.

now() { date +%s.%N; }

# bench_setup NAME PROG...: T a temporary directory (removed at exit) and
# NCPU the cores; the benchmark NAME stops when a PROG is missing.
bench_setup() {
	_bn=$1
	shift
	T=$(mktemp -d)
	trap 'rm -rf "$T"' EXIT
	NCPU=$(nproc)
	for _p in "$@"; do
		[ -x "$_p" ] || { echo "$_bn: $_p: missing"; exit 1; }
	done
}

# median_of FILE: the median of the numbers in FILE, one a line.
median_of() { sort -g "$1" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# ratio A B: A / B to two places, 0 when either is not positive.
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (a > 0 && b > 0) ? a / b : 0 }'; }

# timed OUT CMD...: run CMD once, standard output to OUT; seconds in SEC.
timed() {
	out=$1
	shift
	t0=$(now)
	"$@" >"$out"
	t1=$(now)
	SEC=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f", b - a }')
}


# uniform_frs FRS DDA MATRIX...: the targets of frd-gen(1) for uniform FRS
# (-i const -n 1024, no jitter): 10 sets, seeds 1 to 10, the matrices
# taken in turn; the exact spectrum for |k| <= 128 in 2-unit annuli.
# Prints "peak ring aniso_max aniso_mean rho": the highest radial mean at
# f >= 4, the highest at 1.5 times its frequency or beyond, the largest and
# the mean anisotropy (dB) over 4 <= f < 128, and the mean of dda
# --density's rho.  Dart throwing from ref-sample: 1.52 1.17 -8.5 -10.0 0.70.
uniform_frs() {
	_frs=$1 _dda=$2
	shift 2
	_u=$(mktemp -d)
	_s=1
	while [ $_s -le 10 ]; do
		_i=$(( (_s - 1) % $# + 1 ))
		eval "_m=\${$_i}"
		"$_frs" -q -m "$_m" -i const -n 1024 -S $_s -o "$_u/s$_s.pts"
		_s=$((_s + 1))
	done
	"$_dda" -q --fourier --size 128 --radial "$_u/rad" "$_u"/s*.pts >/dev/null
	for _f in "$_u"/s*.pts; do "$_dda" -q --density "$_f"; done |
	    awk -F '\t' '$1 == "mean" { s += $4; n++ } END { printf "%.3f\n", s / n }' \
	    >"$_u/rho"
	awk -F '\t' -v rf="$_u/rho" '
		BEGIN { getline rho < rf }
		NR > 1 && $1 >= 4 && $1 < 128 {
			n++; f[n] = $1; p[n] = $2
			if ($2 > pk) { pk = $2; pf = $1 }
			if (n == 1 || $3 > am) am = $3
			as += $3
		}
		END {
			for (i = 1; i <= n; i++) if (f[i] >= 1.5 * pf && p[i] > ring) ring = p[i]
			printf "%.2f %.2f %.1f %.1f %s\n", pk, ring, am, as / n, rho
		}' "$_u/rad"
	rm -rf "$_u"
}

# baseline_build COMMIT [VARIANT]: the programs of COMMIT (a commit, tag
# or branch of this repository), built once with its own Makefile from a
# git archive into build/base/HASH/ (VARIANT rel by default, the build
# make bench times of ours), and its bin directory printed.  Later calls, from
# any benchmark, reuse the build; a build that failed half-way is redone
# (the stamp comes last).  Notes and errors go to standard error.
baseline_build() {
	_bc=$1 _bv=${2:-rel}
	_btop=$(git rev-parse --show-toplevel 2>/dev/null ||
	    { cd "$(dirname "$0")/.." && pwd; })
	_bh=$(git -C "$_btop" rev-parse --short=12 "$_bc^{commit}") || {
		echo "baseline_build: $_bc: not a commit" >&2; return 1; }
	_bd=$_btop/build/base/$_bh
	if [ ! -e "$_bd/built-$_bv" ]; then
		echo "baseline_build: building $_bc ($_bh) in $_bd" >&2
		rm -rf "$_bd/src" && mkdir -p "$_bd/src" &&
		    git -C "$_btop" archive "$_bh" | tar -x -C "$_bd/src" || {
			echo "baseline_build: $_bc: git archive failed" >&2
			return 1
		}
		make -C "$_bd/src" -j"$(nproc)" VARIANT="$_bv" progs \
		    >"$_bd/build-$_bv.log" 2>&1 || {
			echo "baseline_build: $_bc: make failed; see" \
			    "$_bd/build-$_bv.log" >&2
			return 1
		}
		: >"$_bd/built-$_bv"
	fi
	echo "$_bd/src/build/$_bv/bin"
}

# pts_v1 IN OUT: OUT a copy of the point file IN, of pts(5) version 2
# without extra columns, as version 1 (the same bytes but the version),
# for a baseline from before version 2.
pts_v1() {
	cp "$1" "$2" &&
	    printf '\001' | dd of="$2" bs=1 seek=8 conv=notrunc 2>/dev/null
}

# bench_sizes: MAPS and NS (log2 of the counts) of the frs-sample and
# hsw-sample tables; fewer with BENCH_QUICK.
bench_sizes() {
	if [ -n "${BENCH_QUICK:-}" ]; then
		MAPS="blob"
		NS="0 16 24"
	else
		MAPS="const blob ramp sunset"
		NS="0 4 8 12 16 20 24"
	fi
}
