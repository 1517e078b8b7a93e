#!/bin/sh
# test/lib.sh's own promises, on scripts that source it: one that ends
# with done_testing passes; one that stops before it (an early exit 0)
# and one killed by TERM or INT stop there, say "not ok", exit non-zero
# and leave no scratch directory behind.
. "$(dirname "$0")/lib.sh"
LIB=$(cd "$(dirname "$0")" && pwd)/lib.sh

# run_script BODY: run a script that sources lib.sh and then BODY, with
# its own TMPDIR; its output in $T/s.out, its status in $rc.
run_script() {
	rm -rf "$T/tmp" && mkdir "$T/tmp"
	printf '. "%s"\n%s\n' "$LIB" "$1" >"$T/s.sh"
	TMPDIR=$T/tmp sh "$T/s.sh" >"$T/s.out" 2>&1
	rc=$?
}

run_script 'ok "one"
done_testing'
[ $rc -eq 0 ] && ! grep -q '^not ok' "$T/s.out" && [ -z "$(ls -A "$T/tmp")" ] &&
    ok "a script that reaches done_testing passes and cleans up" ||
    nok "done_testing: exit $rc, $(cat "$T/s.out"), left: $(ls -A "$T/tmp")"

run_script 'ok "one"
exit 0
ok "two"
done_testing'
[ $rc -eq 1 ] && grep -q '^not ok - the script stopped before its end' "$T/s.out" &&
    ! grep -q 'ok - two' "$T/s.out" && [ -z "$(ls -A "$T/tmp")" ] &&
    ok "an early exit 0 is a failure" ||
    nok "early exit: exit $rc, $(cat "$T/s.out")"

for sig in TERM INT; do
	run_script "ok \"one\"
kill -$sig \$\$
ok \"after the signal\"
done_testing"
	[ $rc -ne 0 ] && ! grep -q 'after the signal' "$T/s.out" &&
	    grep -q '^not ok' "$T/s.out" && [ -z "$(ls -A "$T/tmp")" ] &&
	    ok "SIG$sig stops the script, a failure, nothing left" ||
	    nok "SIG$sig: exit $rc, $(cat "$T/s.out"), left: $(ls -A "$T/tmp")"
done
done_testing
