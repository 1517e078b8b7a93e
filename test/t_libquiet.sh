#!/bin/sh
# The library prints nothing: a program on the public API alone
# (test/user_mapload.c, linked with libfrs.a) loading a procedural map
# large enough for the programs' progress bar, on a terminal (script(1)
# gives it one).  The programs keep their bar there, and -q still hides it.
. "$(dirname "$0")/lib.sh"

USER_PROG="$BIN/../test/user_mapload"
# About 3 s in the sanitizer build, well past the bar's first second.
SIZE_W=4096 SIZE_H=2048

if ! command -v script >/dev/null 2>&1; then
	skip_all "script(1) missing: no terminal to run on"
fi

# on_tty FILE CMD: run CMD (one shell word list) on a pseudo-terminal,
# everything it writes there into FILE.
on_tty() {
	out=$1
	shift
	script -qec "$*" /dev/null </dev/null >"$out" 2>&1
}

if on_tty "$T/lib.out" "$USER_PROG aniso $SIZE_W $SIZE_H"; then
	if [ -s "$T/lib.out" ]; then
		nok "frs_map_load on a terminal prints nothing"
		tr '\r' '\n' <"$T/lib.out" | tail -n 3 | sed 's/^/# /'
	else
		ok "frs_map_load on a terminal prints nothing"
	fi
else
	nok "user_mapload aniso ${SIZE_W}x$SIZE_H runs"
	sed 's/^/# /' "$T/lib.out" | head -n 5
fi

# The programs: the same bar as ever on a terminal, nothing with -q.
on_tty "$T/imap.out" "imap gen -j 1 -s ${SIZE_W}x$SIZE_H -o $T/a.exr aniso"
tr '\r' '\n' <"$T/imap.out" >"$T/imap.lines"
grep -q '^imap: aniso \[#* *\] *[0-9.]*% .*/s ETA [0-9:-]* $' "$T/imap.lines" &&
    grep -q '^imap: aniso \[#\{30\}\] 100\.0% .*ETA 00:00 $' "$T/imap.lines" &&
    ok "imap gen on a terminal: its progress bar" ||
    { nok "imap gen on a terminal: its progress bar"
    tail -n 3 "$T/imap.lines" | sed 's/^/# /'; }
on_tty "$T/imapq.out" "imap gen -q -j 1 -s ${SIZE_W}x$SIZE_H -o $T/b.exr aniso"
[ -s "$T/b.exr" ] && [ ! -s "$T/imapq.out" ] &&
    ok "imap gen -q on a terminal: no bar" ||
    nok "imap gen -q on a terminal: no bar"
done_testing
