#!/bin/sh
# The numerical hard cases through the programs: counts of 2^24 and 2^40
# (64-bit window math), maps scaled to denormals, degenerate maps and
# matrices, discrepancy and density closed forms at the edges of the unit
# square.  Every check compares a value with an oracle given beside it.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../ptsutil.sh"

# within COUNT N: |COUNT - N| <= 5 sqrt(N) + 2 (binomial, 5 sd)
within() {
	awk -v c="$1" -v n="$2" 'BEGIN { d = c - n; if (d < 0) d = -d
		exit !(d <= 5 * sqrt(n) + 2) }'
}
# col N FILE: field N of the second line of a tab-separated table
col() { awk -F '\t' -v k="$1" 'NR == 2 { print $k }' "$2"; }
# rel A B TOL: |A - B| <= TOL |B|
rel() {
	awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d
		if (b < 0) b = -b; exit !(d <= t * b) }'
}
# in_unit FILE: every point of a text .pts lies in [0,1)^2 and is a number
in_unit() {
	awk '!/^#/ { if (!($1 >= 0 && $1 < 1 && $2 >= 0 && $2 < 1)) bad = 1; k++ }
	    END { exit bad || k == 0 }' "$1"
}

# A 64x64 permutation (v = 37 (x + 64 y) mod 4096, 37 odd) as text,
# imported: a small matrix made in no time.
awk 'BEGIN { for (y = 0; y < 64; y++) { s = ""
	for (x = 0; x < 64; x++) s = s (x ? " " : "") (37 * (x + 64 * y)) % 4096
	print s } }' >"$T/m64.txt"
frd-prep --import text "$T/m64.txt" -o "$T/m64.frd" 2>"$T/err"
M=$T/m64.frd

# ---- 64-bit window math: 2^24 and 2^40 with the shipped 2048^2 matrix ----
# Constant 128^2 map: n_s 256 (2^24) or 65536 (2^40), the window whole
# tiles, T = 65536: the count is n exactly; tau finite (the thesis code
# had tau = inf and no samples at 2^24).
n=$(frs-sample -n 16777216 --count-only -v 2>"$T/v")
[ "$n" = 16777216 ] && ok "2^24 constant: exactly 2^24 samples" ||
    nok "2^24 constant: $n samples"
grep -q 'n_s 256, window 32768x32768 .*tau 65536,' "$T/v" &&
    ok "2^24: n_s 256, window 32768^2, tau 65536" || nok "2^24 setup: $(cat "$T/v")"
n=$(frs-sample -n 1099511627776 --count-only -q)
[ "$n" = 1099511627776 ] && ok "2^40 constant: exactly 2^40 samples" ||
    nok "2^40 constant: $n samples"
n=$(frs-sample -i blob -n 16777216 --count-only -q)
within "$n" 16777216 && ok "2^24 blob: $n within 5 sd of n" || nok "2^24 blob: $n"

# ---- only ratios matter: denormal and huge constant maps ------------------
# 5e-324 is 2^-1074: a power of two times the map of 1, so the same
# thresholds and the same bytes; tau overflowed to inf before and every
# window element became a sample.
frs-sample -q -m "$M" -i const:1 -n 1000 -T -o "$T/c1.txt"
for v in 5e-324 1e-310 1e-300 1e300; do
	frs-sample -q -m "$M" -i "const:$v" -n 1000 -T -o "$T/cv.txt" 2>"$T/err"
	case $v in
	5e-324)	cmp -s "$T/c1.txt" "$T/cv.txt" &&
		    ok "frs const:$v gives the bytes of const:1" ||
		    nok "frs const:$v: $(grep -vc '^#' "$T/cv.txt") points" ;;
	*)	n1=$(grep -vc '^#' "$T/c1.txt"); nv=$(grep -vc '^#' "$T/cv.txt")
		[ $((nv - n1)) -le 2 ] && [ $((n1 - nv)) -le 2 ] && in_unit "$T/cv.txt" &&
		    ok "frs const:$v: $nv points, const:1 $n1" ||
		    nok "frs const:$v: $nv points, const:1 $n1" ;;
	esac
done
frs-sample -q -m "$M" -i const:5e-324 -n 1000 --pdf -T -o "$T/pdf.txt"
awk '!/^#/ && $3 != 1 { bad = 1 } END { exit bad }' "$T/pdf.txt" &&
    ok "--pdf of const:5e-324 is 1" || nok "--pdf of const:5e-324"
hsw-sample -i const:1 -n 2000 -T -o "$T/h1.txt"
hsw-sample -i const:5e-324 -n 2000 -T -o "$T/hv.txt"
cmp -s "$T/h1.txt" "$T/hv.txt" && ok "hsw const:5e-324 gives the bytes of const:1" ||
    nok "hsw const:5e-324 differs from const:1"
# OpenCL: the host scales the map the same way for the device.
nolsan frs-sample -q -m "$M" -i const:5e-324 -n 1000 -T --device cl -o "$T/cl.txt" 2>"$T/err" &&
    cmp -s "$T/c1.txt" "$T/cl.txt" && ok "frs --device cl const:5e-324: the bytes of const:1" ||
    nok "frs --device cl const:5e-324: $(head -n 2 "$T/err")"
nolsan hsw-sample -i const:5e-324 -n 2000 -T --device cl -o "$T/hcl.txt" 2>"$T/err" &&
    cmp -s "$T/h1.txt" "$T/hcl.txt" && ok "hsw --device cl const:5e-324: the bytes of const:1" ||
    nok "hsw --device cl const:5e-324: $(head -n 2 "$T/err")"
# one bright pixel among denormals: a blob of 1e-300 floor 5e-324
frs-sample -q -m "$M" -i 'blob:peak=1e-300,sigma=0.01,floor=5e-324' -n 2000 -T \
    -o "$T/b.txt"
n=$(grep -vc '^#' "$T/b.txt")
within "$n" 2000 && in_unit "$T/b.txt" && ok "blob of 1e-300 on denormals: $n samples" ||
    nok "blob of 1e-300 on denormals: $n samples"

# An OpenEXR map holds floats: 1e300 would become infinity (a file every
# reader refuses), 1e-310 zero everywhere; FLT_MAX itself fits, and a
# float map of it samples like const:1 (2^128 (1 - 2^-24) is in range).
expect_fail "imap gen const:1e300 as OpenEXR" 1 "beyond the largest float" "$T/big.exr" \
    imap gen const:1e300 -s 8 -o "$T/big.exr"
expect_fail "imap gen const:1e-310 as OpenEXR" 1 "zero everywhere" "$T/tiny.exr" \
    imap gen const:1e-310 -s 8 -o "$T/tiny.exr"
imap gen const:3.4028234663852886e38 -s 128 -o "$T/fmax.exr" &&
    imap info "$T/fmax.exr" >"$T/fi" && [ "$(value max "$T/fi")" = 3.40282347e+38 ] &&
    frs-sample -q -m "$M" -i "$T/fmax.exr" -n 1000 -q -T -o "$T/fm.txt" &&
    n1=$(grep -vc '^#' "$T/c1.txt") && nv=$(grep -vc '^#' "$T/fm.txt") &&
    [ $((nv - n1)) -le 2 ] && [ $((n1 - nv)) -le 2 ] &&
    ok "FLT_MAX map as OpenEXR: $nv points, const:1 $n1" ||
    nok "FLT_MAX map as OpenEXR"

# ---- degenerate maps --------------------------------------------------------
expect_fail "hsw: all-zero map" 1 "zero everywhere" "$T/z.pts" \
    hsw-sample -i const:0 -n 10 -o "$T/z.pts"
expect_fail "dda: all-zero map" 1 "zero everywhere" "$T/z.tsv" \
    dda --density -i const:0 -o "$T/z.tsv" "$T/c1.txt"
# 1x1 map: n_s 256, 16 whole 64^2 tiles, T = 1000 4096 / 65536 = 62.5:
# 16 x 62 plus 16 coins
frs-sample -q -m "$M" -s 1x1 -n 1000 -T -o "$T/one.txt"
n=$(grep -vc '^#' "$T/one.txt")
[ "$n" -ge 992 ] && [ "$n" -le 1008 ] && in_unit "$T/one.txt" &&
    ok "1x1 map: $n samples in [992, 1008]" || nok "1x1 map: $n samples"
# 1x7 strip, a ramp from 1 to 7 down the rows: row k holds the value at
# its centre, 1 + 6 (k + 1/2) / 7, which sum to 28.  FRS: binomial bounds;
# HSW of 28000 Hammersley points: within 4 (log2 n + 1) = 64.
frs-sample -q -m "$M" -i 'ramp:from=1,to=7,angle=90' -s 1x7 -n 28000 -T -o "$T/strip.txt"
awk '!/^#/ { r = int($2 * 7); c[r]++; n++ } END {
	for (k = 0; k < 7; k++) { e = n * (1 + 6 * (k + 0.5) / 7) / 28; d = c[k] - e
		if (d < 0) d = -d; if (d > 5 * sqrt(e) + 2) bad = 1 }
	exit bad || n < 27000 }' "$T/strip.txt" && in_unit "$T/strip.txt" &&
    ok "1x7 strip: rows follow the ramp" || nok "1x7 strip: rows"
hsw-sample -i 'ramp:from=1,to=7,angle=90' -s 1x7 -n 28000 --input hammersley -T \
    -o "$T/hstrip.txt"
awk '!/^#/ { c[int($2 * 7)]++; if ($1 < 0 || $1 >= 1) bad = 1 } END {
	for (k = 0; k < 7; k++) { d = c[k] - 1000 * (1 + 6 * (k + 0.5) / 7)
		if (d < 0) d = -d; if (d > 64) bad = 1 }
	exit bad }' "$T/hstrip.txt" && ok "hsw 1x7 strip: rows follow the ramp" ||
    nok "hsw 1x7 strip: rows"

# ---- tiny and large matrices ------------------------------------------------
# frd-gen's smallest sizes: permutations of 0..N-1, checked by frd-prep
# and by sorting the values here.
for s in 2 3 2x3 3x2 2x17 5x7; do
	frd-gen -s $s -q -o "$T/g.frd"
	w=${s%x*}; h=${s#*x}
	nv=$((w * h))
	tail -c $((4 * nv)) "$T/g.frd" | od -A n -v -t u4 | tr -s ' ' '\n' |
	    grep -v '^$' | sort -n | awk -v n="$nv" '$1 != NR - 1 { bad = 1 }
	    END { exit bad || NR != n }' && frd-prep --check "$T/g.frd" -o /dev/null &&
	    ok "frd-gen -s $s: a permutation of 0..$((nv - 1))" ||
	    nok "frd-gen -s $s: not a permutation"
done
frd-gen -k 3 -s 2 -q -o "$T/c.frd" && frd-prep --check "$T/c.frd" -o /dev/null &&
    [ "$(tail -c 32 "$T/c.frd" | od -A n -v -t u4 | tr -s ' ' '\n' | grep -v '^$' |
    sort -n | tr '\n' ' ')" = "0 1 2 3 4 5 6 7 " ] && ok "frd-gen -k 3 -s 2: 0..7" ||
    nok "frd-gen -k 3 -s 2"
expect_fail "frd-gen -s 1x5" 2 "at least 2 cells" "$T/o.frd" frd-gen -s 1x5 -o "$T/o.frd"
expect_fail "frd-gen -s 5x1" 2 "at least 2 cells" "$T/o.frd" frd-gen -s 5x1 -o "$T/o.frd"
# 2x2: prepared, and sampled: each tile passes its value 0 with the
# coin T = n 4 / S_W^2, so about n samples; .frd and .frp the same bytes.
frd-gen -s 2 -q -o "$T/t2.frd"
check "frd-prep -a all on 2x2" frd-prep -a all "$T/t2.frd" -o "$T/t2.frp"
frs-sample -m "$T/t2.frd" -i blob -n 3000 -q -T -o "$T/t2a.txt"
frs-sample -m "$T/t2.frp" -i blob -n 3000 -q -T -o "$T/t2b.txt"
n=$(grep -vc '^#' "$T/t2a.txt")
cmp -s "$T/t2a.txt" "$T/t2b.txt" && within "$n" 3000 && in_unit "$T/t2a.txt" &&
    ok "2x2 matrix: $n samples of 3000, the same from the .frp" ||
    nok "2x2 matrix: $n samples"
impls_same "$T/t2a.txt" -m "$T/t2.frp" -i blob -n 3000 -q &&
    ok "2x2 matrix: every implementation, the same points" ||
    nok "2x2 matrix: implementations differ"
frd-gen -s 3 -q -o "$T/t3.frd"
expect_fail "frd-prep -a all on 3x3" 1 "power-of-two" "$T/t3.frp" \
    frd-prep -a all "$T/t3.frd" -o "$T/t3.frp"
frs-sample -m "$T/t3.frd" -a naive -i blob -n 3000 -q -T -o "$T/t3.txt"
n=$(grep -vc '^#' "$T/t3.txt")
# partial 3x3 tiles at the window's edges: up to 2 of 3 rows and columns
awk -v c="$n" 'BEGIN { d = c - 3000; if (d < 0) d = -d; exit !(d <= 5 * sqrt(3000) + 60) }' &&
    in_unit "$T/t3.txt" && ok "3x3 matrix, naive: $n samples of 3000" ||
    nok "3x3 matrix, naive: $n samples"
# The top half of the shipped matrix, 2048x1024, ranked: a permutation;
# the blob's count near n, Naive and Sorted the same points.
tail -c $((4 * 2048 * 2048)) data/default.frd | head -c $((4 * 2048 * 1024)) \
    >"$T/half.raw"
check "import 2048x1024 with --rank" frd-prep --import raw32 -s 2048x1024 --rank \
    "$T/half.raw" -o "$T/half.frd"
check "2048x1024: a permutation" frd-prep --check "$T/half.frd" -o /dev/null
frs-sample -m "$T/half.frd" -i blob -n 5000 -q -T -o "$T/hs.txt"
frs-sample -m "$T/half.frd" -a naive -i blob -n 5000 -q -T | grep -v '^#' | sort >"$T/hn.s"
n=$(grep -vc '^#' "$T/hs.txt")
grep -v '^#' "$T/hs.txt" | sort | cmp -s - "$T/hn.s" && within "$n" 5000 &&
    ok "2048x1024 matrix: $n samples of 5000, Naive = Sorted" ||
    nok "2048x1024 matrix: $n samples"

# ---- discrepancy at the edges -------------------------------------------------
# One point (x, y), and copies of it: star D2^2 = 1/9 - (1-x^2)(1-y^2)/2 +
# (1-x)(1-y), Dinf = max(1 - xy, x, y); rect D2^2 = 1/36 + 2x(1-x)y(1-y).
for p in "0.3 0.6" "0 0" "0.99999999999999989 0.99999999999999989" "0 0.99999999999999989"; do
	for k in 1 5; do
		i=0; : >"$T/p.txt"
		while [ $i -lt $k ]; do echo "$p" >>"$T/p.txt"; i=$((i + 1)); done
		set -- $p
		want=$(awk -v x="$1" -v y="$2" 'BEGIN {
		    printf "%.12g %.12g %.12g", sqrt(1/9 - (1-x*x)*(1-y*y)/2 + (1-x)*(1-y)),
		    (1-x*y > x ? (1-x*y > y ? 1-x*y : y) : (x > y ? x : y)),
		    sqrt(1/36 + 2*x*(1-x)*y*(1-y)) }')
		set -- $want
		discrepancy --exact -o "$T/d.tsv" "$T/p.txt" &&
		    discrepancy -c rect --exact -o "$T/r.tsv" "$T/p.txt" &&
		    near "$(col 4 "$T/d.tsv")" "$1" 1e-8 && near "$(col 6 "$T/d.tsv")" "$2" 1e-8 &&
		    near "$(col 4 "$T/r.tsv")" "$3" 1e-8 &&
		    ok "discrepancy of ($p) x $k: $want" ||
		    nok "discrepancy of ($p) x $k: $(col 4 "$T/d.tsv") $(col 6 "$T/d.tsv") $(col 4 "$T/r.tsv"), want $want"
	done
done
# The k x k grid of cell centres, k = 64: star D2^2 = 1/(18k^2) + 7/(288k^4).
awk 'BEGIN { for (i = 0; i < 64; i++) for (j = 0; j < 64; j++)
	printf "%.17g %.17g\n", (i + 0.5) / 64, (j + 0.5) / 64 }' >"$T/grid.txt"
discrepancy --exact -o "$T/g.tsv" "$T/grid.txt"
want=$(awk 'BEGIN { k = 64; printf "%.12g", sqrt(1/(18*k*k) + 7/(288*k^4)) }')
near "$(col 4 "$T/g.tsv")" "$want" 1e-11 && ok "64x64 grid: star D2 $want" ||
    nok "64x64 grid: star D2 $(col 4 "$T/g.tsv"), want $want"
printf '0.3 1\n' >"$T/one.txt"
expect_fail "discrepancy: a coordinate of 1" 1 "outside [0,1)" "$T/o.tsv" \
    discrepancy -o "$T/o.tsv" "$T/one.txt"

# ---- density at the edges ------------------------------------------------------
printf '0.3 0.7\n0.3 0.7\n0.1 0.1\n' >"$T/dup.txt"
dda --density -o "$T/dd.tsv" "$T/dup.txt"
[ "$(col 3 "$T/dd.tsv")" = 0 ] && [ "$(col 4 "$T/dd.tsv")" = 0 ] &&
    ok "duplicate points: dmin 0, rho 0" || nok "duplicates: $(sed -n 2p "$T/dd.tsv")"
# (0, 0.5) and (1 - 2^-53, 0.5): plain 1 - 2^-53, toroidal 2^-53, rho =
# d / sqrt(2 / (sqrt 3 2)) = d 3^(1/4)
printf '0 0.5\n0.99999999999999989 0.5\n' >"$T/edge.txt"
dda --density --torus -o "$T/dt.tsv" "$T/edge.txt"
dda --density -o "$T/dp.tsv" "$T/edge.txt"
r4=$(awk 'BEGIN { printf "%.17g", 3 ^ 0.25 }')
rel "$(col 3 "$T/dt.tsv")" 1.1102230246251565e-16 1e-8 &&
    rel "$(col 4 "$T/dt.tsv")" "$(awk -v r="$r4" 'BEGIN { printf "%.17g", r * 2 ^ -53 }')" 1e-8 &&
    rel "$(col 3 "$T/dp.tsv")" 1 1e-15 && rel "$(col 4 "$T/dp.tsv")" "$r4" 1e-8 &&
    ok "0 and 1 - 2^-53: toroidal 2^-53, plain 1" ||
    nok "0 and 1 - 2^-53: $(sed -n 2p "$T/dt.tsv"); $(sed -n 2p "$T/dp.tsv")"
# (0.125, 0.25) and (0.5, 0.75): 0.625 both ways (a 3-4-5 triangle)
printf '0.125 0.25\n0.5 0.75\n' >"$T/two.txt"
dda --density --torus -o "$T/d2.tsv" "$T/two.txt"
[ "$(col 3 "$T/d2.tsv")" = 0.625 ] && rel "$(col 4 "$T/d2.tsv")" "$(awk -v r="$r4" \
    'BEGIN { printf "%.17g", 0.625 * r }')" 1e-8 &&
    ok "two points: dmin 0.625, rho 0.625 3^(1/4)" || nok "two points: $(sed -n 2p "$T/d2.tsv")"
done_testing
