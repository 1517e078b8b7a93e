#!/bin/sh
# Faults, for every program and every kind of output it writes: SIGINT
# and SIGTERM during a long run, a full disk, a closed standard output.
# Each check is one row of a table below.
. "$(dirname "$0")/lib.sh"

D=$(dirname "$0")/../data
M=$D/default.frd	# 2048x2048
# OpenCL runs without the leak check (see test/run.sh).
CL="env ASAN_OPTIONS=${FRS_CL_ASAN:-${ASAN_OPTIONS:-}}"
ref-sample -k random -n 1000000 -q -o "$T/a.pts"
ref-sample -k random -n 20000 -q -o "$T/r.pts"
ref-sample -k random -n 256 -q -o "$T/s.pts"
imap gen blob -s 64x64 -o "$T/blob.png"
# frd-gen -j 1: its spinning threads crawl on a machine that is busy.
frd-gen -j 1 -s 64 -o "$T/m.frd"

# insane FILE: FILE holds a sanitizer report.
insane() {
	grep -qE 'Sanitizer|runtime error' "$1"
}

# verdict WHAT ERR WHY: ok WHAT when WHY (what went wrong, "; ..." each)
# is empty and ERR (its standard error) holds no sanitizer report, else
# not ok with the reasons and the first lines of ERR.
verdict() {
	set -- "$1" "$2" "$3$(insane "$2" && echo "; sanitizer report")"
	if [ -z "$3" ]; then
		ok "$1"
	else
		nok "$1$3"
		sed 's/^/# stderr: /' "$2" | head -n 5
	fi
}

# alive PID: the process runs (a zombie does not).
alive() {
	kill -0 "$1" 2>/dev/null &&
	    ! grep -qs '^State:[[:space:]]*Z' "/proc/$1/status"
}

# ---- 1. SIGINT and SIGTERM -------------------------------------------
#
# Rows "WATCH COMMAND": COMMAND writes its result to $S/out, or to
# standard output, and runs for seconds.  The signal comes once
# $S/WATCH.tmp.* exists (WATCH "-": no temporary is open early, as in
# discrepancy and on standard output; then after 0.4 s).  Standard
# output is a pipe nobody reads, so a program that writes much of it
# blocks and cannot finish before the signal.  Before a SIGTERM run
# $S/out holds old bytes, which must stay; after a SIGINT run $S/out
# must not exist; either way nothing else may be left in $S.  KEEP=NAME
# lets $S/NAME stay (a complete checkpoint).
sig_rows='
out   imap gen ramp -s 3000x3000 --format exr -o $S/out
out   imap gen ramp -s 3000x3000 --format png -o $S/out
out   imap convert -s 3000x3000 --format exr $T/blob.png $S/out
out   imap convert -s 3000x3000 --format png -o $S/out $T/blob.png
-     imap gen ramp -s 3000x3000 --format exr
-     imap info -s 4000x4000 sky
out   frd-gen -s 256 -o $S/out
-     frd-gen -s 256
out   $CL frd-gen --device cl -s 256 -o $S/out
out   frd-prep -a all -o $S/out $M
-     frd-prep -a all $M
out   frs-sample -q -m $T/m.frd -i blob -n 100000 --sets 200 -o $S/out
out   frs-sample -q -m $T/m.frd -i blob -n 100000 --sets 200 -T -o $S/out
out   frs-sample -q -m $T/m.frd -i blob -n 100000 --sets 200 --count-only -o $S/out
-     frs-sample -q -m $T/m.frd -i blob -n 100000 --sets 200
out   $CL frs-sample --device cl -q -m $T/m.frd -i blob -n 100000 --sets 200 -o $S/out
out   pts-render -s 4000 --format png -o $S/out $T/a.pts
out   pts-render -s 4000 --format pnm -o $S/out $T/a.pts
-     pts-render -s 4000 $T/a.pts
out   ref-sample -k random -n 100000 --sets 100 -o $S/out
out   ref-sample -k random -n 100000 --sets 100 -T -o $S/out
-     ref-sample -k random -n 100000 --sets 100
out   hsw-sample -i blob -n 2000000 -o $S/out
out   hsw-sample -i blob -n 2000000 -T -o $S/out
-     hsw-sample -i blob -n 2000000 -T
out   $CL hsw-sample --device cl -i blob -n 2000000 -T -o $S/out
-     discrepancy -c half -o $S/out $T/r.pts
-     discrepancy -c half $T/r.pts
out   dda --rdf -o $S/out $T/a.pts
out   dda --density -o $S/out $T/a.pts
p.png dda --size 700 --approx --png $S/p.png -o $S/out $T/s.pts
rad   dda --size 700 --approx --bin 0.0001 --radial $S/rad -o $S/out $T/s.pts
-     dda --rdf $T/a.pts
'

# A background job of a script ignores SIGINT, and outfile.c keeps a
# signal that was ignored ignored: env(1) gives it back its default.
if env --default-signal=INT true 2>/dev/null; then
	sigs="INT TERM"
	dfl="env --default-signal=INT,TERM"
else
	sigs=TERM
	dfl=env
	echo "# env has no --default-signal: SIGINT not tested"
fi

# interrupt SIG WATCH COMMAND: one run, as described above.
interrupt() {
	sig=$1 watch=$2 cmd=$3
	S=$T/sig.$sig
	rm -rf "$S" && mkdir "$S" || return
	[ "$sig" = TERM ] && echo "old bytes" >"$S/out"
	rm -f "$T/fifo.$sig" && mkfifo "$T/fifo.$sig" || return
	exec 5<>"$T/fifo.$sig"	# the reader that never reads
	eval "exec $dfl $cmd" >"$T/fifo.$sig" 2>"$T/err.$sig" &
	pid=$!
	seen="" i=0
	# Wait for the temporary (at most about 20 s), or 0.4 s for "-".
	[ "$watch" = - ] && sleep 0.4
	while [ "$watch" != - ] && alive $pid && [ $i -lt 2000 ]; do
		if ls "$S" | grep -q "^$watch\.tmp\."; then
			seen=1
			break
		fi
		sleep 0.01
		i=$((i + 1))
	done
	kill -s "$sig" $pid 2>/dev/null
	i=0
	while alive $pid && [ $i -lt 100 ]; do
		sleep 0.05
		i=$((i + 1))
	done
	alive $pid && kill -s KILL $pid 2>/dev/null
	wait $pid 2>/dev/null
	rc=$?
	exec 5<&-
	why=""
	[ "$watch" = - ] || [ -n "$seen" ] ||
	    why="; $watch.tmp.* never appeared (the run is too short?)"
	[ $i -lt 100 ] || why="$why; still running 5 s after SIG$sig"
	case $sig in INT) want=130 ;; *) want=143 ;; esac
	[ $rc -eq $want ] ||
	    why="$why; exit status $rc, not death by SIG$sig"
	left=$(ls -A "$S" | grep -vx -e out -e "${KEEP:-/}" | tr '\n' ' ')
	[ -z "$left" ] || why="$why; left in the directory: $left"
	if [ "$sig" = TERM ]; then
		[ "$(cat "$S/out" 2>/dev/null)" = "old bytes" ] ||
		    why="$why; the old $S/out was changed"
	elif [ -e "$S/out" ]; then
		why="$why; $S/out was created"
	fi
	verdict "SIG$sig: $cmd" "$T/err.$sig" "$why"
}

# SIGINT and SIGTERM runs of a row at the same time, in their own
# directories; their reports in order.
interrupt_both() {
	for sig in $sigs; do
		interrupt "$sig" "$@" >"$T/log.$sig" &
	done
	wait
	for sig in $sigs; do cat "$T/log.$sig"; done
}

echo "$sig_rows" | while read -r watch cmd; do
	[ -n "$watch" ] && interrupt_both "$watch" "$cmd"
done
# --checkpoint: the last complete checkpoint stays, no temporary.  (Each
# is written in milliseconds, too short a time to aim at.)
KEEP=ck interrupt_both - \
    'frd-gen -s 512 --checkpoint $S/ck --checkpoint-every 0 -o $S/out'

# ---- 2. A full disk --------------------------------------------------
#
# Rows are commands.  One that names /dev/full writes that file; the
# others write standard output, which is /dev/full.  Expected: status 1,
# a message naming the file (or standard output) and "No space left on
# device", nothing left in $T/full (where other outputs go).
full_rows='
imap gen blob --format exr -o /dev/full
imap gen blob --format png -o /dev/full
imap convert --format exr $T/blob.png /dev/full
imap convert --format png -o /dev/full $T/blob.png
imap gen blob --format exr
imap gen blob --format png
imap info blob
imap --help
frd-gen -j 1 -s 16 -o /dev/full
frd-gen -j 1 -s 16
frd-gen --quality $T/m.frd
$CL frd-gen --device cl -s 16 -o /dev/full
frd-prep -a all -o /dev/full $T/m.frd
frd-prep $T/m.frd
frs-sample -n 10 -o /dev/full
frs-sample -n 10 -T -o /dev/full
frs-sample -n 10 --count-only -o /dev/full
frs-sample -n 10
frs-sample -n 10 --count-only
$CL frs-sample --device cl -n 10 -o /dev/full
pts-render -s 64 --format png -o /dev/full $T/s.pts
pts-render -s 64 --format pnm -o /dev/full $T/s.pts
pts-render -s 64 $T/s.pts
ref-sample -n 10 -o /dev/full
ref-sample -n 10 -T -o /dev/full
ref-sample -n 10
hsw-sample -i blob -n 10 -o /dev/full
hsw-sample -i blob -n 10 -T -o /dev/full
hsw-sample -i blob -n 10
$CL hsw-sample --device cl -i blob -n 10 -o /dev/full
discrepancy -o /dev/full $T/s.pts
discrepancy $T/s.pts
mc-error -o /dev/full $T/s.pts
mc-error $T/s.pts
dda --size 10 -o /dev/full $T/s.pts
dda --size 10 --png /dev/full -o $T/full/out $T/s.pts
dda --size 10 --radial /dev/full -o $T/full/out $T/s.pts
dda --density -o /dev/full $T/s.pts
dda --rdf $T/s.pts
dda --size 10 $T/s.pts
dda --summary --size 10 -o /dev/full $T/s.pts
dda --summary --size 10 --png /dev/full -o $T/full/out $T/s.pts
dda --summary --size 10 $T/s.pts
'
for p in imap frd-gen frd-prep frs-sample pts-render ref-sample hsw-sample \
    discrepancy dda mc-error; do
	full_rows="$full_rows$p --version
"
done

full() {
	cmd=$1
	rm -rf "$T/full" && mkdir "$T/full" || return
	case $cmd in
	*/dev/full*)
		name='/dev/full'
		eval "timeout -k 5 60 $cmd" >"$T/out" 2>"$T/err" ;;
	*)
		name='<stdout>|standard output'
		eval "timeout -k 5 60 $cmd" >/dev/full 2>"$T/err" ;;
	esac
	rc=$?
	why=""
	[ $rc -eq 1 ] || why="; exit status $rc"
	grep -E -- "$name" "$T/err" | grep -q "No space left on device" ||
	    why="$why; no message naming $name and the full disk"
	[ -z "$(ls -A "$T/full")" ] || why="$why; left: $(ls -A "$T/full")"
	verdict "full disk: $cmd" "$T/err" "$why"
}

echo "$full_rows" | while read -r cmd; do
	[ -n "$cmd" ] && full "$cmd"
done

# ---- 3. A closed standard output -------------------------------------
#
# Rows "BYTES COMMAND": COMMAND | head -c BYTES, with SIGPIPE at its
# default (the program dies of it, or fails with status 1 and a message)
# and ignored (then writes fail with EPIPE: status 1 and a message naming
# standard output).  Rows with BYTES 10 write far more than a pipe holds
# (64 KiB), so they meet the closed pipe; BYTES 0: a small output, which
# goes to a pipe whose reader is gone before the program starts.
pipe_rows='
10 imap gen ramp -s 2000x2000 --format exr
0  imap convert --format png -s 1024x512 $D/sunset.exr -
0  imap info -s 500x500 sky
0  imap --help
0  frd-gen -j 1 -s 64
0  frd-gen --quality $T/m.frd
10 frd-prep $M
10 frd-prep -a level2 $M
10 frs-sample -m $T/m.frd -q -i blob -n 100000
10 frs-sample -m $T/m.frd -q -i blob -n 100000 -T
0  frs-sample -m $T/m.frd -q -i blob -n 1000 --count-only --sets 20
0  pts-render -s 1000 $T/r.pts
10 pts-render -s 1000 --format pnm $T/r.pts
10 ref-sample -n 100000
10 ref-sample -n 100000 -T
10 hsw-sample -i blob -n 100000
10 hsw-sample -i blob -n 100000 -T
0  discrepancy $T/r.pts
10 dda --size 50 $T/r.pts
0  dda --density $T/r.pts
0  dda --rdf $T/r.pts
'

closed() {
	mode=$1 bytes=$2 cmd=$3
	err=$T/err.$mode
	run="timeout -k 5 60 env --$mode-signal=PIPE $cmd"
	if [ "$bytes" = 0 ]; then
		rm -f "$T/fifo.$mode" && mkfifo "$T/fifo.$mode" || return
		# Open both ends without blocking, then close the reader.
		exec 3<>"$T/fifo.$mode" 4>"$T/fifo.$mode" 3<&-
		eval "$run" >&4 2>"$err"
		rc=$?
		exec 4>&-
	else
		{
			eval "$run" 2>"$err"
			echo $? >"$T/status.$mode"
		} | head -c "$bytes" >/dev/null
		rc=$(cat "$T/status.$mode")
	fi
	why=""
	said=""
	grep -E '<stdout>|standard output' "$err" |
	    grep -q "Broken pipe" && said=1
	case $mode.$rc in
	default.141) ;;
	*.1) [ -n "$said" ] || why="; status 1 without a message naming standard output" ;;
	*.124) why="; hung" ;;
	*) why="; exit status $rc" ;;
	esac
	verdict "closed pipe, SIGPIPE $mode: $cmd" "$err" "$why"
}

# Both dispositions at once; their reports in order.
echo "$pipe_rows" | while read -r bytes cmd; do
	[ -n "$bytes" ] || continue
	closed default "$bytes" "$cmd" >"$T/log.default" &
	closed ignore "$bytes" "$cmd" >"$T/log.ignore" &
	wait
	cat "$T/log.default" "$T/log.ignore"
done
done_testing
