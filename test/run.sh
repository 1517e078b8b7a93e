#!/bin/sh
# Run every test: the cmocka binaries in BUILD/test and the shell tests
# test/t_*.sh (against the programs in BUILD/bin), plus the man page lint.
# The last line is "N passed, N failed"; the exit status is 0 only when
# nothing failed.
#   test/run.sh BUILD [NAME...]   NAME: test_x or t_x to run only those
set -u
build=${1:?usage: test/run.sh BUILD [NAME...]}
shift
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top" || exit 1
logs=$build/test-logs
mkdir -p "$logs"
export BIN="$top/$build/bin"
# Sanitizer settings: fail hard, and keep LeakSanitizer on.
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=0:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# The OpenCL runtime leaks inside itself; those leaks are not ours.
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$top/test/lsan.supp}"
# LeakSanitizer's tracer has been seen to crash while PoCL's threads still
# run at exit.  That is not a leak: processes that use OpenCL run again
# when it happens (the *cl tests below, test/lib.sh's cl_run), and only
# whole experiment scripts run without the leak check (nolsan).
export FRS_CL_ASAN="$ASAN_OPTIONS:detect_leaks=0"

pass=0
fail=0
failed=""

# Two tests at a time (FRS_TEST_JOBS; 1: one after another): each runs as
# this script on its own name, its lines kept in LOGS/NAME.res and shown
# when it ends; the sums come from their last lines.
jobs=${FRS_TEST_JOBS:-2}
if [ -z "${FRS_TEST_CHILD:-}" ] && [ "$jobs" -gt 1 ]; then
	names=""
	for t in "$build"/test/test_* "$build"/fuzz/replay_*; do
		case $t in *.o|*.d) continue ;; esac
		[ -x "$t" ] && names="$names $(basename "$t")"
	done
	for t in test/t_*.sh test/hard/t_*.sh; do
		[ -f "$t" ] && names="$names $(basename "$t" .sh)"
	done
	names="$names lint-man"
	if [ $# -gt 0 ]; then
		keep=""
		for n in $names; do
			for w in "$@"; do [ "$w" = "$n" ] && keep="$keep $n"; done
		done
		names=$keep
	fi
	export FRS_TEST_CHILD=1
	# The slow ones first, so that they do not end the run alone.
	for n in t_experiments t_frs-sample test_api3 test_api_exact t_faults; do
		case " $names " in *" $n "*)
			names="$n $(echo " $names " | sed "s/ $n / /")" ;;
		esac
	done
	echo $names | tr ' ' '\n' | xargs -P "$jobs" -I{} sh -c \
	    'sh test/run.sh "$0" "$1" >"$2/$1.res" 2>&1; sed "\$d" "$2/$1.res"' \
	    "$build" {} "$logs"
	for n in $names; do
		last=$(tail -n 1 "$logs/$n.res")
		p=${last%% passed*}
		f=${last#*passed, }
		f=${f%% failed*}
		case $p$f in *[!0-9]*|"") p=0 f=1 ;; esac
		pass=$((pass + p))
		fail=$((fail + f))
		[ "$f" -ne 0 ] && failed="$failed $n"
	done
	[ -n "$failed" ] && echo "failed:$failed"
	echo "$pass passed, $fail failed"
	[ "$fail" -eq 0 ]
	exit
fi

want() {
	[ -z "$sel" ] && return 0
	for w in $sel; do [ "$w" = "$1" ] && return 0; done
	return 1
}
sel="$*"

# cmocka prints "[  PASSED  ] N test(s)." and "[  FAILED  ] N test(s)".
run_cmocka() {
	name=$(basename "$1")
	log=$logs/$name.log
	# One PoCL kernel cache per test binary, shared by its runs.
	POCL_CACHE_DIR="$top/$build/pocl-cache/$name" && mkdir -p "$POCL_CACHE_DIR"
	export POCL_CACHE_DIR
	for try in 1 2 3; do
		"$1" >"$log" 2>&1
		rc=$?
		grep -q 'LeakSanitizer has encountered a fatal error' "$log" ||
		    break
	done
	p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
	f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
	p=${p:-0}
	f=${f:-0}
	if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
		f=1	# crashed or a sanitizer stopped it
	fi
	pass=$((pass + p))
	fail=$((fail + f))
	if [ "$f" -ne 0 ]; then
		failed="$failed $name"
		echo "FAIL $name ($p passed, $f failed; log $log)"
		grep -E '^\[  (ERROR|FAILED)|ERROR|runtime error|Sanitizer' "$log" |
		    head -n 20
	else
		echo "ok   $name ($p)"
	fi
}

# Shell tests print "ok - what" and "not ok - what" lines (test/lib.sh;
# one "not ok" more when a script stops before its done_testing).
run_shell() {
	name=$(basename "$1" .sh)
	log=$logs/$name.log
	POCL_CACHE_DIR="$top/$build/pocl-cache/$name" && mkdir -p "$POCL_CACHE_DIR"
	export POCL_CACHE_DIR
	sh "$1" >"$log" 2>&1
	rc=$?
	p=$(grep -c '^ok ' "$log")
	f=$(grep -c '^not ok ' "$log")
	if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
		f=1
		echo "not ok - $name exited with status $rc" >>"$log"
	fi
	pass=$((pass + p))
	fail=$((fail + f))
	if [ "$f" -ne 0 ]; then
		failed="$failed $name"
		echo "FAIL $name ($p passed, $f failed; log $log)"
		grep -A3 '^not ok' "$log" | head -n 30
	else
		echo "ok   $name ($p)"
	fi
}

for t in "$build"/test/test_*; do
	case $t in *.o|*.d) continue ;; esac
	[ -x "$t" ] || continue
	want "$(basename "$t")" && run_cmocka "$t"
done
for t in test/t_*.sh test/hard/t_*.sh; do
	[ -f "$t" ] || continue
	want "$(basename "$t" .sh)" && run_shell "$t"
done

# The libFuzzer targets (test/fuzz/fuzz_*.c) replayed without libFuzzer on
# their seed corpus and any saved crashes: one pass per target.
for t in "$build"/fuzz/replay_*; do
	case $t in *.o|*.d) continue ;; esac
	[ -x "$t" ] || continue
	name=$(basename "$t")
	target=${name#replay_}
	want "$name" || continue
	log=$logs/$name.log
	set -- "test/fuzz/corpus/$target"
	[ -d "test/fuzz/crashes/$target" ] && set -- "$@" "test/fuzz/crashes/$target"
	# A parser must not ask for more than 1 GiB on these small inputs
	# (a damaged header once made frp_read ask for 5 GiB).
	ASAN_OPTIONS="$ASAN_OPTIONS:max_allocation_size_mb=1024:allocator_may_return_null=0" \
	    "$t" "$@" >"$log" 2>&1
	rc=$?
	if [ "$rc" -eq 0 ] && ! grep -qE 'runtime error|Sanitizer' "$log"; then
		pass=$((pass + 1))
		echo "ok   $name ($(tail -n 1 "$log"))"
	else
		fail=$((fail + 1))
		failed="$failed $name"
		echo "FAIL $name (status $rc; log $log)"
		grep -E 'ERROR|runtime error|Sanitizer' "$log" | head -n 20
	fi
done

if want lint-man; then
	if command -v mandoc >/dev/null 2>&1; then
		out=$(mandoc -Tlint -Wwarning man/man*/*.[0-9] 2>&1)
		if [ -z "$out" ]; then
			pass=$((pass + 1))
			echo "ok   lint-man"
		else
			fail=$((fail + 1))
			failed="$failed lint-man"
			echo "FAIL lint-man"
			echo "$out" | head -n 20
		fi
	else
		fail=$((fail + 1))
		echo "FAIL lint-man (mandoc missing: run scripts/deps.sh)"
	fi
fi

# A child's names of failed tests: the parent lists them all at the end.
[ -n "$failed" ] && [ -z "${FRS_TEST_CHILD:-}" ] && echo "failed:$failed"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
