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
# A procedural map spec given with -i (mc-error: --env) that does not
# parse (a value out of its range, an unknown parameter, no parameters
# after the colon, a ramp3 axis that is not 0, 1 or 2) is a usage error:
# exit 2, the spec and its problem named, nothing written.  A bad map
# file stays an input error: exit 1.  Every program that takes a map,
# each with what it needs.
awk 'BEGIN { srand(5); for (i = 0; i < 200; i++) printf "%.17g %.17g\n", rand(), rand() }' \
    >"$T/X.txt"
frd-gen -s 64 -o "$T/m.frd" 2>/dev/null
head -c 2000 "$TD/sunset.exr" >"$T/cut.exr"
# with_map PROG...: the program's command line with @ for the map.
with_map() {
	case $1 in
	frs-sample) echo "frs-sample -i @ -n 100 -o $T/o.pts" ;;
	hsw-sample) echo "hsw-sample -i @ -n 100 -o $T/o.pts" ;;
	ref-sample) echo "ref-sample -k relaxed-dart -i @ -n 100 -o $T/o.pts" ;;
	pts-render) echo "pts-render -i @ $T/X.txt -o $T/o.png" ;;
	dda) echo "dda --dda -i @ $T/X.txt -o $T/o.txt" ;;
	frd-prep) echo "frd-prep --for 100 -i @ $T/m.frd -o $T/o.txt" ;;
	mc-error) echo "mc-error -f env --env @ $T/X.txt -o $T/o.txt" ;;
	esac
}
for p in frs-sample hsw-sample ref-sample pts-render dda frd-prep mc-error; do
	cmd=$(with_map "$p")
	for spec in const:-1 blob:sigma=-1 blob:radius=3 blob:; do
		# shellcheck disable=SC2046
		expect_fail "$p -i $spec: a usage error" 2 "$p: $spec: " "${cmd##* }" \
		    $(echo "$cmd" | sed "s|@|$spec|")
	done
	for f in "$T/nothere.exr" "$T/cut.exr"; do
		# shellcheck disable=SC2046
		expect_fail "$p -i ${f##*/}: an input error" 1 "$p: $f" "${cmd##* }" \
		    $(echo "$cmd" | sed "s|@|$f|")
	done
done
for spec in blob3:sigma=-1 blob3:q=1 ramp3:axis=1.5; do
	expect_fail "frs-sample -i $spec (3-D): a usage error" 2 "frs-sample: $spec: " \
	    "$T/o.pts" frs-sample -i "$spec" -n 100 -o "$T/o.pts"
done

done_testing
