#!/bin/sh
# 3-D Forced Random Sampling: frs-sample with a 3-D matrix and an
# importance volume, imap's volumes (.frv), and their bad input.
. "$(dirname "$0")/lib.sh"

frd-gen -k 3 -s 16 --tol 1e-2 -o "$T/m3.frd"
M=$T/m3.frd
DATA=$(dirname "$0")/../data

check "blob3, 2000 samples" frs-sample -m "$M" -i blob3 -n 2000 -q -o "$T/a.pts"
dims=$(od -A n -t u4 -j 12 -N 4 "$T/a.pts" | tr -d ' ')
cnt=$(od -A n -t u8 -j 24 -N 8 "$T/a.pts" | tr -d ' ')
[ "$dims" = 3 ] && ok "3 coordinates a point" || nok "3 coordinates a point ($dims)"
[ "$cnt" -gt 1900 ] && [ "$cnt" -lt 2100 ] && ok "about n samples ($cnt)" ||
    nok "about n samples ($cnt)"
[ "$(wc -c <"$T/a.pts")" -eq $((32 + 24 * cnt)) ] && ok "binary .pts layout" ||
    nok "binary .pts layout"

# Same bytes for any thread count; naive and sorted give the same set.
frs-sample -m "$M" -i blob3 -n 3000 -q -j 1 -T -o "$T/j1.txt"
frs-sample -m "$M" -i blob3 -n 3000 -q -j 2 -T -o "$T/j2.txt"
cmp -s "$T/j1.txt" "$T/j2.txt" && ok "-j 1 and -j 2 give the same bytes" ||
    nok "-j 1 and -j 2 give the same bytes"
frs-sample -m "$M" -i blob3 -n 3000 -q -a naive -T | grep -v '^#' | sort >"$T/naive.s"
grep -v '^#' "$T/j1.txt" | sort >"$T/sorted.s"
cmp -s "$T/naive.s" "$T/sorted.s" && ok "naive and sorted give the same points" ||
    nok "naive and sorted give the same points"

# Density follows the volume: a z ramp from 0 to 1 puts the mean z at
# 2/3 (voxel centres of 32 slices: 0.66654), a constant one at 1/2.
frs-sample -m "$M" -i ramp3 -n 20000 -q -T -o "$T/ramp.txt"
mz=$(awk '!/^#/ { s += $3; n++ } END { printf "%.5f", s / n }' "$T/ramp.txt")
near "$mz" 0.66654 0.01 && ok "ramp3: mean z $mz" || nok "ramp3: mean z $mz"
# A constant volume: every slice along every axis gets n/8 of the points
# (where they sit inside a voxel is the matrix's business).
frs-sample -m "$M" -n 5000 -s 8 -q -T -o "$T/const.txt"
awk '!/^#/ { for (i = 1; i <= 3; i++) { if ($i < 0 || $i >= 1) bad = 1; c[i, int($i * 8)]++ }; n++ }
    END { for (i = 1; i <= 3; i++) for (b = 0; b < 8; b++)
        if (c[i, b] < 0.9 * n / 8 || c[i, b] > 1.1 * n / 8) bad = 1; exit bad }' \
    "$T/const.txt" && ok "const: points in the cube, n/8 a slice" ||
    nok "const: points in the cube, n/8 a slice"

# Columns: --pdf is I / mean I, progressive steps; the union of the steps
# is the one-shot set.
frs-sample -m "$M" -i const -n 500 --pdf -q -T -o "$T/pdf.txt"
head -n 1 "$T/pdf.txt" | grep -q 'dims=3 extra=1' &&
    awk '!/^#/ && ($4 < 0.999999 || $4 > 1.000001) { bad = 1 } END { exit bad }' "$T/pdf.txt" &&
    ok "--pdf of a constant volume is 1" || nok "--pdf of a constant volume is 1"
frs-sample -m "$M" -i blob3 --progressive 200,800,2000 -q -T -o "$T/prog.txt"
frs-sample -m "$M" -i blob3 -n 2000 -q -T -o "$T/one.txt"
awk '!/^#/ { print $1, $2, $3 }' "$T/prog.txt" | sort >"$T/prog.s"
grep -v '^#' "$T/one.txt" | sort >"$T/one.s"
cmp -s "$T/prog.s" "$T/one.s" && ok "progressive union equals one shot" ||
    nok "progressive union equals one shot"
frs-sample -m "$M" -i blob3 -n 1000 --jitter random -q -T -o "$T/jr.txt" &&
    frs-sample -m "$M" -i blob3 -n 1000 -q -T -o "$T/jn.txt" &&
    [ "$(grep -vc '^#' "$T/jr.txt")" = "$(grep -vc '^#' "$T/jn.txt")" ] &&
    ! cmp -s "$T/jr.txt" "$T/jn.txt" && ok "jitter moves points, keeps the count" ||
    nok "jitter moves points, keeps the count"
frs-sample -m "$M" -i blob3 -n 700 --sets 3 -q -T -o "$T/sets.txt" &&
    frs-sample -m "$M" -i blob3 -n 700 -S 2 -q -T -o "$T/s2.txt" &&
    sed '/^#/d; s/$/ 1/' "$T/s2.txt" >"$T/s2.s" &&
    head -n 1 "$T/sets.txt" | grep -qx '#pts dims=3 extra=1 count=0 version=2 names=set' &&
    awk '$4 == 1' "$T/sets.txt" | cmp -s - "$T/s2.s" &&
    ok "--sets: set 1 (the set column) is seed 2" || nok "--sets: set 1 is seed 2"
frs-sample -m "$M" -i blob3 --pdf --progressive 100,300 --sets 2 -q -T -o "$T/ps.txt" &&
    { frs-sample -m "$M" -i blob3 --pdf --progressive 100,300 -S 1 -q -T | sed '/^#/d; s/$/ 0/'
      frs-sample -m "$M" -i blob3 --pdf --progressive 100,300 -S 2 -q -T | sed '/^#/d; s/$/ 1/'
    } >"$T/ps1.txt" &&
    head -n 1 "$T/ps.txt" | grep -qx '#pts dims=3 extra=3 count=0 version=2 names=pdf,step,set' &&
    grep -v '^#' "$T/ps.txt" | cmp -s - "$T/ps1.txt" &&
    ok "--sets 2 --progressive: pdf, step and set columns" ||
    nok "--sets 2 --progressive: pdf, step and set columns"

# Count only past 2^32 window elements (n = 2^30 on a 2^3 volume).
n=$(frs-sample -m "$M" -i const -s 2 -n 1073741824 --count-only -q)
awk -v n="$n" 'BEGIN { exit !(n > 0.999 * 1073741824 && n < 1.001 * 1073741824) }' &&
    ok "--count-only at 2^30 ($n)" || nok "--count-only at 2^30 ($n)"
frs-sample -m "$M" -i blob3 -n 5000 2>"$T/warn" >/dev/null
grep -q 'repeat' "$T/warn" && ok "warning past the matrix's unique samples" ||
    nok "warning past the matrix's unique samples"
# Plain tiles repeat the matrix only where the window is larger than it,
# as in 2-D: a window of the matrix's size, wherever it lies, uses each
# element once (issue 32: -s 16x16x16 -n 1000 --sigma 4 gave a 64^3
# window of the shipped 64^3 matrix, at an offset, and warned).  The
# window is the volume's side times n_s: 4 x 4 at sigma 4 (16^3, the
# test matrix) and 5 x 4 (20^3), both below the unique samples.
for a in "-m $M -s 4x4x4 -n 50" "-s 16x16x16 -n 1000"; do
	frs-sample $a --sigma 4 -T -o "$T/tw.txt" 2>"$T/warn"
	[ $? -eq 0 ] && [ ! -s "$T/warn" ] &&
	    ok "no warning for a window the size of the matrix ($a)" ||
	    nok "a window the size of the matrix ($a): $(cat "$T/warn")"
done
frs-sample -m "$M" -s 5x5x5 -n 30 --sigma 4 --tiles plain -T -o "$T/tw.txt" 2>"$T/warn" &&
    grep -q '20x20x20' "$T/warn" &&
    ok "plain tiles: a 20^3 window of a 16^3 matrix warns" ||
    nok "plain tiles: a 20^3 window of a 16^3 matrix warns: $(cat "$T/warn")"

frs-sample -m "$M" -i blob3 -n 300 --sets 3 --count-only -q >"$T/counts"
[ "$(wc -l <"$T/counts")" = 3 ] && frs-sample -m "$M" -i blob3 -n 300 -S 2 --count-only -q |
    cmp -s - "$(sed -n 2p "$T/counts" >"$T/c2"; echo "$T/c2")" &&
    ok "--count-only --sets: a line per set" || nok "--count-only --sets: a line per set"

# The shipped 64^3 matrix is the default for volumes.
check "default 3-D matrix" frs-sample -i shell3 -n 300 -q -o "$T/d.pts"
# Uniform 3-D FRS sets are blue noise: the density rho (dda --density,
# FCC spacing) of three sets of 1024 at sigma 4 is near dart throwing's
# 0.70 (0.66 measured), far above random's 0.06 and jittered's 0.12.
for s in 1 2 3; do frs-sample -i const -n 1024 --sigma 4 -S $s -q -o "$T/u$s.pts"; done
rho=$(dda --density "$T/u1.pts" "$T/u2.pts" "$T/u3.pts" | awk -F '\t' '$1 == "mean" { print $4 }')
awk -v r="$rho" 'BEGIN { exit !(r > 0.55 && r < 0.75) }' &&
    ok "uniform 3-D FRS: density $rho in (0.55, 0.75)" ||
    nok "uniform 3-D FRS: density $rho not in (0.55, 0.75)"
[ "$(od -A n -t u4 -j 12 -N 4 "$T/d.pts" | tr -d ' ')" = 3 ] &&
    ok "default 3-D matrix: 3-D points" || nok "default 3-D matrix: 3-D points"

# imap volumes: gen, info, round trip through frs-sample.
check "imap gen blob3" imap gen blob3:sigma=0.2 -s 8x6x4 -o "$T/b.frv"
[ "$(wc -c <"$T/b.frv")" -eq $((32 + 4 * 8 * 6 * 4)) ] && ok ".frv size" || nok ".frv size"
imap info "$T/b.frv" >"$T/info"
[ "$(value depth "$T/info")" = 4 ] && [ "$(value voxels "$T/info")" = 192 ] &&
    ok "imap info of a volume" || nok "imap info of a volume"
imap info blob3:sigma=0.2 -s 8x6x4 >"$T/info2"
near "$(value mean "$T/info")" "$(value mean "$T/info2")" 1e-6 &&
    ok "the file holds the spec's values (float)" || nok "the file holds the spec's values (float)"
frs-sample -m "$M" -i "$T/b.frv" -n 800 -q -T -o "$T/f.txt" &&
    frs-sample -m "$M" -i blob3:sigma=0.2 -s 8x6x4 -n 800 -q -T -o "$T/g.txt" &&
    [ "$(grep -vc '^#' "$T/f.txt")" -gt 700 ] &&
    ok "sampling a .frv file" || nok "sampling a .frv file"
# Without -m the source says what it is, standard input too: a .frv
# there is sampled in 3-D on the shipped 3-D matrix, as the file is.
frs-sample -i - -n 800 -q -o "$T/in.pts" <"$T/b.frv" &&
    frs-sample -i "$T/b.frv" -n 800 -q -o "$T/file.pts" &&
    cmp -s "$T/in.pts" "$T/file.pts" &&
    [ "$(od -A n -t u4 -j 12 -N 4 "$T/in.pts" | tr -d ' ')" = 3 ] &&
    ok "a .frv on standard input, no -m: a volume" ||
    nok "a .frv on standard input, no -m: a volume"
# A default matrix that does not load says why, not that the map is of
# the other kind.
printf 'junk' >"$T/junk.frd"
expect_fail "FRS_MATRIX3 that does not load" 1 "junk.frd" "$T/o.pts" \
    env FRS_MATRIX3="$T/junk.frd" frs-sample -i blob3 -n 10 -o "$T/o.pts"
# -s WxH asks for a 2-D map: a volume where one is needed says so.
expect_fail "a volume spec with -s WxH" 1 "a procedural volume where a 2-D map is needed" \
    "$T/o.pts" frs-sample -i blob3 -s 8x8 -n 10 -o "$T/o.pts"
expect_fail "a .frv with -s WxH" 1 "a volume (.frv) where a 2-D map is needed" \
    "$T/o.pts" frs-sample -i "$T/b.frv" -s 8x8 -n 10 -o "$T/o.pts"
imap gen const -s 4 --format frv -o "$T/c.frv" && [ "$(wc -c <"$T/c.frv")" -eq 288 ] &&
    ok "imap gen const as a volume" || nok "imap gen const as a volume"

# Bad input: the message names the file or option, status 1 (2 for
# usage), no output left.
head -c 100 "$T/b.frv" >"$T/short.frv"
expect_fail "truncated .frv" 1 "short.frv" "$T/o.pts" frs-sample -m "$M" -i "$T/short.frv" -n 10 -o "$T/o.pts"
{ printf '\211FRV\r\n\032\n'; printf '\002\000\000\000'; tail -c +13 "$T/b.frv"; } >"$T/ver.frv"
expect_fail ".frv version 2" 1 "version 2" "$T/o.pts" frs-sample -m "$M" -i "$T/ver.frv" -n 10 -o "$T/o.pts"
{ head -c 12 "$T/b.frv"; printf '\000\000\000\000'; tail -c +17 "$T/b.frv"; } >"$T/zero.frv"
expect_fail ".frv of width 0" 1 "impossible size" "$T/o.pts" frs-sample -m "$M" -i "$T/zero.frv" -n 10 -o "$T/o.pts"
{ cat "$T/b.frv"; printf 'x'; } >"$T/long.frv"
expect_fail ".frv with trailing bytes" 1 "long.frv" "$T/o.pts" frs-sample -m "$M" -i "$T/long.frv" -n 10 -o "$T/o.pts"
# A NaN voxel (float 0x7fc00000) at voxel (1, 0, 0).
{ head -c 36 "$T/b.frv"; printf '\000\000\300\177'; tail -c +41 "$T/b.frv"; } >"$T/nan.frv"
expect_fail "NaN voxel" 1 "voxel (1, 0, 0) is NaN" "$T/o.pts" frs-sample -m "$M" -i "$T/nan.frv" -n 10 -o "$T/o.pts"
{ head -c 36 "$T/b.frv"; printf '\000\000\200\277'; tail -c +41 "$T/b.frv"; } >"$T/neg.frv"
frs-sample -m "$M" -i "$T/neg.frv" -n 10 -o "$T/o.pts" 2>"$T/err" && grep -q "1 negative voxels clamped" "$T/err" &&
    ok "a negative voxel is clamped with a warning" || nok "a negative voxel is clamped with a warning"
rm -f "$T/o.pts"
expect_fail "--strict: a negative voxel" 1 "voxel (1, 0, 0) is negative" "$T/o.pts" \
    frs-sample -m "$M" -i "$T/neg.frv" --strict -n 10 -o "$T/o.pts"
imap gen const:0 -s 4 -o "$T/z.frv"
expect_fail "all-zero volume" 1 "zero everywhere" "$T/o.pts" frs-sample -m "$M" -i "$T/z.frv" -n 10 -o "$T/o.pts"
expect_fail "a 2-D map for a 3-D matrix" 1 "a 2-D map where a volume is needed" "$T/o.pts" \
    frs-sample -m "$M" -i blob -n 10 -o "$T/o.pts"
expect_fail "a PNG for a 3-D matrix" 1 "not an importance volume" "$T/o.pts" \
    frs-sample -m "$M" -i "$DATA/sunset.exr" -n 10 -o "$T/o.pts"
expect_fail "-s WxH for a volume" 1 "give -s N or WxHxD" "$T/o.pts" frs-sample -m "$M" -s 4x4 -n 10 -o "$T/o.pts"
expect_fail "-s WxHxD for a 2-D matrix" 1 "2-D matrix" "$T/o.pts" \
    frs-sample -m "$DATA/default.frd" -i blob -s 4x4x4 -n 10 -o "$T/o.pts"
expect_fail "-s of another size than the file" 1 "not the 5x5x5" "$T/o.pts" \
    frs-sample -m "$M" -i "$T/b.frv" -s 5 -n 10 -o "$T/o.pts"
expect_fail "-a stack in 3-D" 1 "naive and sorted" "$T/o.pts" frs-sample -m "$M" -a stack -n 10 -o "$T/o.pts"
expect_fail "--device cl in 3-D" 1 "CPU only" "$T/o.pts" frs-sample -m "$M" --device cl -n 10 -o "$T/o.pts"
expect_fail "--equirect in 3-D" 1 "--equirect" "$T/o.pts" frs-sample -m "$M" --equirect -n 10 -o "$T/o.pts"
expect_fail "a volume into a 2-D matrix" 1 "2-D" "$T/o.pts" frs-sample -m "$DATA/default.frd" -i "$T/b.frv" -n 10 -o "$T/o.pts"
expect_fail "a count that would take hours" 1 "use a larger matrix" - \
    frs-sample -m "$M" -i const -s 1 -n 1099511627776 --count-only
expect_fail "3-D samples past FRS_MAX_MEM" 1 "above the memory limit" "$T/o.pts" \
    env FRS_MAX_MEM=1G frs-sample -m "$M" -n 80000000 -o "$T/o.pts"
expect_fail "ramp3 axis 1.5" 2 "ramp3:axis=1.5: axis: 1.5 is not 0 (x), 1 (y) or 2 (z)" "$T/o.pts" frs-sample -m "$M" -i ramp3:axis=1.5 -n 10 -o "$T/o.pts"
expect_fail "unknown volume parameter" 2 "unknown parameter" "$T/o.pts" frs-sample -m "$M" -i blob3:q=1 -n 10 -o "$T/o.pts"
expect_fail "imap gen blob3 as PNG" 2 "volume" "$T/v.png" imap gen blob3 -o "$T/v.png"
expect_fail "imap gen blob -s 4x4x4" 2 "volume size" "$T/v.png" imap gen blob -s 4x4x4 -o "$T/v.png"
expect_fail "imap convert of a volume" 2 "not converted" "$T/v.png" imap convert "$T/b.frv" "$T/v.png"
expect_fail "a value past float32" 1 "outside the float range" "$T/big.frv" imap gen const:1e300 -s 2 -o "$T/big.frv"
expect_fail "a value below float32" 1 "outside the float range" "$T/small.frv" imap gen const:1e-300 -s 2 -o "$T/small.frv"
expect_fail "imap gen blob3 -s 4x4" 2 "WxHxD" "$T/v.frv" imap gen blob3 -s 4x4 -o "$T/v.frv"
done_testing
