#!/bin/sh
# The option handling every program shares (src/cli/cli.c): an empty
# output name, getopt's messages, the program's name in them.
. "$(dirname "$0")/lib.sh"

progs="dda discrepancy frd-gen frd-prep frs-sample hsw-sample imap mc-error
    pts-render ref-sample"

# -o '': a usage error naming the option, nothing written.
mkdir "$T/d"
for p in $progs; do
	case $p in
	imap) args="gen const" ;;
	*) args="" ;;
	esac
	# shellcheck disable=SC2086
	(cd "$T/d" && $p $args -o '' x) >"$T/out" 2>"$T/err"
	rc=$?
	if [ $rc -eq 2 ] && grep -qF "$p: -o: an empty file name" "$T/err" &&
	    [ -z "$(ls -A "$T/d")" ]; then
		ok "$p -o '': a usage error"
	else
		nok "$p -o '': exit $rc, $(head -n 1 "$T/err"), left: $(ls -A "$T/d")"
	fi
done
for o in --png --radial; do
	expect_fail "dda $o ''" 2 "dda: $o: an empty file name" - dda "$o" '' x.pts
done

# An unknown option, a missing argument: getopt's message names the
# program, not the path it was run by.
for p in $progs; do
	case $p in
	imap) args="info" ;;
	*) args="" ;;
	esac
	# shellcheck disable=SC2086
	"$BIN/$p" $args --no-such-option >"$T/out" 2>"$T/err"
	rc=$?
	first=$(head -n 1 "$T/err")
	[ $rc -eq 2 ] && [ "$first" = "$p: unrecognized option '--no-such-option'" ] &&
	    ! grep -qF "$BIN" "$T/err" &&
	    ok "$p --no-such-option: the program's name" ||
	    nok "$p --no-such-option: exit $rc, $first"
done
"$BIN/frs-sample" -n >"$T/out" 2>"$T/err"
[ "$(head -n 1 "$T/err")" = "frs-sample: option requires an argument -- 'n'" ] &&
    ok "a missing argument: the program's name" ||
    nok "a missing argument: $(head -n 1 "$T/err")"
done_testing
