# Helpers for the shell tests; source it.  Each check prints "ok - what"
# or "not ok - what"; test/run.sh counts them.  Every script ends with
# done_testing: one that exits before it (an early exit, a stray exit 0,
# a failed command under set -e) would lose its later checks unseen, so
# then the exit prints one more "not ok" and the status is 1.
set -u
: "${BIN:?BIN must name the directory of the programs}"
PATH="$BIN:$PATH"
# The repository's data (test/run.sh runs every test from the top).
TD=$PWD/data
T=$(mktemp -d "${TMPDIR:-/tmp}/frs-test.XXXXXX")
reached_end=0
at_exit() {
	rm -rf "$T"
	if [ "$reached_end" -eq 0 ]; then
		echo "not ok - the script stopped before its end (done_testing)"
		exit 1
	fi
}
trap at_exit EXIT
# Interrupted: stop here (the EXIT trap cleans up and reports it).
trap 'exit 130' INT
trap 'exit 143' TERM

ok() { echo "ok - $*"; }

# man_example PAGE ERE: the literal block (.Bd -literal ... .Ed) of the
# man page PAGE that has a line matching ERE, as a shell script (roff's
# \e back to a backslash); nothing when no block has one.
man_example() {
	awk -v re="$2" '/^\.Bd -literal/ { n = 0; on = 1; next }
	    /^\.Ed/ { if (hit) exit; on = 0; next }
	    on { l[n++] = $0; if ($0 ~ re) hit = 1 }
	    END { if (hit) for (i = 0; i < n; i++) { gsub(/\\e/, "\\", l[i]); print l[i] } }' "$1"
}

# done_testing: the last line of every test script.
done_testing() { reached_end=1; }

# skip_all WHY: the script cannot run here (a tool missing): one skipped
# check, and the script ends.
skip_all() {
	ok "# SKIP $*"
	reached_end=1
	exit 0
}

# nolsan CMD...: run CMD without LeakSanitizer's exit check: for whole
# experiment scripts, whose many OpenCL processes make a tracer crash (see
# cl_run) likely; cl_run covers the same code with the check on.
nolsan() {
	ASAN_OPTIONS=${FRS_CL_ASAN:-${ASAN_OPTIONS:-}} "$@"
}

# cl_run CMD...: run CMD, which uses OpenCL, with LeakSanitizer on.  Its
# tracer has been seen to crash on PoCL's threads at exit ("LeakSanitizer
# has encountered a fatal error"), which is not a leak: then CMD runs
# again, up to three times.  Output is kept until the last run, so that
# a retry does not write twice; CMD must not read standard input.
cl_run() {
	for try in 1 2 3; do
		"$@" >"$T/cl_run.out" 2>"$T/cl_run.err" </dev/null
		rc=$?
		grep -q 'LeakSanitizer has encountered a fatal error' \
		    "$T/cl_run.err" || break
	done
	cat "$T/cl_run.out"
	cat "$T/cl_run.err" >&2
	return "$rc"
}
nok() { echo "not ok - $*"; }

# check WHAT CMD...: CMD succeeds.
check() {
	what=$1
	shift
	if "$@" >"$T/out" 2>"$T/err"; then
		ok "$what"
	else
		nok "$what"
		echo "# command: $*"
		sed 's/^/# /' "$T/err" | head -n 10
	fi
}

# expect_fail WHAT STATUS PATTERN OUTFILE CMD...: CMD exits with STATUS,
# its standard error contains PATTERN (fixed string), and OUTFILE (may be
# "-" for none) does not exist afterwards, nor any temporary beside it.
expect_fail() {
	what=$1 status=$2 pattern=$3 outfile=$4
	shift 4
	"$@" >"$T/out" 2>"$T/err"
	rc=$?
	why=""
	[ "$rc" -eq "$status" ] || why="exit status $rc, expected $status"
	grep -qF -- "$pattern" "$T/err" || why="$why; stderr lacks '$pattern'"
	# A leak or sanitizer report on the way out also exits 1: not a pass.
	grep -qE 'Sanitizer|runtime error' "$T/err" &&
	    why="$why; a sanitizer report"
	if [ "$outfile" != "-" ]; then
		[ -e "$outfile" ] && why="$why; $outfile was left behind"
		d=$(dirname "$outfile")
		if [ -d "$d" ] && ls "$d" | grep -q '\.tmp\.'; then
			why="$why; a temporary file was left in $d"
		fi
	fi
	if [ -z "$why" ]; then
		ok "$what"
	else
		nok "$what: $why"
		echo "# command: $*"
		sed 's/^/# stderr: /' "$T/err" | head -n 5
	fi
}

# value KEY FILE: the value of "KEY value" lines (imap info output).
value() {
	awk -v k="$1" '$1 == k { print $2 }' "$2"
}

# near A B TOL: |A - B| <= TOL * max(1, |B|)
near() {
	awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN {
		d = a - b; if (d < 0) d = -d
		m = b < 0 ? -b : b; if (m < 1) m = 1
		exit !(d <= t * m) }'
}
