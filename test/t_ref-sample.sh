#!/bin/sh
# ref-sample: every kind, text output, determinism and bad input.
. "$(dirname "$0")/lib.sh"

count() { od -A n -t u8 -j 24 -N 8 "$1" | tr -d ' '; }

# Every kind writes a valid binary file of the right count.
for k in random regular jittered halton hammersley sobol dart; do
	case $k in regular|jittered) want=1024 ;; *) want=1000 ;; esac
	if ref-sample -k $k -n 1000 -q -o "$T/$k.pts" 2>"$T/err"; then
		cnt=$(count "$T/$k.pts")
		size=$(wc -c <"$T/$k.pts")
		if [ "$cnt" = "$want" ] && [ "$size" -eq $((32 + 16 * want)) ] &&
		    [ "$(head -c 4 "$T/$k.pts" | tail -c 3)" = "PTS" ]; then
			ok "-k $k: $want points"
		else
			nok "-k $k: count $cnt, size $size, expected $want"
		fi
	else
		nok "-k $k"
		sed 's/^/# /' "$T/err"
	fi
done
check "default kind is random" ref-sample -n 1000 -q -o "$T/def.pts"
cmp -s "$T/def.pts" "$T/random.pts" && ok "default kind gives random's bytes" ||
    nok "default kind gives random's bytes"

# The note on a count that is not a square, silenced by -q.
ref-sample -k regular -n 1000 -o /dev/null 2>"$T/err"
grep -q 'nearest square grid (32x32)' "$T/err" && ok "regular notes 1024 for 1000" ||
    nok "regular notes 1024 for 1000"
ref-sample -k regular -n 1000 -q -o /dev/null 2>"$T/err"
[ ! -s "$T/err" ] && ok "-q silences the note" || nok "-q silences the note"
ref-sample -k jittered -n 1024 -o /dev/null 2>"$T/err"
[ ! -s "$T/err" ] && ok "no note for a square count" || nok "no note for a square count"

# Text output: a header and the points, in [0, 1).
ref-sample -k halton -n 4 -S 0 -T -o "$T/h.txt"
head -n 1 "$T/h.txt" | grep -q '^#pts dims=2 extra=0 count=4' && ok "-T header" ||
    nok "-T header"
sed -n 2p "$T/h.txt" | awk '{ exit !($1 == 0.5 && $2 > 0.333333 && $2 < 0.333334) }' &&
    ok "-S 0 halton starts at (1/2, 1/3)" || nok "-S 0 halton starts at (1/2, 1/3)"
for k in random sobol dart; do
	ref-sample -k $k -n 500 -T -o "$T/$k.txt"
	awk '!/^#/ { n++; if ($1 < 0 || $1 >= 1 || $2 < 0 || $2 >= 1) bad = 1 }
	    END { exit bad || n != 500 }' "$T/$k.txt" &&
	    ok "-k $k -T: 500 points in [0,1)^2" || nok "-k $k -T: 500 points in [0,1)^2"
done

# Same seed same bytes, another seed other points.
for k in random sobol dart halton; do
	ref-sample -k $k -n 300 -S 5 -o "$T/a.pts"
	ref-sample -k $k -n 300 -S 5 -o "$T/b.pts"
	ref-sample -k $k -n 300 -S 6 -o "$T/c.pts"
	cmp -s "$T/a.pts" "$T/b.pts" && ok "-k $k: same seed, same bytes" ||
	    nok "-k $k: same seed, same bytes"
	cmp -s "$T/a.pts" "$T/c.pts" && nok "-k $k: another seed, other points" ||
	    ok "-k $k: another seed, other points"
done

# Dart throwing that gives up says so.
ref-sample -k dart -n 5000 --max-failures 1 -o "$T/few.pts" 2>"$T/err"
cnt=$(count "$T/few.pts")
[ "$cnt" -lt 5000 ] && grep -q "placed $cnt of 5000" "$T/err" &&
    ok "dart stops early and says how many ($cnt)" ||
    nok "dart stops early and says how many ($cnt)"

# Bad input.
expect_fail "unknown kind" 2 "unknown kind" "$T/o.pts" ref-sample -k blue -n 10 -o "$T/o.pts"
expect_fail "n = 0" 2 "-n" "$T/o.pts" ref-sample -n 0 -o "$T/o.pts"
expect_fail "no count" 2 "-n COUNT is required" "$T/o.pts" ref-sample -k sobol -o "$T/o.pts"
expect_fail "junk count" 2 "-n" "$T/o.pts" ref-sample -n 12x -o "$T/o.pts"
expect_fail "bad --max-failures" 2 "--max-failures" "$T/o.pts" \
    ref-sample -k dart -n 10 --max-failures 0 -o "$T/o.pts"
expect_fail "stray argument" 2 "unexpected argument" "$T/o.pts" ref-sample -n 10 extra -o "$T/o.pts"
expect_fail "missing directory" 1 "cannot create" "$T/no/o.pts" ref-sample -n 10 -o "$T/no/o.pts"
expect_fail "full disk" 1 "No space left" - ref-sample -n 10 -o /dev/full

# --sets M: set i is the set of -S S+i, the records one after another
# under one header that counts them all.
for k in random jittered halton sobol dart relaxed-dart; do
	case $k in jittered) per=81 ;; *) per=90 ;; esac  # round(sqrt 90)^2
	case $k in relaxed-dart) imp="-i blob -s 32x32" ;; *) imp="" ;; esac
	# shellcheck disable=SC2086
	ref-sample -k $k $imp -n 90 -S 5 --sets 3 -q -o "$T/sets.pts"
	: >"$T/cat.bin"
	for s in 5 6 7; do
		# shellcheck disable=SC2086
		ref-sample -k $k $imp -n 90 -S $s -q -o "$T/one.pts"
		tail -c +33 "$T/one.pts" >>"$T/cat.bin"
	done
	if tail -c +33 "$T/sets.pts" | cmp -s - "$T/cat.bin" &&
	    [ "$(count "$T/sets.pts")" = $((3 * per)) ] &&
	    [ "$(head -c 24 "$T/sets.pts" | od -A n -t x1)" = \
	      "$(head -c 24 "$T/one.pts" | od -A n -t x1)" ]; then
		ok "-k $k --sets 3 -S 5: the sets of -S 5, 6, 7, count $((3 * per))"
	else
		nok "-k $k --sets 3 -S 5: the sets of -S 5, 6, 7, count $((3 * per))"
	fi
done
ref-sample -k sobol -n 50 -S 2 --sets 2 -T -o "$T/sets.txt"
{ ref-sample -k sobol -n 50 -S 2 -T; ref-sample -k sobol -n 50 -S 3 -T; } |
    grep -v '^#' >"$T/cat.txt"
head -n 1 "$T/sets.txt" | grep -q '^#pts dims=2 extra=0 count=100$' &&
    grep -v '^#' "$T/sets.txt" | cmp -s - "$T/cat.txt" &&
    ok "--sets 2 -T: one header, count 100, the records of -S 2 and 3" ||
    nok "--sets 2 -T: one header, count 100, the records of -S 2 and 3"
for a in "-k random -n 100" "-k regular -n 90" "-k hammersley -n 64 -S 0" \
    "-k dart -n 5000 --max-failures 1"; do
	# shellcheck disable=SC2086
	ref-sample $a -q -o "$T/a.pts"
	# shellcheck disable=SC2086
	ref-sample $a -q --sets 1 -o "$T/b.pts"
	cmp -s "$T/a.pts" "$T/b.pts" && ok "$a: --sets 1 gives the same bytes" ||
	    nok "$a: --sets 1 gives the same bytes"
done
expect_fail "--sets 0" 2 "--sets" "$T/o.pts" ref-sample -n 10 --sets 0 -o "$T/o.pts"
expect_fail "junk --sets" 2 "--sets" "$T/o.pts" ref-sample -n 10 --sets 3x -o "$T/o.pts"
expect_fail "negative --sets" 2 "--sets" "$T/o.pts" ref-sample -n 10 --sets -2 -o "$T/o.pts"
expect_fail "--sets past 2^56 points in all (64-bit product)" 2 "2^56" "$T/o.pts" \
    ref-sample -k sobol -n 4294967296 --sets 33554432 -o "$T/o.pts"
expect_fail "--sets past seed 2^64-1" 2 "2^64-1" "$T/o.pts" \
    ref-sample -n 10 -S 18446744073709551614 --sets 3 -o "$T/o.pts"
check "--sets up to seed 2^64-1" \
    ref-sample -n 10 -S 18446744073709551614 --sets 2 -o "$T/o.pts"
rm -f "$T/o.pts"
expect_fail "--sets: a short dart set is an error" 1 "placed only" "$T/o.pts" \
    ref-sample -k dart -n 5000 --max-failures 1 --sets 2 -o "$T/o.pts"

# Relaxed dart throwing by an importance map.
if ref-sample -k relaxed-dart -n 500 -i blob -s 64x64 -q -o "$T/rd.pts" 2>"$T/err" &&
    [ "$(count "$T/rd.pts")" = 500 ]; then
	ok "-k relaxed-dart -i blob: 500 points"
else
	nok "-k relaxed-dart -i blob: 500 points"
	sed 's/^/# /' "$T/err"
fi
expect_fail "relaxed-dart: bad -i file" 1 "nosuchmap" "$T/rdbad.pts" \
    ref-sample -k relaxed-dart -n 10 -i "$T/nosuchmap.png" -o "$T/rdbad.pts"
