#!/bin/sh
# imap: generation, statistics, conversion, real HDR maps, bad input.
. "$(dirname "$0")/lib.sh"

# The issue's own acceptance line.
check "gen blob -s 256x256 -o blob.exr" imap gen blob -s 256x256 -o "$T/blob.exr"
check "info blob.exr" imap info "$T/blob.exr"
cp "$T/out" "$T/info.exr"
[ "$(value width "$T/info.exr")" = 256 ] && [ "$(value height "$T/info.exr")" = 256 ] &&
    ok "info gives the size" || nok "info gives the size"

# The file holds what the spec defines: same statistics as the spec itself
# (float precision in the file).
imap info -s 256x256 blob >"$T/info.spec" 2>"$T/err"
for k in mean max min sum; do
	if near "$(value $k "$T/info.exr")" "$(value $k "$T/info.spec")" 1e-6; then
		ok "blob.exr $k matches the spec"
	else
		nok "blob.exr $k matches the spec"
	fi
done

# PNG is scaled to its maximum: mean / max stays within 16-bit
# quantisation.
check "gen blob png" imap gen blob -s 256x256 -o "$T/blob.png"
imap info "$T/blob.png" >"$T/info.png"
want=$(awk -v m="$(value mean "$T/info.spec")" -v x="$(value max "$T/info.spec")" \
    'BEGIN { printf "%.12g", m / x }')
[ "$(value max "$T/info.png")" = 1 ] &&
near "$(value mean "$T/info.png")" "$want" 2e-6 &&
    ok "png mean within quantisation" || nok "png mean within quantisation"

# Area-weighted resampling keeps the mean.
check "convert -s 64x32" imap convert -s 64x32 "$T/blob.exr" "$T/small.exr"
imap info "$T/small.exr" >"$T/info.small"
[ "$(value width "$T/info.small")" = 64 ] && [ "$(value height "$T/info.small")" = 32 ] &&
    ok "convert resizes" || nok "convert resizes"
near "$(value mean "$T/info.small")" "$(value mean "$T/info.exr")" 1e-6 &&
    ok "resampling keeps the mean" || nok "resampling keeps the mean"

# Standard input and output.
imap info - <"$T/blob.exr" >"$T/info.stdin" 2>"$T/err" &&
    [ "$(value mean "$T/info.stdin")" = "$(value mean "$T/info.exr")" ] &&
    ok "info reads standard input" || nok "info reads standard input"
imap gen ramp --format exr | imap info - >"$T/info.pipe" 2>"$T/err" &&
    near "$(value mean "$T/info.pipe")" 0.5 1e-7 &&
    ok "gen | info through a pipe" || nok "gen | info through a pipe"

# --equirect on a constant map: the mean becomes 2/pi.
imap info --equirect -s 16x64 const >"$T/info.eq"
near "$(value mean "$T/info.eq")" 0.636619772 1e-8 &&
    ok "equirect weight integrates to 2/pi" || nok "equirect weight integrates to 2/pi"

# Real HDR environment maps (DWAB-compressed float RGB).
for m in sunset forest interior; do
	f=$TD/$m.exr
	if imap info "$f" >"$T/info.$m" 2>"$T/err" &&
	    [ "$(value width "$T/info.$m")" = 1024 ] &&
	    [ "$(value nonfinite "$T/info.$m")" = 0 ]; then
		ok "real map $m.exr loads"
	else
		nok "real map $m.exr loads"
		sed 's/^/# /' "$T/err"
	fi
done

# interior.exr has small negative luminance values from lossy DWA:
# clamped with one warning by default, an error with --strict.
neg=$(value negatives "$T/info.interior")
[ "${neg:-0}" -gt 1000 ] && ok "interior.exr has $neg negative pixels" ||
    nok "interior.exr negative pixels counted (got '$neg')"
imap convert -s 128x64 "$TD/interior.exr" "$T/int.exr" 2>"$T/err"
if [ $? -eq 0 ] && [ "$(grep -c 'negative pixels clamped' "$T/err")" = 1 ] &&
    grep -q "$neg negative" "$T/err"; then
	ok "negatives clamped with one warning naming the count"
else
	nok "negatives clamped with one warning naming the count"
	sed 's/^/# /' "$T/err"
fi
imap info "$T/int.exr" >"$T/info.int"
[ "$(value negatives "$T/info.int")" = 0 ] && ok "clamped output has no negatives" ||
    nok "clamped output has no negatives"
# info's statistics are those of the map as the programs use it, which
# its warning says is clamped: min 0, the clamped pixels among the zeros,
# the same as those of the clamped map that convert writes; negatives
# and min_negative are the warning's count and smallest value.  With
# --equirect too, whose weighting comes after the clamping, as in
# convert: the same warning.
for eq in "" --equirect; do
	imap info $eq "$TD/interior.exr" >"$T/ii" 2>"$T/iw"
	imap convert $eq "$TD/interior.exr" "$T/ic.exr" 2>"$T/cw" &&
	    imap info "$T/ic.exr" >"$T/ci" 2>>"$T/cw"
	n=$(sed -n 's/.*: \([0-9]*\) negative pixels clamped to zero.*/\1/p' "$T/iw")
	small=$(sed -n 's/.*clamped to zero (smallest \(.*\))$/\1/p' "$T/iw")
	why=""
	[ "$(value min "$T/ii")" = 0 ] || why="$why min $(value min "$T/ii");"
	[ "$(value zeros "$T/ii")" = "$(value zeros "$T/ci")" ] ||
	    why="$why zeros $(value zeros "$T/ii"), clamped map's $(value zeros "$T/ci");"
	for k in max mean sum min_positive; do
		near "$(value $k "$T/ii")" "$(value $k "$T/ci")" 1e-6 ||
		    why="$why $k $(value $k "$T/ii"), clamped map's $(value $k "$T/ci");"
	done
	[ -n "$n" ] && [ "$(value negatives "$T/ii")" = "$n" ] &&
	    near "$(value min_negative "$T/ii")" "$small" 1e-5 ||
	    why="$why negatives/min_negative not the warning's ($(cat "$T/iw"));"
	cmp -s "$T/iw" "$T/cw" || why="$why info warns $(cat "$T/iw"), convert $(cat "$T/cw");"
	[ -z "$why" ] && ok "info ${eq:+$eq }of interior.exr: the statistics of the clamped map" ||
	    nok "info ${eq:+$eq }of interior.exr: the statistics of the clamped map:$why"
done
expect_fail "--strict refuses negative importance" 1 "is negative" "$T/strict.exr" \
    imap convert --strict "$TD/interior.exr" "$T/strict.exr"
grep -q "pixel (" "$T/err" && ok "--strict names the pixel" || nok "--strict names the pixel"

# Bad input: exit 1, file and problem named, no output left behind.
: >"$T/empty.png"
expect_fail "empty file" 1 "empty.png: empty file" "$T/o1.exr" \
    imap convert "$T/empty.png" "$T/o1.exr"
echo "just text" >"$T/text.png"
expect_fail "not a PNG" 1 "not a PNG or OpenEXR" "$T/o2.exr" \
    imap convert "$T/text.png" "$T/o2.exr"
head -c 300 "$T/blob.png" >"$T/cut.png"
expect_fail "truncated PNG" 1 "cut.png: bad PNG" "$T/o3.exr" \
    imap convert "$T/cut.png" "$T/o3.exr"
head -c 2000 "$TD/sunset.exr" >"$T/cut.exr"
expect_fail "truncated EXR" 1 "cut.exr" "$T/o4.png" \
    imap convert "$T/cut.exr" "$T/o4.png"
expect_fail "unknown spec" 2 "unknown parameter 'radius'" "$T/o5.exr" \
    imap gen blob:radius=3 -o "$T/o5.exr"
expect_fail "unknown map name" 2 "not a procedural map" "$T/o6.exr" \
    imap gen blobby -o "$T/o6.exr"
expect_fail "missing input" 1 "nothere.exr: no such file" "$T/o7.exr" \
    imap convert "$T/nothere.exr" "$T/o7.exr"
expect_fail "bad size" 2 "-s" "$T/o8.exr" imap gen blob -s 0x5 -o "$T/o8.exr"
expect_fail "junk size" 2 "-s" "$T/o9.exr" imap gen blob -s 12x -o "$T/o9.exr"
expect_fail "unknown option" 2 "usage" "$T/o10.exr" imap gen blob --frobnicate -o "$T/o10.exr"
expect_fail "unknown extension" 2 "unknown extension" "$T/o11.tif" imap gen blob -o "$T/o11.tif"
expect_fail "missing directory" 1 "$T/no/dir/x.exr: cannot create" "$T/no/dir/x.exr" \
    imap gen blob -o "$T/no/dir/x.exr"
expect_fail "full disk" 1 "/dev/full" - imap gen blob --format exr -o /dev/full
expect_fail "no command" 2 "no command" - imap
expect_fail "unknown command" 2 "unknown command" - imap frob

# A signal during a long run leaves no file and no temporary (SIGTERM:
# a background job of a script ignores SIGINT).
mkdir "$T/sig"
imap gen sky -s 8000x8000 -o "$T/sig/big.exr" 2>/dev/null &
pid=$!
sleep 1
kill -TERM $pid 2>/dev/null
wait $pid
rc=$?
if [ $rc -ne 0 ] && [ -z "$(ls "$T/sig")" ]; then
	ok "SIGTERM leaves nothing behind"
else
	nok "SIGTERM leaves nothing behind (status $rc, left: $(ls "$T/sig"))"
fi

# --log maps the positive range onto (1/256, 1] for looking at HDR maps.
imap gen 'ramp:from=1,to=1000' --log -o "$T/log.exr" 2>"$T/err" &&
    imap info "$T/log.exr" >"$T/info.log" &&
    near "$(value max "$T/info.log")" 1 1e-6 &&
    near "$(value min "$T/info.log")" 0.00390625 1e-6 &&
    ok "--log spans (1/256, 1]" || nok "--log spans (1/256, 1]"

# Binary output to a terminal is refused (script(1) gives a pty).
if command -v script >/dev/null 2>&1; then
	script -qec "imap gen blob --format exr" /dev/null >"$T/tty" 2>&1
	grep -q "refusing to write binary data to a terminal" "$T/tty" &&
	    ok "no binary on a terminal" || nok "no binary on a terminal"
fi

# Same bytes for any thread count.
imap gen sky -s 200x100 -j 1 -o "$T/j1.exr" && imap gen sky -s 200x100 -j 2 -o "$T/j2.exr" &&
    imap gen sky -s 200x100 -j 7 -o "$T/j7.exr" && cmp -s "$T/j1.exr" "$T/j2.exr" &&
    cmp -s "$T/j1.exr" "$T/j7.exr" && ok "-j 1, 2 and 7 give the same bytes" ||
    nok "-j 1, 2 and 7 give the same bytes"

# OpenEXRCore 3.1.5's ZIP encoder corrupts some chunks (a 128^2 blob read
# back with NaNs): every written file must read back as written.
bad=""
for sz in 64 127 128 129 200; do
	imap gen blob -s $sz -o "$T/z$sz.exr" 2>>"$T/err" &&
	    imap info "$T/z$sz.exr" >"$T/iz" 2>>"$T/err" &&
	    imap info -s $sz blob >"$T/is" &&
	    near "$(value mean "$T/iz")" "$(value mean "$T/is")" 1e-6 || bad="$bad $sz"
done
[ -z "$bad" ] && ok "EXR files read back as written" || nok "EXR files read back as written (bad:$bad)"
done_testing
