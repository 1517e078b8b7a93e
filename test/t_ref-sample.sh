#!/bin/sh
# ref-sample: every kind in 2-D and 3-D (-d 3), text output, determinism,
# 2-D golden bytes and bad input.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/ptsutil.sh"

# Every kind writes a valid binary file of the right count.
for k in random regular jittered halton hammersley sobol dart; do
	case $k in regular|jittered) want=1024 ;; *) want=1000 ;; esac
	if ref-sample -k $k -n 1000 -q -o "$T/$k.pts" 2>"$T/err"; then
		cnt=$(pts_count "$T/$k.pts")
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
cnt=$(pts_count "$T/few.pts")
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

# --sets M: set i is the set of -S S+i, the records one after another,
# each followed by its set (the column named set), under one header that
# counts them all.
recs() { tail -c +$(($2 + 1)) "$1" | od -A n -t x8 -v -w$((8 * $3)); }
sethex() { case $1 in 0) echo 0000000000000000 ;; 1) echo 3ff0000000000000 ;;
	2) echo 4000000000000000 ;; esac; }
for k in random jittered halton sobol dart relaxed-dart; do
	case $k in jittered) per=81 ;; *) per=90 ;; esac  # round(sqrt 90)^2
	case $k in relaxed-dart) imp="-i blob -s 32x32" ;; *) imp="" ;; esac
	# shellcheck disable=SC2086
	ref-sample -k $k $imp -n 90 -S 5 --sets 3 -q -o "$T/sets.pts"
	: >"$T/cat.hex"
	for s in 5 6 7; do
		# shellcheck disable=SC2086
		ref-sample -k $k $imp -n 90 -S $s -q -o "$T/one.pts"
		recs "$T/one.pts" 32 2 | sed "s/\$/ $(sethex $((s - 5)))/" >>"$T/cat.hex"
	done
	if recs "$T/sets.pts" 40 3 | cmp -s - "$T/cat.hex" &&
	    [ "$(pts_count "$T/sets.pts")" = $((3 * per)) ] &&
	    [ "$(head -c 40 "$T/sets.pts" | tail -c 8 | tr '\0' ' ')" = "set     " ]; then
		ok "-k $k --sets 3 -S 5: the sets of -S 5, 6, 7 and a set column, count $((3 * per))"
	else
		nok "-k $k --sets 3 -S 5: the sets of -S 5, 6, 7 and a set column, count $((3 * per))"
	fi
done
ref-sample -k sobol -n 50 -S 2 --sets 2 -T -o "$T/sets.txt"
{ ref-sample -k sobol -n 50 -S 2 -T | sed '/^#/d; s/$/ 0/'
  ref-sample -k sobol -n 50 -S 3 -T | sed '/^#/d; s/$/ 1/'; } >"$T/cat.txt"
head -n 1 "$T/sets.txt" | grep -q '^#pts dims=2 extra=1 count=100 version=2 names=set$' &&
    grep -v '^#' "$T/sets.txt" | cmp -s - "$T/cat.txt" &&
    ok "--sets 2 -T: one header, count 100, the records of -S 2 and 3 and their set" ||
    nok "--sets 2 -T: one header, count 100, the records of -S 2 and 3 and their set"
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

# A long dart run says so first, whether or not standard error is a
# terminal (here a file): a note with the time it will take, from the
# count (and the sets), not with -q, none for a short run.
# note_of CMD...: CMD's standard error in $T/note, CMD stopped once the
# note is there (or after 20 s); its output must not be left.
# The note and the output are cleared first: a note left from the case
# before would stop the loop at once, and a stop before the exec would land
# in this shell's TERM trap, not in CMD, which then runs to the end.
note_of() {
	: >"$T/note"
	rm -f "$T/long.pts"
	"$@" 2>"$T/note" &
	pid=$!
	i=0
	while [ $i -lt 200 ] && ! grep -q 'take about' "$T/note" &&
	    kill -0 $pid 2>/dev/null; do
		sleep 0.1
		i=$((i + 1))
	done
	kill $pid 2>/dev/null
	wait $pid 2>/dev/null
}
for a in "-k dart -n 6000000" "-k dart -n 1000000 --sets 10" \
    "-d 3 -k dart -n 2000000" "-k relaxed-dart -n 4000000"; do
	# shellcheck disable=SC2086
	note_of ref-sample $a -o "$T/long.pts"
	if grep -qE '^ref-sample: [a-z-]+: [0-9]+ points( in [0-9]+ sets)? take about [0-9]+ (seconds|minutes|hours)' \
	    "$T/note" && [ ! -e "$T/long.pts" ]; then
		ok "ref-sample $a: a note of the time first ($(cat "$T/note"))"
	else
		nok "ref-sample $a: no note of the time: $(cat "$T/note")"
	fi
done
note_of ref-sample -q -k dart -n 6000000 -o "$T/long.pts"
[ ! -s "$T/note" ] && ok "-q: no note of the time" ||
    nok "-q: a note of the time: $(cat "$T/note")"
ref-sample -k dart -n 100000 -o "$T/short.pts" 2>"$T/note" && [ ! -s "$T/note" ] &&
    ok "a short dart run: no note" || nok "a short dart run: $(cat "$T/note")"

# Relaxed dart throwing by an importance map.
writes_points "-k relaxed-dart -i blob: 500 points" 500 "$T/rd.pts" \
    ref-sample -k relaxed-dart -n 500 -i blob -s 64x64 -q -o "$T/rd.pts"
expect_fail "relaxed-dart: bad -i file" 1 "nosuchmap" "$T/rdbad.pts" \
    ref-sample -k relaxed-dart -n 10 -i "$T/nosuchmap.png" -o "$T/rdbad.pts"

# 2-D bytes are unchanged by -d: cksums of the records of sets made
# before 3-D existed (pts(5) version 1 then; version 2 changed the header
# alone, not these records).  Halton's since num.h's radical inverse (the
# last bits of base 3: the sum of frs-sample's and hsw-sample's Halton).
golden() {
	want=$1
	shift
	ref-sample "$@" -q -o "$T/g.pts"
	got=$(tail -c +33 "$T/g.pts" | cksum | awk '{ print $1, $2 }')
	[ "$got" = "$want" ] && ok "2-D golden: $*" || nok "2-D golden: $* ($got, expected $want)"
}
golden "1078683921 1024" -k halton -n 64 -S 3
golden "4233120002 4800" -k hammersley -n 300 -S 7
golden "2997165810 4800" -k sobol -n 300 -S 7
golden "579980928 4800" -k random -n 300 -S 1
golden "317242794 4624" -k jittered -n 300 -S 1
golden "2879106105 4800" -k dart -n 300 -S 1
golden "1078683921 1024" -d 2 -k halton -n 64 -S 3

# -d 3: every kind, a binary file with k = 3 and the right count.
for k in random regular jittered halton hammersley sobol dart; do
	case $k in regular|jittered) want=1000 ;; *) want=900 ;; esac
	if ref-sample -d 3 -k $k -n 900 -q -o "$T/$k.3.pts" 2>"$T/err"; then
		cnt=$(pts_count "$T/$k.3.pts")
		dims=$(od -A n -t u4 -j 12 -N 4 "$T/$k.3.pts" | tr -d ' ')
		size=$(wc -c <"$T/$k.3.pts")
		if [ "$cnt" = "$want" ] && [ "$dims" = 3 ] &&
		    [ "$size" -eq $((32 + 24 * want)) ]; then
			ok "-d 3 -k $k: $want points of 3 coordinates"
		else
			nok "-d 3 -k $k: count $cnt, dims $dims, size $size, expected $want"
		fi
	else
		nok "-d 3 -k $k"
		sed 's/^/# /' "$T/err"
	fi
	ref-sample -d 3 -k $k -n 500 -q -T -o "$T/$k.3.txt"
	head -n 1 "$T/$k.3.txt" | grep -q '^#pts dims=3 extra=0 count=' &&
	awk '!/^#/ { n++; if (NF != 3) bad = 1
	    for (i = 1; i <= 3; i++) if ($i < 0 || $i >= 1) bad = 1 }
	    END { exit bad || n < 500 }' "$T/$k.3.txt" &&
	    ok "-d 3 -k $k -T: dims=3 header, points in [0,1)^3" ||
	    nok "-d 3 -k $k -T: dims=3 header, points in [0,1)^3"
done
ref-sample -d 3 -k jittered -n 900 -o /dev/null 2>"$T/err"
grep -q 'nearest cubic grid (10x10x10) to 900' "$T/err" &&
    ok "-d 3 jittered notes 1000 for 900" || nok "-d 3 jittered notes 1000 for 900"
ref-sample -d 3 -k regular -n 27 -T -o "$T/r27.txt" 2>"$T/err"
[ ! -s "$T/err" ] && [ "$(sed -n 2p "$T/r27.txt")" = "0.16666666666666666 0.16666666666666666 0.16666666666666666" ] &&
    [ "$(sed -n 3p "$T/r27.txt")" = "0.5 0.16666666666666666 0.16666666666666666" ] &&
    ok "-d 3 regular -n 27: cell centres of 3x3x3, no note" ||
    nok "-d 3 regular -n 27: cell centres of 3x3x3, no note"

# Classical sequences with -S 0: Halton (1/2, 1/3, 1/5); Sobol' as in Joe
# and Kuo's published example (web.maths.unsw.edu.au/~fkuo/sobol/).
ref-sample -d 3 -k halton -n 2 -S 0 -T | sed -n 2p |
    awk '{ exit !($1 == 0.5 && $2 == 1 / 3 && $3 == 0.2) }' &&
    ok "-d 3 -S 0 halton starts at (1/2, 1/3, 1/5)" ||
    nok "-d 3 -S 0 halton starts at (1/2, 1/3, 1/5)"
ref-sample -d 3 -k sobol -n 6 -S 0 -T | grep -v '^#' >"$T/sob.txt"
printf '0 0 0\n0.5 0.5 0.5\n0.75 0.25 0.25\n0.25 0.75 0.75\n0.375 0.375 0.625\n0.875 0.875 0.125\n' |
    cmp -s - "$T/sob.txt" && ok "-d 3 -S 0 sobol: Joe and Kuo's first points" ||
    nok "-d 3 -S 0 sobol: Joe and Kuo's first points"
ref-sample -d 3 -k hammersley -n 4 -S 0 -T | sed -n 3p |
    awk '{ exit !($1 == 0.375 && $2 == 0.5 && $3 == 1 / 3) }' &&
    ok "-d 3 -S 0 hammersley point 1 is (3/8, 1/2, 1/3)" ||
    nok "-d 3 -S 0 hammersley point 1 is (3/8, 1/2, 1/3)"

# Same seed same bytes, for any -j; another seed other points.
for k in random jittered halton sobol dart; do
	ref-sample -d 3 -k $k -n 400 -S 5 -j 1 -q -o "$T/a.pts"
	ref-sample -d 3 -k $k -n 400 -S 5 -j 8 -q -o "$T/b.pts"
	ref-sample -d 3 -k $k -n 400 -S 6 -q -o "$T/c.pts"
	cmp -s "$T/a.pts" "$T/b.pts" && ok "-d 3 -k $k: same seed, same bytes (-j 1, -j 8)" ||
	    nok "-d 3 -k $k: same seed, same bytes (-j 1, -j 8)"
	cmp -s "$T/a.pts" "$T/c.pts" && nok "-d 3 -k $k: another seed, other points" ||
	    ok "-d 3 -k $k: another seed, other points"
done

# --sets in 3-D: the sets of -S 5, 6 under one header, and the set.
ref-sample -d 3 -k dart -n 200 -S 5 --sets 2 -q -o "$T/sets3.pts"
{ ref-sample -d 3 -k dart -n 200 -S 5 -q -o "$T/one.pts" && recs "$T/one.pts" 32 3 |
      sed "s/\$/ $(sethex 0)/"
  ref-sample -d 3 -k dart -n 200 -S 6 -q -o "$T/one.pts" && recs "$T/one.pts" 32 3 |
      sed "s/\$/ $(sethex 1)/"; } >"$T/cat3.hex"
recs "$T/sets3.pts" 40 4 | cmp -s - "$T/cat3.hex" && [ "$(pts_count "$T/sets3.pts")" = 400 ] &&
    ok "-d 3 --sets 2: the sets of -S 5 and 6 and their set, count 400" ||
    nok "-d 3 --sets 2: the sets of -S 5 and 6 and their set, count 400"

# Dart that gives up in 3-D says so.
ref-sample -d 3 -k dart -n 20000 --max-failures 1 -o "$T/few3.pts" 2>"$T/err"
cnt=$(pts_count "$T/few3.pts")
[ "$cnt" -lt 20000 ] && grep -q "placed $cnt of 20000" "$T/err" &&
    ok "-d 3 dart stops early and says how many ($cnt)" ||
    nok "-d 3 dart stops early and says how many ($cnt)"

# Bad -d and what 3-D refuses.
expect_fail "-d 4" 2 "-d: '4' is not 2 or 3" "$T/o.pts" ref-sample -d 4 -n 10 -o "$T/o.pts"
expect_fail "-d 1" 2 "-d: '1' is not 2 or 3" "$T/o.pts" ref-sample -d 1 -n 10 -o "$T/o.pts"
expect_fail "-d 3x" 2 "-d: '3x' is not 2 or 3" "$T/o.pts" ref-sample --dims 3x -n 10 -o "$T/o.pts"
expect_fail "-d 3 -k relaxed-dart" 2 "relaxed-dart is two-dimensional only" "$T/o.pts" \
    ref-sample -d 3 -k relaxed-dart -n 10 -o "$T/o.pts"
expect_fail "-d 3 -i blob" 2 "-i is two-dimensional only" "$T/o.pts" \
    ref-sample -d 3 -k dart -i blob -n 10 -o "$T/o.pts"
done_testing
