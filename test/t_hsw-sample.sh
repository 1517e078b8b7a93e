#!/bin/sh
# hsw-sample: exact counts, text output, --pdf, file input, determinism
# and bad input.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/ptsutil.sh"

check "blob, 2000 points" hsw-sample -i blob -n 2000 -o "$T/a.pts"
cnt=$(pts_count "$T/a.pts")
[ "$cnt" = 2000 ] && ok "exactly n points ($cnt)" || nok "exactly n points ($cnt)"
[ "$(wc -c <"$T/a.pts")" -eq $((32 + 16 * 2000)) ] && ok "binary .pts layout" ||
    nok "binary .pts layout"
for s in random regular jittered halton hammersley; do
	hsw-sample -i blob -n 777 --input $s -o "$T/$s.pts"
	c=$(pts_count "$T/$s.pts")
	[ "$c" = 777 ] && ok "--input $s: exactly n" || nok "--input $s: exactly n ($c)"
done

hsw-sample -i blob -n 500 -T -o "$T/t.txt"
head -n 1 "$T/t.txt" | grep -q '^#pts dims=2 extra=0 count=500' &&
    [ "$(grep -vc '^#' "$T/t.txt")" = 500 ] &&
    awk '!/^#/ && (NF != 2 || $1 < 0 || $1 >= 1 || $2 < 0 || $2 >= 1) { bad = 1 }
        END { exit bad }' "$T/t.txt" &&
    ok "-T: 500 text lines in [0,1)" || nok "-T: 500 text lines in [0,1)"

hsw-sample -i const -n 500 --pdf -T -o "$T/pdf.txt"
head -n 1 "$T/pdf.txt" | grep -qx '#pts dims=2 extra=1 count=500 version=2 names=pdf' &&
    ok "--pdf header: the column named pdf" || nok "--pdf header: $(head -n 1 "$T/pdf.txt")"
hsw-sample -i const -n 500 --pdf -o "$T/pdf.pts"
[ "$(head -c 36 "$T/pdf.pts" | tail -c 4 | tr '\0' ' ')" = "pdf " ] &&
    [ "$(od -A n -t u4 -j 20 -N 4 "$T/pdf.pts" | tr -d ' ')" = 8 ] &&
    ok "--pdf binary: names block pdf" || nok "--pdf binary: names block"
awk '!/^#/ && ($3 < 0.999999 || $3 > 1.000001) { bad = 1 } END { exit bad }' "$T/pdf.txt" &&
    ok "--pdf of a constant map is 1" || nok "--pdf of a constant map is 1"
hsw-sample -i blob -n 500 --pdf -T | awk '!/^#/ { s += $3 } END { exit !(s > 500) }' &&
    ok "--pdf: points go where the density is high" ||
    nok "--pdf: points go where the density is high"

# A text point file as input: its points, warped by a constant map, back.
printf '0.25 0.5\n0.75 0.125\n0.5 0.875\n' >"$T/in.txt"
hsw-sample -i const -s 64x64 -n 3 --input "$T/in.txt" -T -o "$T/f.txt"
grep -v '^#' "$T/f.txt" | awk '{ printf "%.12f %.12f\n", $1, $2 }' >"$T/f.s"
awk '{ printf "%.12f %.12f\n", $1, $2 }' "$T/in.txt" >"$T/in.s"
cmp -s "$T/f.s" "$T/in.s" && ok "--input FILE, constant map: unchanged" ||
    nok "--input FILE, constant map: unchanged"
hsw-sample -i blob --input "$T/in.txt" -T -o "$T/f2.txt"
[ "$(grep -vc '^#' "$T/f2.txt")" = 3 ] && ok "--input FILE without -n: all its points" ||
    nok "--input FILE without -n: all its points"

hsw-sample -i blob -n 20000 -j 1 -o "$T/j1.pts"
hsw-sample -i blob -n 20000 -j 2 -o "$T/j2.pts"
cmp -s "$T/j1.pts" "$T/j2.pts" && ok "-j 1 and -j 2 give the same bytes" ||
    nok "-j 1 and -j 2 give the same bytes"
# Over several rounds of warping and writing (2^16 points) and chunks:
# thread counts, and a file of the points against the set made on the
# fly, give the same bytes, with the density column too.
hsw-sample -i blob -s 100x60 -n 300001 --pdf -j 1 -o "$T/r1.pts"
hsw-sample -i blob -s 100x60 -n 300001 --pdf -j 3 -o "$T/r3.pts"
cmp -s "$T/r1.pts" "$T/r3.pts" && ok "-n 300001 --pdf: -j 1 and -j 3 the same bytes" ||
    nok "-n 300001 --pdf: -j 1 and -j 3 the same bytes"
hsw-sample -i blob -n 300001 --input random -S 5 -o "$T/in.pts"
hsw-sample -i blob -n 300001 --input "$T/in.pts" -j 1 -o "$T/f1.pts"
hsw-sample -i blob -n 300001 --input "$T/in.pts" -j 3 -o "$T/f3.pts"
cmp -s "$T/f1.pts" "$T/f3.pts" && ok "--input FILE, 300001 points: -j 1 and -j 3 the same bytes" ||
    nok "--input FILE, 300001 points: -j 1 and -j 3 the same bytes"
hsw-sample -i blob -n 20000 --pdf -T -j 1 -o "$T/t1.txt"
hsw-sample -i blob -n 20000 --pdf -T -j 3 -o "$T/t3.txt"
cmp -s "$T/t1.txt" "$T/t3.txt" && ok "-T --pdf: -j 1 and -j 3 the same text" ||
    nok "-T --pdf: -j 1 and -j 3 the same text"
hsw-sample -i blob -n 100 --input random -S 2 -o "$T/s2.pts"
hsw-sample -i blob -n 100 --input random -S 3 -o "$T/s3.pts"
cmp -s "$T/s2.pts" "$T/s3.pts" && nok "-S changes random input" || ok "-S changes random input"

# Non-power-of-two map: points stay in the map.
check "100x60 map" hsw-sample -i blob -s 100x60 -n 1000 -T -o "$T/np.txt"
hsw-sample -i blob -s 100x60 -n 1000 -v -o /dev/null 2>"$T/v"
grep -q 'padded to 128x128' "$T/v" && grep -q 'warping' "$T/v" &&
    ok "-v: padding and warping time" || nok "-v: padding and warping time"

# --input dart: ref-sample's dart throwing, warped.
writes_points "--input dart: 500 points" 500 "$T/dart.pts" \
    hsw-sample -i blob -n 500 --input dart -S 3 -o "$T/dart.pts"

# Bad input.
expect_fail "all-zero map" 1 "zero everywhere" "$T/z.pts" \
    hsw-sample -i const:0 -n 10 -o "$T/z.pts"
expect_fail "-n 0" 2 "-n" "$T/n0.pts" hsw-sample -i blob -n 0 -o "$T/n0.pts"
expect_fail "missing -n" 2 "-n COUNT" - hsw-sample -i blob
expect_fail "missing -i" 2 "-i IMPORTANCE" - hsw-sample -n 10
expect_fail "unknown --input" 2 "sobol" "$T/u.pts" \
    hsw-sample -i blob -n 10 --input sobol -o "$T/u.pts"
expect_fail "missing input file" 1 "nonexistent.pts" "$T/m.pts" \
    hsw-sample -i blob -n 10 --input "$T/nonexistent.pts" -o "$T/m.pts"
expect_fail "input file too short" 1 "need 10" "$T/short.pts" \
    hsw-sample -i blob -n 10 --input "$T/in.txt" -o "$T/short.pts"
printf '0.5 1.5\n' >"$T/bad.txt"
expect_fail "input point outside the square" 1 "outside" - \
    hsw-sample -i blob --input "$T/bad.txt" -o /dev/null
expect_fail "missing map" 1 "nosuchmap" - hsw-sample -i "$T/nosuchmap.png" -n 10
expect_fail "write to /dev/full" 1 "/dev/full" - \
    hsw-sample -i blob -n 100000 -o /dev/full

# --equirect: the map's rows weighted by sin(theta) at load, as imap
# convert --equirect writes it: the points of the converted map (float
# pixels: equal to 1e-6), and not those of the map as it is.
imap convert --equirect -s 64x32 sky "$T/sky-eq.exr"
hsw-sample -i sky -s 64x32 --equirect -n 3000 --input random -T -o "$T/eq.txt"
hsw-sample -i "$T/sky-eq.exr" -n 3000 --input random -T -o "$T/conv.txt"
hsw-sample -i sky -s 64x32 -n 3000 --input random -T -o "$T/plain.txt"
maxdiff() {
	paste "$1" "$2" | awk '!/^#/ { d = $1 - $3; if (d < 0) d = -d; if (d > m) m = d
	    d = $2 - $4; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3g\n", m }'
}
awk -v a="$(maxdiff "$T/eq.txt" "$T/conv.txt")" -v b="$(maxdiff "$T/eq.txt" "$T/plain.txt")" \
    'BEGIN { exit !(a < 1e-6 && b > 1e-3) }' &&
    ok "--equirect: the points of imap convert --equirect's map" ||
    nok "--equirect: $(maxdiff "$T/eq.txt" "$T/conv.txt") from the converted map"
# A constant map over the sphere: density sin(pi y), so a share
# (1 - cos(pi/4)) / 2 = 0.1464 of the points above y = 1/4 (standard
# error 0.0011 for 100000 points).
hsw-sample -i const --equirect -n 100000 --input random -T |
    awk '!/^#/ { n++; if ($2 < 0.25) k++ } END { p = k / n; print p
	exit !(p > 0.1404 && p < 0.1524) }' >"$T/share" &&
    ok "--equirect, constant map: $(cat "$T/share") of the points above y = 1/4 (0.146)" ||
    nok "--equirect, constant map: $(cat "$T/share") above y = 1/4, not 0.146"
# --strict: a negative pixel is an error naming the map, no output; without
# it clamped with a warning.
expect_fail "--strict refuses negative importance" 1 "is negative" "$T/strict.pts" \
    hsw-sample --strict -i "$TD/interior.exr" -s 64x32 -n 100 -o "$T/strict.pts"
hsw-sample -i "$TD/interior.exr" -s 64x32 -n 100 -o "$T/clamped.pts" 2>"$T/err" &&
    grep -q "interior.exr: .*negative.*clamped" "$T/err" &&
    ok "negative importance without --strict: clamped, a warning" ||
    nok "negative importance without --strict: $(cat "$T/err")"

# --sets M: set i is the set of -S S+i, the records one after another,
# each followed by its set (the column named set), counted in the header.
# recs FILE NCOL: the records after the header and its names block.
recs() {
	tail -c +$((32 + $(od -A n -t u4 -j 20 -N 4 "$1" | tr -d ' ') + 1)) "$1" |
	    od -A n -t x8 -v -w$((8 * $2))
}
sethex() { case $1 in 0) echo 0000000000000000 ;; 1) echo 3ff0000000000000 ;;
	2) echo 4000000000000000 ;; esac; }
for a in "--input random" "--input jittered" "--input dart" "--input random --pdf"; do
	case $a in *pdf) nc=3 names="pdf set " ;; *) nc=2 names="set     " ;; esac
	# shellcheck disable=SC2086
	hsw-sample -i blob -s 64x64 $a -n 200 -S 5 --sets 3 -o "$T/sets.pts"
	: >"$T/cat.hex"
	for s in 5 6 7; do
		# shellcheck disable=SC2086
		hsw-sample -i blob -s 64x64 $a -n 200 -S $s -o "$T/one.pts"
		recs "$T/one.pts" $nc |
		    sed "s/\$/ $(sethex $((s - 5)))/" >>"$T/cat.hex"
	done
	if recs "$T/sets.pts" $((nc + 1)) | cmp -s - "$T/cat.hex" &&
	    [ "$(pts_count "$T/sets.pts")" = 600 ] &&
	    [ "$(head -c 40 "$T/sets.pts" | tail -c 8 | tr '\0' ' ')" = "$names" ]; then
		ok "$a --sets 3 -S 5: the sets of -S 5, 6, 7 and a set column, count 600"
	else
		nok "$a --sets 3 -S 5: the sets of -S 5, 6, 7 and a set column, count 600"
	fi
done
hsw-sample -i blob --input random -n 50 -S 2 --sets 2 -T -o "$T/sets.txt"
{ hsw-sample -i blob --input random -n 50 -S 2 -T | sed '/^#/d; s/$/ 0/'
  hsw-sample -i blob --input random -n 50 -S 3 -T | sed '/^#/d; s/$/ 1/'; } >"$T/cat.txt"
head -n 1 "$T/sets.txt" | grep -q '^#pts dims=2 extra=1 count=100 version=2 names=set$' &&
    grep -v '^#' "$T/sets.txt" | cmp -s - "$T/cat.txt" &&
    ok "--sets 2 -T: one header, count 100, the records of -S 2 and 3 and their set" ||
    nok "--sets 2 -T: $(head -n 1 "$T/sets.txt")"
hsw-sample -i blob --input random -n 300 -S 4 -o "$T/a.pts"
hsw-sample -i blob --input random -n 300 -S 4 --sets 1 -o "$T/b.pts"
cmp -s "$T/a.pts" "$T/b.pts" && ok "--sets 1 gives the same bytes" ||
    nok "--sets 1 gives the same bytes"
for i in halton regular hammersley "$T/in.txt"; do
	expect_fail "--sets 2 with --input $i, the same for every seed" 2 "every seed" \
	    "$T/o.pts" hsw-sample -i blob -n 3 --input "$i" --sets 2 -o "$T/o.pts"
done
expect_fail "--sets 0" 2 "--sets" "$T/o.pts" \
    hsw-sample -i blob -n 10 --input random --sets 0 -o "$T/o.pts"
expect_fail "--sets past 2^56 points in all" 2 "2^56" "$T/o.pts" \
    hsw-sample -i blob -n 4294967296 --input random --sets 33554432 -o "$T/o.pts"
expect_fail "--sets past seed 2^64-1" 2 "2^64-1" "$T/o.pts" \
    hsw-sample -i blob -n 10 --input random -S 18446744073709551614 --sets 3 -o "$T/o.pts"

# --device: OpenCL gives the CPU's bytes; device listing and errors.
if cl_run hsw-sample --list-devices >"$T/dev" 2>"$T/err"; then
	head -n 1 "$T/dev" | grep -q '^cl:0' && ok "--list-devices: cl:0 first" ||
	    nok "--list-devices: cl:0 first"
	for m in blob sky:sun=1e4 ramp:angle=30; do
		hsw-sample -i "$m" -n 30000 --device cpu -o "$T/cpu.pts"
		cl_run hsw-sample -i "$m" -n 30000 --device cl -o "$T/cl.pts"
		cmp -s "$T/cpu.pts" "$T/cl.pts" &&
		    ok "--device cl, $m: the CPU's bytes" ||
		    nok "--device cl, $m: the CPU's bytes"
	done
	cl_run hsw-sample -i blob -s 100x60 -n 300001 --pdf --device cl \
	    -o "$T/rcl.pts"
	cmp -s "$T/r1.pts" "$T/rcl.pts" &&
	    ok "--device cl, -n 300001 --pdf: the bytes of -j 1" ||
	    nok "--device cl, -n 300001 --pdf: the bytes of -j 1"
	cl_run hsw-sample -i blob -n 300001 --input "$T/in.pts" --device cl \
	    -o "$T/fcl.pts"
	cmp -s "$T/f1.pts" "$T/fcl.pts" &&
	    ok "--device cl, --input FILE: the bytes of -j 1" ||
	    nok "--device cl, --input FILE: the bytes of -j 1"
	hsw-sample -i blob -s 100x60 -n 5000 --input dart -S 4 --pdf -T \
	    --device cpu -o "$T/cpu.txt"
	cl_run hsw-sample -i blob -s 100x60 -n 5000 --input dart -S 4 --pdf -T \
	    --device cl:0 -o "$T/cl.txt"
	cmp -s "$T/cpu.txt" "$T/cl.txt" &&
	    ok "--device cl:0, 100x60, dart, --pdf -T: the CPU's text" ||
	    nok "--device cl:0, 100x60, dart, --pdf -T: the CPU's text"
	hsw-sample -i blob -n 3000 --input jittered -S 3 --sets 3 --pdf -o "$T/scpu.pts"
	cl_run hsw-sample -i blob -n 3000 --input jittered -S 3 --sets 3 --pdf \
	    --device cl -o "$T/scl.pts"
	cmp -s "$T/scpu.pts" "$T/scl.pts" &&
	    ok "--device cl --sets 3: the CPU's bytes" ||
	    nok "--device cl --sets 3: the CPU's bytes"
	cl_run hsw-sample -i blob -n 1000 --device cl -v -o /dev/null 2>"$T/v"
	grep -q 'kernel' "$T/v" && ok "-v --device cl: device times" ||
	    nok "-v --device cl: device times"
	expect_fail "--device cl:63" 1 "cl:63" "$T/d63.pts" \
	    cl_run hsw-sample -i blob -n 10 --device cl:63 -o "$T/d63.pts"
	for d in cl:64 cl:99; do
		expect_fail "--device $d: no such device" 1 "no device $d" "$T/d63.pts" \
		    cl_run hsw-sample -i blob -n 10 --device $d -o "$T/d63.pts"
	done
else
	grep -q 'no platform' "$T/err" && ok "--list-devices without a platform" ||
	    nok "--list-devices: $(head -n 1 "$T/err")"
fi
expect_fail "--device gpu" 2 "gpu" "$T/gpu.pts" \
    hsw-sample -i blob -n 10 --device gpu -o "$T/gpu.pts"
done_testing
