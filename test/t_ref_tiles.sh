#!/bin/sh
# The measures of test/ref/ref_tiles.c that tell the lattice of plain
# tiles in the dark of an HDR map from blue noise and from white-noise
# clumps: band (the largest periodogram value of a band of rows) on a
# planted lattice against dart throwing and white noise; nn (nearest-
# neighbour distances in local spacings) against distances known by hand
# and a brute-force oracle, and blue noise against white.
. "$(dirname "$0")/lib.sh"
REF=$BIN/../test/ref_tiles

# ---- band ----------------------------------------------------------

# pmax Y0 Y1 FILE: the largest periodogram value of the band
pmax() { "$REF" band "$1" "$2" "$3" | awk '{ print $5 }'; }

# A 40 x 40 lattice, exact and with a jitter of 1/1000 of its spacing:
# the exact one gives P = m at its frequencies, multiples of (40, 0) and
# (0, 40) in the whole square, of (40, 0) and (0, 12) in rows 0.6 to 0.9
# (12 rows).
lattice() {	# jitter
	awk -v j="$1" 'BEGIN { srand(5); for (b = 0; b < 40; b++) for (a = 0; a < 40; a++)
	    printf "%.12f %.12f\n", (a + 0.5 + j * (rand() - 0.5)) / 40,
	        (b + 0.5 + j * (rand() - 0.5)) / 40 }'
}
lattice 0 >"$T/lat0.txt"
lattice 0.001 >"$T/lat.txt"
# (m, pmax, kx, ky of each band)
e=$({ "$REF" band 0 1 "$T/lat0.txt"; "$REF" band 0.6 0.9 "$T/lat0.txt"; } |
    awk '{ printf "%s%s %s %s %s", (NR > 1 ? ", " : ""), $3, $5, $7, $8 }')
echo "$e" | awk -F', ' '{ split($1, a, " "); split($2, b, " ")
    exit !(a[1] == 1600 && a[2] == 1600 && a[3] % 40 == 0 && a[4] % 40 == 0 &&
        b[1] == 480 && b[2] == 480 && b[3] % 40 == 0 && b[4] % 12 == 0) }' &&
    ok "band: an exact lattice gives P = m (m pmax kx ky: $e)" ||
    nok "band: an exact lattice gives P = m (m pmax kx ky: $e)"
# m counts the rows strictly inside the band
m=$("$REF" band 0.6 0.9 "$T/lat.txt" | awk '{ print $3 }')
mo=$(awk '$2 > 0.6 && $2 < 0.9' "$T/lat.txt" | wc -l)
[ "$m" -eq "$mo" ] && ok "band: m $m, the samples with 0.6 < y < 0.9" ||
    nok "band: m $m, the samples with 0.6 < y < 0.9 are $mo"

# Measured (seed 1, n 4096, rows 0.6 to 0.9): jittered lattice 480,
# relaxed dart 8.4, dart 15.3 (19.7 the most of seeds 1 to 5), white
# noise 7.5 (7.5 to 12.5 over seeds 1 to 5; the largest of some 8000
# exponentials of mean 1 stays within 5 to 25 but for chances below
# 1e-6).  Without the |k| >= 3 cut every one gives P(0) = m, about 1200.
pl=$(pmax 0.6 0.9 "$T/lat.txt")
for k in relaxed-dart dart random; do
	ref-sample -q -k $k -n 4096 -S 1 -o "$T/$k.pts"
done
pr=$(pmax 0.6 0.9 "$T/relaxed-dart.pts")
pd=$(pmax 0.6 0.9 "$T/dart.pts")
pw=$(pmax 0.6 0.9 "$T/random.pts")
awk -v l="$pl" -v r="$pr" -v d="$pd" 'BEGIN { exit !(l > 100 && r < 40 && d < 40) }' &&
    ok "band: lattice $pl above 100, relaxed dart $pr and dart $pd below 40" ||
    nok "band: lattice $pl above 100, relaxed dart $pr and dart $pd below 40"
awk -v w="$pw" 'BEGIN { exit !(w > 5 && w < 25) }' &&
    ok "band: white noise $pw within 5 to 25" ||
    nok "band: white noise $pw within 5 to 25"

# ---- nn ------------------------------------------------------------

# By hand: the ramp at 4 x 2 pixels holds 1/8, 3/8, 5/8, 7/8 in its
# columns (sum 4), so with 4 samples dens is the pixel's value.  A
# (0.05, 0.25) and B (0.05, 0.75) are 1 pixel apart (0.5 in y is 1 pixel
# of 2) in column 0: r = sqrt(1/8) = 0.3536; C (0.8, 0.25) and D (0.95,
# 0.25) 0.6 pixels apart in column 3: r = 0.6 sqrt(7/8) = 0.5612; mean
# 0.4574.  Levels A 0, B C D 1: A's 1.5 spacings (4.24 pixels) hold B
# and C, B's hold A, C's (1.60 pixels) only D, though A (3 pixels off)
# sees C: seams A and B.
printf '#pts dims=2 extra=1 count=4 version=2 names=lev\n0.05 0.25 0\n0.05 0.75 1\n0.8 0.25 1\n0.95 0.25 1\n' >"$T/four.txt"
want="$T/four.txt n 4 p1 0.3536 p5 0.3536 p10 0.3536 mean 0.4574 seam 2 p1 0.3536 p5 0.3536 other 2 p1 0.5612 p5 0.5612"
got=$("$REF" nn ramp -s 4x2 --level-col lev "$T/four.txt")
[ "$got" = "$want" ] && ok "nn: four samples on a ramp, known by hand" ||
    nok "nn: four samples on a ramp, known by hand: $got"

# A brute-force oracle over every pair on the ramp of W x H pixels
# (column c holds (c + 1/2) / W, the sum is W H / 2), the level in the
# third column: n, mean, the seam and other counts, and the 1st and 5th
# percentiles of r, the values at floor(p (n - 1)) sorted.
oracle() {	# W H FILE
	awk -v W="$1" -v H="$2" -v rf="$T/r.txt" '
	BEGIN { n = 0 }	# (x[""] is not x[0])
	!/^#/ { x[n] = $1 * W; y[n] = $2 * H; c = int($1 * W)
		v[n] = (c + 0.5) / W; l[n] = $3; n++ }
	END { for (i = 0; i < n; i++) {
			d = n * v[i] / (W * H / 2); best = -1; seam = 0
			for (j = 0; j < n; j++) {
				if (j == i) continue
				dx = x[j] - x[i]; dy = y[j] - y[i]; q = dx * dx + dy * dy
				if (best < 0 || q < best) best = q
				if (l[j] != l[i] && q <= 2.25 / d) seam = 1
			}
			r = sqrt(best * d); sum += r; ns += seam; print r >rf
		}
		printf "%d %.4f %d %d", n, sum / n, ns, n - ns }' "$3"
	sort -g "$T/r.txt" | awk '{ v[NR - 1] = $1 }
	    END { printf " %.4f %.4f\n", v[int(0.01 * (NR - 1))], v[int(0.05 * (NR - 1))] }'
}
# same ORACLE GOT: the two lines agree (means and percentiles to 2e-4)
same() {
	echo "$1 $2" | awk '{ exit !($1 == $7 && $3 == $9 && $4 == $10 &&
	    ($2 - $8)^2 < 4e-8 && ($5 - $11)^2 < 4e-8 && ($6 - $12)^2 < 4e-8) }'
}
# Relaxed dart on a 64 x 64 ramp with levels by quadrant (seams along x
# 0.5 and y 0.3); two sets of it (--sets 2, the set column), set 0
# squeezed into the left half and set 1, mirrored, into the right (their
# dense sides meet).
ref-sample -q -k relaxed-dart -i ramp -s 64x64 -n 1000 -S 2 -T |
    awk '/^#/ { print "#pts dims=2 extra=1 count=1000 version=2 names=lev"; next }
        { print $1, $2, ($1 > 0.5) + 2 * ($2 > 0.3) }' >"$T/quad.txt"
ref-sample -q -k relaxed-dart -i ramp -s 64x64 -n 400 --sets 2 -S 3 -T |
    awk '/^#/ { print; next } { printf "%.17g %s %s\n", $3 ? 0.5 + (1 - $1) * 0.4999 : $1 / 2, $2, $3 }' >"$T/sets.txt"
for f in quad:lev sets:set; do
	o=$(oracle 64 64 "$T/${f%:*}.txt")
	c=$("$REF" nn ramp -s 64x64 --level-col "${f#*:}" "$T/${f%:*}.txt" |
	    awk '{ print $3, $11, $13, $19, $5, $7 }')
	same "$o" "$c" && ok "nn: ${f%:*} as a brute-force oracle (n mean seam other p1 p5: $c)" ||
	    nok "nn: ${f%:*} as a brute-force oracle: $c, oracle $o"
done

# Measured: on the constant map (n 4096, seed 1) p5 0.734 relaxed dart,
# 0.757 dart, 0.133 white noise (0.126 to 0.141 over seeds 1 to 5);
# relaxed dart on a blob, its own density: p1 0.723.
p5() { "$REF" nn "$@" | awk '{ print $7 }'; }
br=$(p5 const "$T/relaxed-dart.pts")
bd=$(p5 const "$T/dart.pts")
bw=$(p5 const "$T/random.pts")
awk -v r="$br" -v d="$bd" -v w="$bw" 'BEGIN { exit !(r > 0.6 && d > 0.6 && w < 0.25) }' &&
    ok "nn: p5 relaxed dart $br and dart $bd above 0.6, white noise $bw below 0.25" ||
    nok "nn: p5 relaxed dart $br and dart $bd above 0.6, white noise $bw below 0.25"
ref-sample -q -k relaxed-dart -i blob -s 256x256 -n 2000 -S 1 -o "$T/blob.pts"
p1=$("$REF" nn blob -s 256x256 "$T/blob.pts" | awk '{ print $5 }')
awk -v p="$p1" 'BEGIN { exit !(p > 0.6) }' &&
    ok "nn: relaxed dart on a blob, p1 $p1 in its local spacing" ||
    nok "nn: relaxed dart on a blob, p1 $p1 in its local spacing"

expect_fail "nn: a column the file lacks" 1 "no column bogus" - \
    "$REF" nn const --level-col bogus "$T/four.txt"
expect_fail "band: Y0 above Y1" 1 "Y0 < Y1" - "$REF" band 0.9 0.6 "$T/lat.txt"
done_testing
