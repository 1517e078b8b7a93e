#!/bin/sh
# pts-render: size, where a dot lands, how dark it is, the importance
# background, colour by order, standard input and output, bad input.
. "$(dirname "$0")/lib.sh"

# Pixels of a binary PGM/PPM as "index value" lines, one per byte
# after the header ("P5\nW H\n255\n": HEAD bytes).
pixels() {
	od -An -v -tu1 -j "$2" "$1" | awk '{ for (i = 1; i <= NF; i++) print n++, $i }'
}

awk 'BEGIN { srand(1); for (i = 0; i < 1000; i++) printf "%.17g %.17g\n", rand(), rand() }' >"$T/X.txt"

# The issue's example, and the size of the result.
check "render over blob" pts-render -i blob "$T/X.txt" -o "$T/X.png"
imap info "$T/X.png" >"$T/info" 2>"$T/err"
[ "$(value width "$T/info")" = 512 ] && [ "$(value height "$T/info")" = 512 ] &&
    ok "default size 512x512" || nok "default size 512x512"
check "-s 300x200" pts-render -s 300x200 "$T/X.txt" -o "$T/s.png"
imap info "$T/s.png" >"$T/info" 2>"$T/err"
[ "$(value width "$T/info")" = 300 ] && [ "$(value height "$T/info")" = 200 ] &&
    ok "-s WxH gives that size" || nok "-s WxH gives that size"
check "-s 64" pts-render -s 64 "$T/X.txt" -o "$T/s64.png"
imap info "$T/s64.png" >"$T/info" 2>"$T/err"
[ "$(value width "$T/info")" = 64 ] && [ "$(value height "$T/info")" = 64 ] &&
    ok "-s N gives NxN" || nok "-s N gives NxN"
# An 8-bit grey PNG (IHDR: depth at byte 24, colour type at 25).
[ "$(od -An -tu1 -j24 -N2 "$T/X.png" | tr -s ' ')" = " 8 0" ] &&
    ok "8-bit grey PNG" || nok "8-bit grey PNG"

# Standard input ("-" or none) and standard output give the same bytes.
pts-render -i blob <"$T/X.txt" >"$T/stdio.png" 2>"$T/err" &&
    cmp -s "$T/X.png" "$T/stdio.png" &&
    ok "standard input to standard output" || nok "standard input to standard output"
pts-render -i blob - -o "$T/dash.png" <"$T/X.txt" 2>"$T/err" &&
    cmp -s "$T/X.png" "$T/dash.png" && ok "'-' is standard input" ||
    nok "'-' is standard input"

# One point at (0.25, 0.75): y grows downward, so on a 512x512 image the
# dot is centred at pixel coordinates (128, 384).  The netpbm output
# gives the pixels to od; its darkness has its centroid there, the
# darkest pixel touches it, and it adds up to pi r^2.
echo "0.25 0.75" >"$T/one.txt"
check "one point, PGM" pts-render -r 3 "$T/one.txt" -o "$T/one.pgm"
[ "$(head -c 15 "$T/one.pgm" | od -An -c | tr -d ' \n')" = 'P5\n512512\n255\n' ] &&
    ok "PGM header" || nok "PGM header"
pixels "$T/one.pgm" 15 | awk '
	{ d = 1 - $2 / 255; x = $1 % 512 + 0.5; y = int($1 / 512) + 0.5
	  s += d; sx += d * x; sy += d * y; n++
	  if (n == 1 || $2 < min) { min = $2; mx = x; my = y } }
	END { printf "n %d\ncx %.6f\ncy %.6f\nsum %.6f\nmx %g\nmy %g\n",
	    n, sx / s, sy / s, s, mx, my }' >"$T/stats"
[ "$(value n "$T/stats")" = 262144 ] && ok "PGM has 512x512 pixels" ||
    nok "PGM has 512x512 pixels"
near "$(value cx "$T/stats")" 128 1e-4 && near "$(value cy "$T/stats")" 384 1e-5 &&
    ok "dot centred at (128, 384)" ||
    nok "dot centred at (128, 384): $(value cx "$T/stats"), $(value cy "$T/stats")"
awk -v x="$(value mx "$T/stats")" -v y="$(value my "$T/stats")" 'BEGIN {
	exit !((x - 128) ^ 2 + (y - 384) ^ 2 < 9) }' &&
    ok "darkest pixel within the dot" || nok "darkest pixel within the dot"
near "$(value sum "$T/stats")" 28.2743339 0.01 &&
    ok "darkness of a dot of radius 3 is 9 pi" ||
    nok "darkness of a dot of radius 3 is 9 pi: $(value sum "$T/stats")"
# The PNG holds the same picture: same mean.
check "one point, PNG" pts-render -r 3 "$T/one.txt" -o "$T/one.png"
imap info "$T/one.png" >"$T/info" 2>"$T/err"
near "$(value mean "$T/info")" "$(awk -v s="$(value sum "$T/stats")" \
    'BEGIN { printf "%.12g", 1 - s / 262144 }')" 1e-9 &&
    ok "PNG and PGM agree" || nok "PNG and PGM agree"
# --format pnm to standard output is the same file.
pts-render -r 3 --format pnm "$T/one.txt" >"$T/one-stdout.pgm" 2>"$T/err" &&
    cmp -s "$T/one.pgm" "$T/one-stdout.pgm" && ok "--format pnm" ||
    nok "--format pnm"

# A binary .pts file with the same point: the same picture.
printf '\211PTS\r\n\032\n\001\000\000\000\002\000\000\000\000\000\000\000\000\000\000\000\001\000\000\000\000\000\000\000\000\000\000\000\000\000\320\077\000\000\000\000\000\000\350\077' \
    >"$T/one.pts"
pts-render -r 3 "$T/one.pts" -o "$T/one-bin.pgm" 2>"$T/err" &&
    cmp -s "$T/one.pgm" "$T/one-bin.pgm" && ok "binary .pts input" ||
    { nok "binary .pts input"; sed 's/^/# /' "$T/err"; }
# Three coordinates: the first two are drawn.
echo "0.25 0.75 0.5" >"$T/three.txt"
pts-render -r 3 "$T/three.txt" -o "$T/three.pgm" 2>"$T/err" &&
    cmp -s "$T/one.pgm" "$T/three.pgm" && ok "3-D points draw x, y" ||
    nok "3-D points draw x, y"

# --axes: which two coordinates of a 3-D set are drawn, across and down.
# The point (0.25, 0.9, 0.75) seen along y (xz) is the dot of one.txt.
echo "0.25 0.9 0.75" >"$T/xz1.txt"
pts-render -r 3 --axes xz "$T/xz1.txt" -o "$T/xz1.pgm" 2>"$T/err" &&
    cmp -s "$T/one.pgm" "$T/xz1.pgm" && ok "--axes xz: the dot at (x, z)" ||
    nok "--axes xz: the dot at (x, z)"
echo "0.9 0.25 0.75" >"$T/yz1.txt"
pts-render -r 3 --axes yz "$T/yz1.txt" -o "$T/yz1.pgm" 2>"$T/err" &&
    cmp -s "$T/one.pgm" "$T/yz1.pgm" && ok "--axes yz: the dot at (y, z)" ||
    nok "--axes yz: the dot at (y, z)"
# A random 3-D set against 2-D files of the coordinates drawn: the same
# PNG bytes, with --color (order) and a map.
awk 'BEGIN { srand(3); for (i = 0; i < 500; i++)
	printf "%.17g %.17g %.17g\n", rand(), rand(), rand() }' >"$T/X3.txt"
for ax in xy xz yz; do
	case $ax in xy) c='$1, $2' ;; xz) c='$1, $3' ;; yz) c='$2, $3' ;; esac
	awk "{ print $c }" "$T/X3.txt" >"$T/X3$ax.txt"
	pts-render --color -i blob --axes $ax "$T/X3.txt" -o "$T/a3.png" 2>"$T/err" &&
	    pts-render --color -i blob "$T/X3$ax.txt" -o "$T/b3.png" 2>>"$T/err" &&
	    cmp -s "$T/a3.png" "$T/b3.png" && ok "--axes $ax = the 2-D file of those columns" ||
	    nok "--axes $ax = the 2-D file of those columns"
done
cmp -s "$T/X3xy.txt" "$T/X3xz.txt" && nok "--axes: the test files differ" ||
    ok "--axes: the test files differ"
pts-render --axes xy "$T/X3.txt" -o "$T/a3.png" 2>"$T/err" &&
    pts-render "$T/X3.txt" -o "$T/b3.png" 2>>"$T/err" && cmp -s "$T/a3.png" "$T/b3.png" &&
    ok "--axes xy is the default" || nok "--axes xy is the default"

# The default radius scales with the width: 1.5 at 512, 3 at 1024, so
# the darkness grows 4 times.
pts-render -s 1024 "$T/one.txt" -o "$T/big.pgm" 2>"$T/err" &&
    pts-render "$T/one.txt" -o "$T/small.pgm" 2>"$T/err" &&
    a=$(pixels "$T/small.pgm" 15 | awk '{ s += 1 - $2 / 255 } END { print s }') &&
    b=$(pixels "$T/big.pgm" 17 | awk '{ s += 1 - $2 / 255 } END { print s }') &&
    near "$a" 7.0685835 0.02 && near "$b" 28.2743339 0.01 &&
    ok "default radius 1.5 * W / 512" || nok "default radius 1.5 * W / 512 ($a, $b)"

# The default radius follows the local spacing: a dense set (about one
# point per 4 square pixels in the middle of a 1024x512 picture, random
# within a 2-pixel grid) is dark, most pixels below half grey, but no
# solid blob, as it is with a fixed radius of 3 (-r 3, the default
# before), and a sparse set keeps the radius 1.5 * W / 512 (the same
# bytes as -r with it).
awk 'BEGIN { srand(7); for (j = 0; j < 128; j++) for (i = 0; i < 256; i++)
	printf "%.17g %.17g\n", 0.25 + (i + rand()) / 512, 0.25 + (j + rand()) / 256 }' \
    >"$T/dense.txt"
# dark FILE: the fraction of pixels below 128 in [384, 640) x [160, 352).
dark() {
	pixels "$1" 17 | awk '{ x = $1 % 1024; y = int($1 / 1024)
	    if (x >= 384 && x < 640 && y >= 160 && y < 352) { n++; d += $2 < 128 } }
	    END { printf "%.4f\n", d / n }'
}
pts-render -s 1024x512 -r 3 "$T/dense.txt" -o "$T/dense3.pgm" 2>"$T/err" &&
    pts-render -s 1024x512 "$T/dense.txt" -o "$T/densed.pgm" 2>>"$T/err" &&
    d3=$(dark "$T/dense3.pgm") && dd=$(dark "$T/densed.pgm") &&
    awk -v a="$d3" -v b="$dd" 'BEGIN { exit !(a > 0.99 && b < 0.9 && b > 0.5) }' &&
    ok "dense set: default radius $dd dark, not solid as -r 3 ($d3)" ||
    nok "dense set: default radius ${dd:-?} dark, not solid as -r 3 (${d3:-?})"
pts-render "$T/X.txt" -o "$T/sparse.pgm" 2>"$T/err" &&
    pts-render -r 1.5 "$T/X.txt" -o "$T/sparse15.pgm" 2>>"$T/err" &&
    cmp -s "$T/sparse.pgm" "$T/sparse15.pgm" &&
    ok "sparse set: default radius 1.5 at 512" ||
    nok "sparse set: default radius 1.5 at 512"
# Dots shrink only where dense: a sparse point next to the dense patch
# keeps its full dot (its darkness 9 pi), wherever the file puts it.
{ echo "0.05 0.5"; cat "$T/dense.txt"; } >"$T/mixed.txt"
pts-render -s 1024x512 "$T/mixed.txt" -o "$T/mixed.pgm" 2>"$T/err" &&
    s=$(pixels "$T/mixed.pgm" 17 | awk '{ x = $1 % 1024; y = int($1 / 1024)
	if (x < 100 && y > 200 && y < 312) s += 1 - $2 / 255 } END { print s }') &&
    near "$s" 28.2743339 0.01 && ok "a lone point keeps radius 3 at 1024" ||
    nok "a lone point keeps radius 3 at 1024 (${s:-?})"

# Denser looks darker (issue 32): the mean darkness, 1 - v/255, of
# jittered grids of spacing 8, 4, 2 and 1 pixels, one in each quarter of
# a 512x512 picture (away from their edges), grows with the density by
# a tenth at least each time, and the densest is dark.
# jgrid X0 Y0 SIDE G [SEED]: points jittered within a G-pixel grid over
# the SIDE-pixel square at (X0, Y0) of a 512x512 picture.
jgrid() {
	awk -v x0="$1" -v y0="$2" -v side="$3" -v g="$4" -v seed="${5:-3}" \
	    'BEGIN { srand(seed); m = side / g
	    for (j = 0; j < m; j++) for (i = 0; i < m; i++)
		printf "%.17g %.17g\n", (x0 + (i + rand()) * g) / 512,
		    (y0 + (j + rand()) * g) / 512 }'
}
# darkness FILE X0 Y0 X1 Y1 [CX CY RMIN]: mean darkness of the PGM
# (512 wide) over [X0, X1) x [Y0, Y1), only at distances of RMIN or more
# from (CX, CY) if given.
darkness() {
	pixels "$1" 15 | awk -v x0="$2" -v y0="$3" -v x1="$4" -v y1="$5" \
	    -v cx="${6:-0}" -v cy="${7:-0}" -v rmin="${8:-0}" '{
		x = $1 % 512; y = int($1 / 512)
		if (x < x0 || x >= x1 || y < y0 || y >= y1) next
		if ((x + 0.5 - cx) ^ 2 + (y + 0.5 - cy) ^ 2 < rmin ^ 2) next
		n++; d += 1 - $2 / 255 }
	    END { printf "%.4f\n", d / n }'
}
{ jgrid 0 0 256 8; jgrid 256 0 256 4; jgrid 0 256 256 2; jgrid 256 256 256 1; } \
    >"$T/grids.txt"
pts-render "$T/grids.txt" -o "$T/grids.pgm" 2>"$T/err" &&
    d8=$(darkness "$T/grids.pgm" 32 32 224 224) &&
    d4=$(darkness "$T/grids.pgm" 288 32 480 224) &&
    d2=$(darkness "$T/grids.pgm" 32 288 224 480) &&
    d1=$(darkness "$T/grids.pgm" 288 288 480 480) &&
    awk -v a="$d8" -v b="$d4" -v c="$d2" -v d="$d1" \
	'BEGIN { exit !(a + 0.1 < b && b + 0.1 < c && c + 0.1 < d && d > 0.8) }' &&
    ok "denser is darker: spacing 8, 4, 2, 1 px: $d8 < $d4 < $d2 < $d1" ||
    nok "denser is darker: spacing 8, 4, 2, 1 px: ${d8:-?}, ${d4:-?}, ${d2:-?}, ${d1:-?}"
# A pile of points does not lighten the points around it (it once made
# a light square box of tiny dots around the sun): the square of 25
# pixels around a pile of 2000 points amid a 2-pixel grid, less the 3
# pixels next to the pile, is as dark as the same square of the same
# grid without the pile.
{ jgrid 0 128 256 2; jgrid 256 128 256 2 5
  awk 'BEGIN { srand(9); for (k = 0; k < 2000; k++)
	printf "%.17g %.17g\n", (127 + 2 * rand()) / 512, (255 + 2 * rand()) / 512 }'
} >"$T/pile.txt"
pts-render "$T/pile.txt" -o "$T/pile.pgm" 2>"$T/err" &&
    dp=$(darkness "$T/pile.pgm" 116 244 141 269 128.5 256.5 3) &&
    dn=$(darkness "$T/pile.pgm" 372 244 397 269 384.5 256.5 3) &&
    awk -v a="$dp" -v b="$dn" 'BEGIN { d = a - b; exit !(d < 0.05 && d > -0.05) }' &&
    ok "a pile leaves its surroundings as dark: $dp, without it $dn" ||
    nok "a pile leaves its surroundings as dark: ${dp:-?}, without it ${dn:-?}"
# The issue's picture: around the sun of sunset.exr, where the samples
# are densest, the picture is dark, far darker than at its sparse foot.
frs-sample -q -i "$TD/sunset.exr" --equirect -n 16384 -T >"$T/sun.txt" 2>"$T/err" &&
    pts-render -i "$TD/sunset.exr" --equirect --log "$T/sun.txt" \
	-o "$T/sun.pgm" 2>>"$T/err" &&
    set -- $(awk '!/^#/ { k = int($1 * 512) " " int($2 * 512)
	if (++c[k] > m) { m = c[k]; at = k } } END { print at }' "$T/sun.txt") &&
    ds=$(darkness "$T/sun.pgm" $(($1 - 12)) $(($2 - 12)) $(($1 + 13)) $(($2 + 13))) &&
    df=$(darkness "$T/sun.pgm" 0 448 512 512) &&
    awk -v s="$ds" -v f="$df" 'BEGIN { exit !(s > 0.7 && s > f + 0.4) }' &&
    ok "sunset: around the sun $ds dark, the foot $df" ||
    nok "sunset: around the sun ${ds:-?} dark, the foot ${df:-?}"

# --alpha: a pixel under one dot at opacity 0.5 is half way between the
# background and the ink: 255 -> 128 on white, 175 -> 88 over the
# maximum of a map, and (128, 128, 255) for a blue dot on white.
centre() { od -An -tu1 -j "$(($2 + $3 * (64 * 32 + 32)))" -N"$3" "$1" | tr -s ' '; }
echo "0.5 0.5" >"$T/mid.txt"
pts-render -s 64 -r 8 --alpha 0.5 "$T/mid.txt" -o "$T/a.pgm" 2>"$T/err" &&
    [ "$(centre "$T/a.pgm" 13 1)" = " 128" ] &&
    ok "--alpha 0.5 on white: 128" || nok "--alpha 0.5 on white: $(centre "$T/a.pgm" 13 1)"
pts-render -s 64 -r 8 --alpha 0.5 -i const:1 "$T/mid.txt" -o "$T/ai.pgm" 2>"$T/err" &&
    [ "$(centre "$T/ai.pgm" 13 1)" = " 88" ] &&
    ok "--alpha 0.5 over grey 175: 88" || nok "--alpha 0.5 over grey 175: $(centre "$T/ai.pgm" 13 1)"
pts-render -s 64 -r 8 --alpha 0.5 --color "$T/mid.txt" -o "$T/ac.ppm" 2>"$T/err" &&
    [ "$(centre "$T/ac.ppm" 13 3)" = " 128 128 255" ] &&
    ok "--alpha 0.5 --color: (128, 128, 255)" ||
    nok "--alpha 0.5 --color: $(centre "$T/ac.ppm" 13 3)"
# Two dots over each other at 0.5: 255 -> 128 -> 64.
printf '0.5 0.5\n0.5 0.5\n' >"$T/mid2.txt"
pts-render -s 64 -r 8 --alpha 0.5 "$T/mid2.txt" -o "$T/a2.pgm" 2>"$T/err" &&
    [ "$(centre "$T/a2.pgm" 13 1)" = " 64" ] &&
    ok "--alpha 0.5 twice: 64" || nok "--alpha 0.5 twice: $(centre "$T/a2.pgm" 13 1)"
# --alpha 1 is the default, byte for byte; 0 draws nothing.
pts-render --alpha 1 -i blob "$T/X.txt" -o "$T/a1.png" 2>"$T/err" &&
    cmp -s "$T/X.png" "$T/a1.png" && ok "--alpha 1 is the default" ||
    nok "--alpha 1 is the default"
pts-render --alpha 0 "$T/X.txt" -o "$T/a0.pgm" 2>"$T/err" &&
    [ "$(pixels "$T/a0.pgm" 15 | awk '$2 != 255' | wc -l)" -eq 0 ] &&
    ok "--alpha 0 leaves white" || nok "--alpha 0 leaves white"

# The importance background: white for zero, 255 - 80 at the maximum.
# A tiny dot in a corner leaves the background as it is.
echo "0.001 0.001" >"$T/corner.txt"
check "-i blob" pts-render -i blob -r 0.01 "$T/corner.txt" -o "$T/bg.png"
imap info "$T/bg.png" >"$T/info" 2>"$T/err"
near "$(value min "$T/info")" 0.68627451 1e-8 && near "$(value max "$T/info")" 1 1e-12 &&
    ok "background from white to 175/255" || nok "background from white to 175/255"
awk -v m="$(value mean "$T/info")" 'BEGIN { exit !(m < 0.97) }' &&
    ok "blob background darkens the mean" || nok "blob background darkens the mean"
pts-render -i blob -s 100 -r 0.01 "$T/corner.txt" -o "$T/bg100.png" 2>"$T/err" &&
    imap info "$T/bg100.png" >"$T/info" && [ "$(value width "$T/info")" = 100 ] &&
    ok "background resampled to the image size" ||
    nok "background resampled to the image size"
# A zero map is fine: white.
pts-render -i const:0 -r 0.01 "$T/corner.txt" -o "$T/zero.png" 2>"$T/err" &&
    imap info "$T/zero.png" >"$T/info" && [ "$(value min "$T/info")" = 1 ] &&
    ok "zero map gives white" || nok "zero map gives white"
# --log: the positive range onto 254 .. 175.
pts-render -i 'ramp:from=1,to=1000' --log -r 0.01 "$T/corner.txt" -o "$T/log.png" \
    2>"$T/err" && imap info "$T/log.png" >"$T/info" &&
    near "$(value min "$T/info")" 0.68627451 1e-8 &&
    near "$(value max "$T/info")" 0.996078431 1e-8 &&
    ok "--log spans 254/255 to 175/255" || nok "--log spans 254/255 to 175/255"
# An importance map from a file.
imap gen blob -s 64 -o "$T/blob.exr" 2>"$T/err" &&
    pts-render -i "$T/blob.exr" -r 0.01 "$T/corner.txt" -o "$T/bgexr.png" 2>"$T/err" &&
    imap info "$T/bgexr.png" >"$T/info" &&
    near "$(value min "$T/info")" 0.68627451 1e-8 &&
    ok "importance map from an EXR file" || nok "importance map from an EXR file"

# --color: RGB, first point blue, last red, over the background.
printf '0.28125 0.5625\n0.71875 0.5625\n' >"$T/two.txt"
check "--color" pts-render --color -i blob "$T/X.txt" -o "$T/c.png"
[ "$(od -An -tu1 -j24 -N2 "$T/c.png" | tr -s ' ')" = " 8 2" ] &&
    ok "--color gives 8-bit RGB" || nok "--color gives 8-bit RGB"
check "--color PPM" pts-render --color -s 16x8 -r 1.5 "$T/two.txt" -o "$T/two.ppm"
# Header "P6\n16 8\n255\n" is 12 bytes; pixel (i, j) at 12 + 3 (16 j + i).
[ "$(od -An -tu1 -j $((12 + 3 * (16 * 4 + 4))) -N3 "$T/two.ppm" | tr -s ' ')" = " 0 0 255" ] &&
    ok "first point blue" || nok "first point blue"
[ "$(od -An -tu1 -j $((12 + 3 * (16 * 4 + 11))) -N3 "$T/two.ppm" | tr -s ' ')" = " 255 0 0" ] &&
    ok "last point red" || nok "last point red"
[ "$(od -An -tu1 -j 12 -N3 "$T/two.ppm" | tr -s ' ')" = " 255 255 255" ] &&
    ok "--color background white" || nok "--color background white"

# Help and version.
pts-render -h >"$T/out" 2>&1 && grep -q "^usage: pts-render" "$T/out" &&
    ok "-h" || nok "-h"
pts-render --version >"$T/out" 2>&1 && grep -q "^pts-render (frs)" "$T/out" &&
    ok "--version" || nok "--version"

# Bad input: exit 1, file and problem named, no output left behind.
expect_fail "missing file" 1 "nothere.txt: No such file" "$T/o1.png" \
    pts-render "$T/nothere.txt" -o "$T/o1.png"
expect_fail "not a point file" 1 "X.png: not a point file" "$T/o2.png" \
    pts-render "$T/X.png" -o "$T/o2.png"
printf '0.1 0.2\n0.3 0.4\n1.5 0.5\n' >"$T/bad.txt"
expect_fail "coordinate 1.5" 1 "bad.txt:3: coordinate 1 is 1.5, outside [0,1)" \
    "$T/o3.png" pts-render "$T/bad.txt" -o "$T/o3.png"
printf '0.1\n0.2\n' >"$T/d1.txt"
expect_fail "1-D points" 1 "d1.txt: points have 1 coordinate, need 2" "$T/o4.png" \
    pts-render "$T/d1.txt" -o "$T/o4.png"
expect_fail "1-D points on standard input" 1 \
    "<stdin>: points have 1 coordinate, need 2" "$T/o4b.png" \
    sh -c 'pts-render -o "$1" <"$2"' sh "$T/o4b.png" "$T/d1.txt"
: >"$T/empty.txt"
expect_fail "empty file" 1 "empty.txt: empty file" "$T/o5.png" \
    pts-render "$T/empty.txt" -o "$T/o5.png"
expect_fail "-s 0" 2 "-s" "$T/o6.png" pts-render -s 0 "$T/X.txt" -o "$T/o6.png"
expect_fail "-s 12x" 2 "-s" "$T/o7.png" pts-render -s 12x "$T/X.txt" -o "$T/o7.png"
expect_fail "-s too many pixels" 2 "-s" "$T/o8.png" \
    pts-render -s 65536x65536 "$T/X.txt" -o "$T/o8.png"
expect_fail "-r 0" 2 "-r" "$T/o9.png" pts-render -r 0 "$T/X.txt" -o "$T/o9.png"
expect_fail "-r junk" 2 "-r" "$T/o10.png" pts-render -r 1x "$T/X.txt" -o "$T/o10.png"
expect_fail "--alpha 1.5" 2 "--alpha: 1.5 is out of range [0, 1]" "$T/oa1.png" \
    pts-render --alpha 1.5 "$T/X.txt" -o "$T/oa1.png"
expect_fail "--alpha -0.1" 2 "--alpha: -0.1 is out of range [0, 1]" "$T/oa2.png" \
    pts-render --alpha -0.1 "$T/X.txt" -o "$T/oa2.png"
expect_fail "--alpha junk" 2 "--alpha: 'half' is not a number" "$T/oa3.png" \
    pts-render --alpha half "$T/X.txt" -o "$T/oa3.png"
expect_fail "--alpha nan" 2 "--alpha: nan is not a finite number" "$T/oa4.png" \
    pts-render --alpha nan "$T/X.txt" -o "$T/oa4.png"
expect_fail "--alpha empty" 2 "--alpha: empty value" "$T/oa5.png" \
    pts-render --alpha '' "$T/X.txt" -o "$T/oa5.png"
expect_fail "unknown option" 2 "usage" "$T/o11.png" \
    pts-render --frobnicate "$T/X.txt" -o "$T/o11.png"
expect_fail "two inputs" 2 "one point file" "$T/o12.png" \
    pts-render "$T/X.txt" "$T/X.txt" -o "$T/o12.png"
expect_fail "--axes xz of a 2-D set" 1 "X.txt: --axes xz: points have 2 coordinates" \
    "$T/o18.png" pts-render --axes xz "$T/X.txt" -o "$T/o18.png"
expect_fail "--axes yz of a 2-D set" 1 "one.txt: --axes yz" "$T/o19.png" \
    pts-render --axes yz "$T/one.txt" -o "$T/o19.png"
expect_fail "--axes zx" 2 "--axes: 'zx' is not xy, xz or yz" "$T/o20.png" \
    pts-render --axes zx "$T/X3.txt" -o "$T/o20.png"
expect_fail "--format bmp" 2 "--format" "$T/o13.png" \
    pts-render --format bmp "$T/X.txt" -o "$T/o13.png"
expect_fail "--log without -i" 2 "need -i" "$T/o14.png" \
    pts-render --log "$T/X.txt" -o "$T/o14.png"
expect_fail "both on standard input" 2 "standard input" "$T/o15.png" \
    pts-render -i - - -o "$T/o15.png"
expect_fail "bad importance map" 2 "unknown parameter" "$T/o16.png" \
    pts-render -i blob:radius=3 "$T/X.txt" -o "$T/o16.png"
expect_fail "missing importance file" 1 "nothere.exr" "$T/o17.png" \
    pts-render -i "$T/nothere.exr" "$T/X.txt" -o "$T/o17.png"
expect_fail "full disk" 1 "/dev/full" - pts-render "$T/X.txt" -o /dev/full
expect_fail "full disk, PNM" 1 "/dev/full" - pts-render -s 100 "$T/X.txt" \
    --format pnm -o /dev/full
expect_fail "missing directory" 1 "$T/no/dir/x.png: cannot create" "$T/no/dir/x.png" \
    pts-render "$T/X.txt" -o "$T/no/dir/x.png"
# A failed run leaves an existing file as it was.
cp "$T/X.png" "$T/keep.png"
pts-render "$T/bad.txt" -o "$T/keep.png" 2>/dev/null
cmp -s "$T/X.png" "$T/keep.png" && ok "failed run keeps the old file" ||
    nok "failed run keeps the old file"

# Binary output to a terminal is refused (script(1) gives a pty).
if command -v script >/dev/null 2>&1; then
	script -qec "pts-render '$T/X.txt'" /dev/null >"$T/tty" 2>&1
	grep -q "refusing to write binary data to a terminal" "$T/tty" &&
	    ok "no PNG on a terminal" || nok "no PNG on a terminal"
fi

# --set K: one set of a stream with a set column (frs-sample --sets 4),
# the image of the seed that made it; or the K-th run of --sets N points
# of an old file without one.
frs-sample -q -i blob -n 300 --sets 4 | pts-render --set 2 -o "$T/set2.png" &&
    frs-sample -q -i blob -n 300 -S 3 | pts-render -o "$T/seed3.png" &&
    cmp -s "$T/set2.png" "$T/seed3.png" && ok "--set 2 of a --sets 4 stream = -S 3" ||
    nok "--set 2 of a --sets 4 stream"
frs-sample -q -i blob -n 300 --sets 4 | pts-render --color --set 0 -o "$T/set0.png" &&
    frs-sample -q -i blob -n 300 | pts-render --color -o "$T/seed1.png" &&
    cmp -s "$T/set0.png" "$T/seed1.png" && ok "--set 0 --color: the ramp over the set" ||
    nok "--set 0 --color"
ref-sample -q -k halton -n 64 --sets 3 -T | awk '!/^#/ { print $1, $2 }' >"$T/old.txt"
ref-sample -q -k halton -n 64 -S 2 | pts-render -o "$T/h2.png"
pts-render --sets 64 --set 1 -o "$T/old1.png" "$T/old.txt" 2>"$T/err" &&
    cmp -s "$T/old1.png" "$T/h2.png" &&
    grep -q "^pts-render: warning: $T/old.txt: no set column: cut in file order into 3 sets of 64" "$T/err" &&
    ok "--sets 64 --set 1 of a file without a set column: its block, a warning naming the file" ||
    nok "--sets 64 --set 1: $(cat "$T/err")"
# A set column of sets of 300 beside --sets 100: its set 1, a warning.
ref-sample -q -k halton -n 300 --sets 3 -o "$T/h3.pts"
ref-sample -q -k halton -n 300 -S 2 | pts-render -o "$T/h300.png"
pts-render --sets 100 --set 1 -o "$T/h31.png" "$T/h3.pts" 2>"$T/err" &&
    cmp -s "$T/h31.png" "$T/h300.png" &&
    grep -q "^pts-render: warning: $T/h3.pts: .*set column have 300 points, not 100" "$T/err" &&
    ok "--sets 100 beside a set column of 300: its set, a warning" ||
    nok "--sets 100 beside a set column: $(cat "$T/err")"
expect_fail "--set without a set column" 1 "old.txt: --set 1: the points have no set column" \
    "$T/o.png" pts-render --set 1 -o "$T/o.png" "$T/old.txt"
expect_fail "--set past the sets" 1 "old.txt: --set 3: the file has 3 sets of 64 points" \
    "$T/o.png" pts-render --sets 64 --set 3 -o "$T/o.png" "$T/old.txt"
expect_fail "--set of no point" 1 "--set 9: no point has that set" "$T/o.png" \
    sh -c "frs-sample -q -n 100 --sets 4 | pts-render --set 9 -o '$T/o.png'"
expect_fail "--sets without --set" 2 "--set K" "$T/o.png" \
    pts-render --sets 64 -o "$T/o.png" "$T/old.txt"
# --strict, as in frs-sample: negative importance in the map an error
# naming it, no picture; without it clamped with a warning.
expect_fail "--strict refuses negative importance" 1 "is negative" "$T/st.png" \
    pts-render --strict -i "$TD/interior.exr" -s 64x32 -o "$T/st.png" "$T/X.txt"
pts-render -i "$TD/interior.exr" -s 64x32 -o "$T/cl.png" "$T/X.txt" 2>"$T/err" &&
    grep -q "interior.exr: .*negative.*clamped" "$T/err" &&
    ok "negative importance without --strict: clamped, a warning" ||
    nok "negative importance without --strict: $(cat "$T/err")"
expect_fail "--strict without -i" 2 "need -i" "$T/st.png" \
    pts-render --strict -o "$T/st.png" "$T/X.txt"
done_testing
