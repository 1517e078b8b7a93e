#!/bin/sh
# dda: spectra, density and RDF from the command line; conventions and
# bad input.
. "$(dirname "$0")/lib.sh"

ref-sample -k regular -n 256 -q -o "$T/grid.pts"
ref-sample -k random -n 512 --sets 10 -q -o "$T/rand.pts"
ref-sample -k dart -n 256 -q -o "$T/dart.pts"

# at KX KY FILE: the value of a kx ky table at one frequency.
at() {
	awk -F '\t' -v x="$1" -v y="$2" 'NR > 1 && $1 == x && $2 == y { print $3 }' "$3"
}

# A regular 16 x 16 grid: P = n at multiples of 16, 0 elsewhere.
check "--fourier of a grid" dda --fourier --size 40 -o "$T/f" "$T/grid.pts"
near "$(at 16 0 "$T/f")" 256 1e-9 && near "$(at 16 -32 "$T/f")" 256 1e-9 &&
    near "$(at 0 0 "$T/f")" 256 1e-9 && ok "grid: P = n at multiples of m" ||
    nok "grid: P(16,0) = $(at 16 0 "$T/f")"
awk -F '\t' 'NR > 1 && ($1 % 16 || $2 % 16) && $3 > 1e-9 { bad = 1 }
    END { exit bad }' "$T/f" && ok "grid: P = 0 elsewhere" || nok "grid: P != 0"
[ "$(head -n 1 "$T/f")" = "$(printf 'kx\tky\tpower')" ] &&
    [ "$(wc -l <"$T/f")" -eq $((81 * 81 + 1)) ] && ok "table: header, (2K+1)^2 rows" ||
    nok "table layout"

# Random sets: white noise, radial mean 1, anisotropy of 10 sets -10 dB.
check "--fourier --radial --png" dda --fourier --sets 512 --radial "$T/r" \
    --png "$T/p.png" -o "$T/f2" "$T/rand.pts"
[ "$(head -n 1 "$T/r")" = "$(printf 'freq\tpower\taniso_db\tcount')" ] &&
    ok "--radial header" || nok "--radial header: $(head -n 1 "$T/r")"
awk -F '\t' 'NR > 3 { p += $2; a += $3; k++ } END {
	p /= k; a /= k; exit !(p > 0.95 && p < 1.05 && a > -11 && a < -9) }' "$T/r" &&
    ok "random: radial mean 1, anisotropy -10 dB" ||
    nok "random: $(awk 'NR > 3' "$T/r" | head -n 3)"
[ "$(head -c 8 "$T/p.png" | od -A n -t x1 | tr -d ' ')" = 89504e470d0a1a0a ] &&
    ok "--png writes a PNG" || nok "--png"
check "--approx" dda --fourier --approx --sets 512 -o "$T/fa" "$T/rand.pts"
paste "$T/f2" "$T/fa" | awk -F '\t' 'NR > 1 { d = $3 - $6; if (d < 0) d = -d
    if (d > 1e-3 * ($3 + 1)) bad = 1 } END { exit bad }' &&
    ok "--approx agrees with the exact sums" || nok "--approx differs"

# Same bytes for any thread count.
dda --fourier --size 32 --sets 512 -j 1 -o "$T/j1" "$T/rand.pts"
dda --fourier --size 32 --sets 512 -j 2 -o "$T/j2" "$T/rand.pts"
cmp -s "$T/j1" "$T/j2" && ok "--fourier: -j 1 = -j 2" || nok "--fourier: -j"
dda --dda --sets 512 -j 1 -o "$T/d1" "$T/rand.pts"
dda --dda --sets 512 -j 2 -o "$T/d2" "$T/rand.pts"
cmp -s "$T/d1" "$T/d2" && ok "--dda: -j 1 = -j 2" || nok "--dda: -j"

# DDA: a constant map is the uniform analysis; random sets give about 1.
dda --dda --sets 512 -i const -o "$T/d3" "$T/rand.pts"
cmp -s "$T/d1" "$T/d3" && ok "--dda: constant map = uniform" || nok "--dda: -i const"
awk -F '\t' 'NR > 1 { r = sqrt($1 * $1 + $2 * $2)
    if (r > 2 && r < 8) { s += $3; k++ } } END { s /= k; exit !(s > 0.9 && s < 1.1) }' \
    "$T/d1" && ok "--dda: random sets near 1" || nok "--dda: random level"

# Density: a square grid has rho = sqrt(sqrt(3)/2).
check "--density" dda --density -o "$T/dn" "$T/grid.pts" "$T/dart.pts"
[ "$(head -n 1 "$T/dn")" = "$(printf 'set\tn\tdmin\trho\tfile')" ] && ok "--density header" ||
    nok "--density header"
near "$(awk -F '\t' 'NR == 2 { print $4 }' "$T/dn")" 0.930604859 1e-8 &&
    ok "grid: rho = 0.9306" || nok "grid rho: $(sed -n 2p "$T/dn")"
[ "$(awk -F '\t' 'END { print $1 }' "$T/dn")" = mean ] && ok "--density: a mean row" ||
    nok "--density mean row"

# RDF of random sets: 1 on average, plain and on the torus.
for t in "" --torus; do
	dda --rdf $t --sets 512 --bins 40 -o "$T/g" "$T/rand.pts"
	awk -F '\t' 'NR > 5 { s += $2; k++ } END { s /= k; exit !(s > 0.93 && s < 1.07) }' \
	    "$T/g" && ok "--rdf $t: random sets about 1" || nok "--rdf $t: $(sed -n 10p "$T/g")"
done

# ---- --summary: every analysis per file, one table, one page -----------

# block NAME FILE: the rows of a --summary block, its header first.
block() {
	awk -v b="# $1" '$0 == b { on = 1; next } on && $0 == "" { exit } on' "$2"
}
check "--summary" dda --summary --bins 40 -j 2 --png "$T/page.png" \
    -o "$T/sum" "$T/rand.pts" "$T/dart.pts"
[ "$(grep '^# ' "$T/sum" | tr '\n' '|')" = \
    "# summary|# density|# radial $T/rand.pts|# radial $T/dart.pts|# rdf $T/rand.pts|# rdf $T/dart.pts|" ] &&
    [ "$(block summary "$T/sum" | head -n 1)" = \
    "$(printf 'sets\tn\tdmin\trho\tpeak\tpeak_freq\tg_max\tg_max_r\tfile')" ] &&
    [ "$(block summary "$T/sum" | wc -l)" -eq 3 ] &&
    ok "--summary: its blocks, in order, and a row per file" ||
    nok "--summary layout: $(grep '^# ' "$T/sum" | tr '\n' '|')"
# The same numbers as the analyses run one by one.
dda --fourier --radial "$T/sr" -o /dev/null "$T/rand.pts"
block "radial $T/rand.pts" "$T/sum" | cut -f 1-4 | cmp -s - "$T/sr" &&
    ok "--summary: radial mean and anisotropy of --fourier --radial" ||
    nok "--summary radial differs"
dda --rdf --bins 40 -o "$T/sg" "$T/dart.pts"
block "rdf $T/dart.pts" "$T/sum" | cut -f 1-2 | cmp -s - "$T/sg" &&
    ok "--summary: RDF of --rdf" || nok "--summary rdf differs"
dda --density -o "$T/sd" "$T/rand.pts" "$T/dart.pts"
sed '$d' "$T/sd" >"$T/sd1"
block density "$T/sum" | cmp -s - "$T/sd1" &&
    ok "--summary: the sets' densities of --density" || nok "--summary density differs"
dda --density -o "$T/sd2" "$T/rand.pts"
[ "$(block summary "$T/sum" | awk -F '\t' 'NR == 2 { print $2, $3, $4 }')" = \
    "$(awk -F '\t' '$1 == "mean" { print $2, $3, $4 }' "$T/sd2")" ] &&
    ok "--summary: a file's row has the mean of --density" ||
    nok "--summary mean density: $(block summary "$T/sum" | sed -n 2p)"
dda --summary --bins 40 -j 1 --png "$T/pj1.png" -o "$T/sj1" \
    "$T/rand.pts" "$T/dart.pts"
cmp -s "$T/sj1" "$T/sum" && cmp -s "$T/pj1.png" "$T/page.png" &&
    ok "--summary: -j 1 = -j 2, table and page" || nok "--summary: -j"
# --dda with a map, and --torus for the RDF.
check "--summary --dda -i" dda --summary --dda -i const --torus --bins 40 \
    -o "$T/sum2" "$T/dart.pts"
dda --dda -i const --radial "$T/sr2" -o /dev/null "$T/dart.pts"
dda --rdf -i const --torus --bins 40 -o "$T/sg2" "$T/dart.pts"
block "radial $T/dart.pts" "$T/sum2" | cut -f 1-4 | cmp -s - "$T/sr2" &&
    block "rdf $T/dart.pts" "$T/sum2" | cut -f 1-2 | cmp -s - "$T/sg2" &&
    ok "--summary --dda --torus: as --dda --radial and --rdf --torus" ||
    nok "--summary --dda differs"
# A 16 x 16 grid: spectrum peak n at |k| = 16, RDF peak in the bin of the
# lattice spacing, 1/16 = 0.9306 mean spacings (bin centre 0.95).
dda --summary --bins 40 -o "$T/sum3" "$T/grid.pts"
[ "$(block summary "$T/sum3" | awk -F '\t' 'NR == 2 { printf "%.6g %g %g", $5, $6, $8 }')" = \
    "256 16 0.95" ] && ok "--summary of a grid: peaks at the lattice" ||
    nok "--summary grid: $(block summary "$T/sum3" | sed -n 2p)"
# The page: 2 columns of 44 + 257 + 16 pixels, 257 + 3 * 128 + 198 high;
# with --size 32, plots 256 wide: 316 a column, 65 + 3 * 128 + 198.
pngsize() {
	od -A n -t u1 -j 16 -N 8 "$1" | awk '{ w = (($1 * 256 + $2) * 256 + $3) * 256 + $4
	    h = (($5 * 256 + $6) * 256 + $7) * 256 + $8; print w "x" h }'
}
[ "$(head -c 8 "$T/page.png" | od -A n -t x1 | tr -d ' ')" = 89504e470d0a1a0a ] &&
    [ "$(pngsize "$T/page.png")" = 634x839 ] && ok "--summary --png: the page, 634x839" ||
    nok "--summary page: $(pngsize "$T/page.png")"
dda --summary --size 32 --png "$T/page2.png" -o /dev/null "$T/grid.pts"
[ "$(pngsize "$T/page2.png")" = 316x647 ] && ok "--summary --size 32: 316x647" ||
    nok "--summary --size 32 page: $(pngsize "$T/page2.png")"
expect_fail "--summary --density" 2 "--summary holds" - \
    dda --summary --density "$T/grid.pts"
expect_fail "--summary --rdf" 2 "--summary holds" - dda --summary --rdf "$T/grid.pts"
expect_fail "--summary --radial" 2 "--radial: --summary" - \
    dda --summary --radial "$T/x" "$T/grid.pts"
expect_fail "--summary -i without --dda" 2 "-i:" - dda --summary -i blob "$T/grid.pts"
dda --summary --dda -i blob:sigma=0.01 --png "$T/o5" -o "$T/o6" "$T/grid.pts" \
    2>"$T/err"
[ $? -eq 1 ] && grep -q 'grid.pts' "$T/err" && [ ! -e "$T/o5" ] && [ ! -e "$T/o6" ] &&
    ! ls "$T" | grep -q '\.tmp\.' &&
    ok "--summary, a point on zero importance: exit 1, no table, no page" ||
    nok "--summary zero importance: $(cat "$T/err")"

# Bad input.
printf '0.1 0.2\n0.3 1.5\n' >"$T/out.txt"
expect_fail "two modes" 2 "one of --fourier" - dda --fourier --dda "$T/grid.pts"
expect_fail "--png with --density" 2 "--png and --radial" - \
    dda --density --png "$T/x.png" "$T/grid.pts"
expect_fail "-i with --fourier" 2 "-i:" - dda --fourier -i blob "$T/grid.pts"
expect_fail "--torus with --dda" 2 "--torus" - dda --dda --torus "$T/grid.pts"
expect_fail "--db junk" 2 "--db" - dda --db 3 "$T/grid.pts"
expect_fail "no files" 2 "no point files" - dda --rdf
expect_fail "missing file" 1 "$T/nope.pts" "$T/o1" dda -o "$T/o1" "$T/nope.pts"
expect_fail "outside [0,1)" 1 "out.txt" "$T/o2" dda -o "$T/o2" "$T/out.txt"
expect_fail "--sets not dividing" 1 \
    "grid.pts: 256 points are not a whole number of sets of 100, and there is no set column" "$T/o3" \
    dda --sets 100 -o "$T/o3" "$T/grid.pts"
expect_fail "point on zero importance" 1 "grid.pts" "$T/o4" \
    dda --dda -i blob:sigma=0.01 -o "$T/o4" "$T/grid.pts"

# ---- 3-D sets: the density ---------------------------------------------

# A regular 8^3 grid: dmin = 1/8, rho = (1/m) / r_u3(m^3) = 2^(-1/6).
awk 'BEGIN { m = 8; for (i = 0; i < m; i++) for (j = 0; j < m; j++)
	for (k = 0; k < m; k++) printf "%.17g %.17g %.17g\n", (i + 0.5) / m,
	    (j + 0.5) / m, (k + 0.5) / m }' >"$T/g3.txt"
for t in "" --torus; do
	check "3-D --density ${t:-plain}" dda --density $t -o "$T/dg3" "$T/g3.txt"
	near "$(awk -F '\t' 'NR == 2 { print $3 }' "$T/dg3")" 0.125 1e-8 &&
	    near "$(awk -F '\t' 'NR == 2 { print $4 }' "$T/dg3")" 0.890898718 1e-8 &&
	    ok "3-D grid ${t:-plain}: dmin 1/8, rho 2^(-1/6)" || nok "3-D grid ${t:-plain}: $(sed -n 2p "$T/dg3")"
done

# Uniform random 3-D sets, 10 of 1000: E[rho] = 0.622 n^(-1/3) = 0.0622,
# 36 % per set (dda(1)); the mean of 10 within 4.5 standard errors.
awk 'BEGIN { srand(11); for (i = 0; i < 10000; i++)
	printf "%.17g %.17g %.17g\n", rand(), rand(), rand() }' >"$T/r3.txt"
for t in "" --torus; do
	dda --density $t --sets 1000 -o "$T/dr3" "$T/r3.txt" 2>"$T/err"
	awk -F '\t' '$1 == "mean" { exit !($2 == 1000 && $4 > 0.030 && $4 < 0.094) }' \
	    "$T/dr3" && [ "$(wc -l <"$T/dr3")" -eq 12 ] &&
	    ok "3-D random ${t:-plain}: mean rho of 10 sets near 0.062" ||
	    nok "3-D random $t: $(tail -n 1 "$T/dr3")"
done
# dmin against every pair (awk), with a duplicate and a pair across
# the faces (0.004 apart on the torus).
awk 'BEGIN { srand(12); for (i = 0; i < 150; i++)
	printf "%.17g %.17g %.17g\n", rand(), rand(), rand()
	print "0.002 0.5 0.5"; print "0.998 0.5 0.5" }' >"$T/s3.txt"
bmin() {
	awk -v t="$2" 'BEGIN { n = 0; b = 9 } { x[n] = $1; y[n] = $2; z[n] = $3; n++ }
	    function f(d) { d = d < 0 ? -d : d; return t && d > 0.5 ? 1 - d : d }
	    END { for (i = 0; i < n; i++) for (j = i + 1; j < n; j++) {
		dx = f(x[i] - x[j]); dy = f(y[i] - y[j]); dz = f(z[i] - z[j])
		d = dx * dx + dy * dy + dz * dz; if (d < b) b = d }
		printf "%.12g\n", sqrt(b) }' "$1"
}
for t in 0 1; do
	o=; [ $t = 1 ] && o=--torus
	dda --density $o -o "$T/ds3" "$T/s3.txt" 2>"$T/err"
	near "$(awk -F '\t' 'NR == 2 { print $3 }' "$T/ds3")" "$(bmin "$T/s3.txt" $t)" 1e-8 &&
	    ok "3-D dmin ${o:-plain} = brute force" ||
	    nok "3-D dmin $o: $(sed -n 2p "$T/ds3"), brute $(bmin "$T/s3.txt" $t)"
done
near "$(awk -F '\t' 'NR == 2 { print $3 }' "$T/ds3")" 0.004 1e-9 &&
    ok "3-D --torus wraps across the faces" || nok "3-D torus wrap: $(sed -n 2p "$T/ds3")"
{ cat "$T/s3.txt"; sed -n 7p "$T/s3.txt"; } >"$T/dup3.txt"
dda --density -o "$T/dd3" "$T/dup3.txt" 2>"$T/err"
[ "$(awk -F '\t' 'NR == 2 { print $3 }' "$T/dd3")" = 0 ] &&
    ok "3-D duplicate point: dmin 0" || nok "3-D duplicate: $(sed -n 2p "$T/dd3")"
dda --density --sets 1000 -j 1 -o "$T/j31" "$T/r3.txt" 2>"$T/err"
dda --density --sets 1000 -j 2 -o "$T/j32" "$T/r3.txt" 2>>"$T/err"
cmp -s "$T/j31" "$T/j32" && ok "3-D --density: -j 1 = -j 2" || nok "3-D --density: -j"

# 3-D errors: exit 1, the file named, no output.
for m in --fourier --dda --rdf --summary; do
	expect_fail "3-D $m" 1 "g3.txt: 3-dimensional points: $m is 2-D only" \
	    "$T/o3" dda $m -o "$T/o3" "$T/g3.txt"
done
expect_fail "3-D default analysis" 1 "g3.txt: 3-dimensional points: --fourier" \
    "$T/o3" dda -o "$T/o3" "$T/g3.txt"
expect_fail "3-D --density -i" 1 "g3.txt: 3-dimensional points: -i is 2-D only" \
    "$T/o3" dda --density -i blob -o "$T/o3" "$T/g3.txt"
expect_fail "2-D then 3-D" 1 "g3.txt: 3-dimensional points after 2-dimensional" \
    "$T/o3" dda --density -o "$T/o3" "$T/grid.pts" "$T/g3.txt"
printf '0.1 0.2 0.3 0.4\n0.5 0.6 0.7 0.8\n' >"$T/d4.txt"
expect_fail "4-D points" 1 "d4.txt: 4-dimensional points" "$T/o3" \
    dda --density -o "$T/o3" "$T/d4.txt"
printf '0.1 0.2 0.3\n' >"$T/one3.txt"
expect_fail "3-D one point" 1 "one3.txt: the density needs 2 points" "$T/o3" \
    dda --density -o "$T/o3" "$T/one3.txt"

# Sets through a pipe: frs-sample --sets 4 writes a set column, which dda
# splits by with no --sets N: the same spectrum, density and RDF as the
# four seeds' files.
for s in 1 2 3 4; do frs-sample -q -i const -n 200 -S $s -o "$T/f$s.pts"; done
for a in "--fourier --size 16" "--dda --size 16" "--density" "--rdf --bins 20"; do
	# shellcheck disable=SC2086
	frs-sample -q -i const -n 200 --sets 4 | dda -q $a -o "$T/sa" -
	# shellcheck disable=SC2086
	dda -q $a -o "$T/sb" "$T/f1.pts" "$T/f2.pts" "$T/f3.pts" "$T/f4.pts"
	# (--density names the file of each set: - here)
	[ "$(cut -f 1-4 "$T/sa")" = "$(cut -f 1-4 "$T/sb")" ] && [ -s "$T/sa" ] &&
	    ok "frs-sample --sets 4 | dda $a: the four seeds'" ||
	    nok "frs-sample --sets 4 | dda $a"
done
# --sets N beside the set column: the same when it agrees, else an error.
dda --fourier --size 16 -o "$T/sc" "$T/rand.pts"
dda --fourier --size 16 --sets 512 -o "$T/sd" "$T/rand.pts"
cmp -s "$T/sc" "$T/sd" && ok "--sets 512 agreeing with the set column" || nok "--sets 512, set column"
# --sets N disagreeing with the set column: the file's sets as they are,
# with a warning naming the file and both sizes.
dda --fourier --size 16 --sets 256 -o "$T/se" "$T/rand.pts" 2>"$T/err"
cmp -s "$T/sc" "$T/se" &&
    grep -q "^dda: warning: $T/rand.pts: .*set column.* 512 points, not 256" "$T/err" &&
    ok "--sets 256 beside a set column of 512: its sets, a warning" ||
    nok "--sets 256 beside a set column: $(cat "$T/err")"
# Sets of different sizes in the set column: the warning gives their range.
printf '#pts dims=2 extra=1 names=set\n0.1 0.2 0\n0.3 0.4 0\n0.5 0.6 1\n0.7 0.8 1\n0.9 0.1 1\n' >"$T/var.txt"
dda --density --sets 2 -o "$T/sv" "$T/var.txt" 2>"$T/err"
grep -q "var.txt: .*2 to 3 points, not 2" "$T/err" && [ "$(grep -c '^[01]	' "$T/sv")" = 2 ] &&
    ok "sets of 2 and 3 points: their range in the warning" || nok "range: $(cat "$T/err")"

# A file without a set column cut into blocks of N in file order: a
# warning naming the file, the blocks as if they were files of their own.
ref-sample -k dart -n 1024 -q -o "$T/d1024.pts"
ref-sample -k dart -n 4096 -q -T -o "$T/d4096.txt"
grep -v '^#' "$T/d4096.txt" | split -l 1024 - "$T/blk."
dda --density --sets 1024 -o "$T/cut" "$T/d4096.txt" 2>"$T/err"
dda --density -o "$T/files" "$T/blk.aa" "$T/blk.ab" "$T/blk.ac" "$T/blk.ad" 2>/dev/null
[ "$(cut -f 1-4 "$T/cut")" = "$(cut -f 1-4 "$T/files")" ] &&
    [ "$(grep -c "^dda: warning: $T/d4096.txt: no set column: cut in file order into 4 sets of 1024" "$T/err")" = 1 ] &&
    ok "no set column, --sets 1024: 4 blocks in file order and a warning naming the file" ||
    nok "blocks without a set column: $(cat "$T/err")"
dda --density --sets 1024 -o "$T/one" "$T/d1024.pts" 2>"$T/err"
[ ! -s "$T/err" ] && ok "a file of exactly N points: one set, no warning" ||
    nok "one block: $(cat "$T/err")"

# frs(7)'s example of --summary, as the page writes it: the commands that
# make its files, then dda, with no message and a page of three columns.
man_example man/man7/frs.7 '^dda --summary' >"$T/ex.sh"
if grep -q '^dda --summary --sets 1024 --png cmp.png frs.pts sobol.pts dart.pts$' "$T/ex.sh" &&
    (cd "$T" && mkdir ex && cd ex && sh -e ../ex.sh >table 2>err) && [ ! -s "$T/ex/err" ] &&
    [ "$(pngsize "$T/ex/cmp.png")" = 951x839 ]; then
	ok "frs(7)'s dda --summary example runs as written"
else
	nok "frs(7)'s dda --summary example: $(cat "$T/ex.sh" "$T/ex/err" 2>&1 | head -n 8)"
fi
# The map options of frs-sample: --equirect weights the map's rows by
# sin(theta) as imap convert --equirect does (the densities of its float
# map, to 1e-6, not those of the map as it is); --strict refuses negative
# importance, which is otherwise clamped with a warning; both need -i.
imap convert --equirect -s 64x32 sky "$T/sky-eq.exr"
hsw-sample -i sky -s 64x32 --equirect -n 200 --input random --sets 20 -q -o "$T/eq.pts"
dda --density -i sky -s 64x32 --equirect -o "$T/de" "$T/eq.pts"
dda --density -i "$T/sky-eq.exr" -o "$T/dc" "$T/eq.pts"
dda --density -i sky -s 64x32 -o "$T/dp" "$T/eq.pts"
# rel A B: the largest relative difference of the sets' rho.
rel() { paste "$1" "$2" | awk -F '\t' 'NR > 1 && $1 != "mean" { d = ($4 - $9) / $9
    if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3g\n", m }'; }
awk -v c="$(rel "$T/de" "$T/dc")" -v p="$(rel "$T/de" "$T/dp")" 'BEGIN { exit !(c < 1e-6 && p > 1e-3) }' &&
    ok "--equirect: the density of imap convert --equirect's map" ||
    nok "--equirect: $(rel "$T/de" "$T/dc") from the converted map, $(rel "$T/de" "$T/dp") from the plain"
ref-sample -n 300 -q -o "$T/r300.pts"
expect_fail "--strict refuses negative importance" 1 "is negative" "$T/o7" \
    dda --density --strict -i "$TD/interior.exr" -s 64x32 -o "$T/o7" "$T/r300.pts"
dda --density -i "$TD/interior.exr" -s 64x32 -o "$T/o8" "$T/r300.pts" 2>"$T/err" &&
    grep -q "interior.exr: .*negative.*clamped" "$T/err" &&
    ok "negative importance without --strict: clamped, a warning" ||
    nok "negative importance without --strict: $(cat "$T/err")"
for o in --equirect --strict; do
	expect_fail "$o without -i" 2 "$o" - dda --density $o "$T/r300.pts"
done
# --density-rule: a pair's scale is the geometric mean of its points'
# scales (default) or the larger one (max).  Six points on a ramp of 4 x 1
# pixels (importance 2, 4, 6, 8; mean 5), against a loop over the pairs.
printf '%s\n' "0.1 0.5" "0.3 0.52" "0.55 0.1" "0.62 0.3" "0.9 0.9" \
    "0.8 0.7" >"$T/rule.txt"
# rule_oracle RULE: rho of the six points under RULE (geometric or max).
rule_oracle() {
	awk -v rule="$1" '{ x[NR] = $1; y[NR] = $2
	    f[NR] = sqrt((2 + 2 * int($1 * 4)) / 5) }
	END { n = NR; best = -1
	    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) {
		d = sqrt((x[i] - x[j]) ^ 2 + (y[i] - y[j]) ^ 2)
		s = rule == "max" ? (f[i] > f[j] ? f[i] : f[j]) : sqrt(f[i] * f[j])
		if (best < 0 || d * s < best) best = d * s }
	    printf "%.9g\n", best / sqrt(2 / (sqrt(3) * n)) }' "$T/rule.txt"
}
for r in geometric max; do
	dda --density --density-rule $r -i ramp:from=1,to=9 -s 4x1 -o "$T/rule-$r" "$T/rule.txt"
	got=$(awk -F '\t' '$1 == "mean" { print $4 }' "$T/rule-$r")
	near "$got" "$(rule_oracle $r)" 1e-7 && ok "--density-rule $r: the pairs' minimum" ||
	    nok "--density-rule $r: rho $got, a loop over the pairs $(rule_oracle $r)"
done
dda --density -i ramp:from=1,to=9 -s 4x1 -o "$T/rule-default" "$T/rule.txt"
cmp -s "$T/rule-default" "$T/rule-geometric" && ok "--density-rule: geometric the default" ||
    nok "--density-rule: the default is not geometric"
near "$(rule_oracle geometric)" "$(rule_oracle max)" 1e-3 &&
    nok "--density-rule: the test's points do not tell the rules apart" ||
    ok "--density-rule: the rules differ on the test's points"
expect_fail "--density-rule bad value" 2 "dda: --density-rule: 'larger' is not geometric or max" - \
    dda --density --density-rule larger -i ramp "$T/rule.txt"
expect_fail "--density-rule without --density" 2 "dda: --density-rule goes with --density" - \
    dda --dda --density-rule max -i ramp "$T/rule.txt"
done_testing
