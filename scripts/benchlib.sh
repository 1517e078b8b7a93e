# Helpers for the benchmark scripts (scripts/bench-*.sh); source it.
# Not named bench-*.sh, so that scripts/bench.sh does not run it.

now() { date +%s.%N; }

# timed OUT CMD...: run CMD once, standard output to OUT; seconds in SEC.
timed() {
	out=$1
	shift
	t0=$(now)
	"$@" >"$out"
	t1=$(now)
	SEC=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f", b - a }')
}

