#!/bin/sh
# discrepancy: the table, set handling, determinism and bad input.
. "$(dirname "$0")/lib.sh"

ref-sample -k halton -n 256 -q -o "$T/h.pts"
ref-sample -k random -n 256 -q -o "$T/r1.pts"
ref-sample -k random -n 256 -S 2 -q -o "$T/r2.pts"
ref-sample -k random -n 64 -q -o "$T/small.pts"

# col NAME FILE [ROW]: the value of column NAME in data row ROW (1).
col() {
	awk -F '\t' -v c="$1" -v r="${3:-1}" 'NR == 1 {
		for (i = 1; i <= NF; i++) if ($i == c) k = i } NR == r + 1 {
		print $k }' "$2"
}

check "star on two sets" discrepancy -c star --grid 300 --group all -o "$T/t" \
    "$T/r1.pts" "$T/r2.pts"
[ "$(head -n 1 "$T/t")" = "$(printf 'class\tn\tsets\tD2\tD2_se\tDinf\tDinf_mean\tshapes\tmethod')" ] &&
    ok "header" || nok "header: $(head -n 1 "$T/t")"
[ "$(col sets "$T/t")" = 2 ] && [ "$(col n "$T/t")" = 256 ] &&
    [ "$(col method "$T/t")" = grid300 ] && [ "$(col shapes "$T/t")" = 90000 ] &&
    ok "one row for two sets of 256, grid300" || nok "row: $(sed -n 2p "$T/t")"

# --per-set, and the mean and max of Eq. 6.3 over it.
discrepancy -c star --grid 300 --per-set "$T/r1.pts" "$T/r2.pts" >"$T/p"
m=$(awk -F '\t' 'NR > 1 { s += $4; if ($5 > x) x = $5 } END {
	printf "%.9g %.9g", s / 2, x }' "$T/p")
near "${m% *}" "$(col D2 "$T/t")" 1e-8 && near "${m#* }" "$(col Dinf "$T/t")" 1e-8 &&
    ok "D2 is the mean, Dinf the max of the sets" || nok "Eq. 6.3: $m"
[ "$(wc -l <"$T/p")" -eq 3 ] && ok "--per-set: a row per set" || nok "--per-set rows"
awk -F '\t' 'NR > 1 && $4 > $5 { bad = 1 } END { exit bad }' "$T/p" &&
    ok "D2 <= Dinf" || nok "D2 <= Dinf"

# Rows per point count and file, in order of first appearance: several
# files are never merged into one row, and their rows name the file.
discrepancy -c star --exact "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/g"
[ "$(col n "$T/g" 1) $(col n "$T/g" 2) $(col n "$T/g" 3) $(col sets "$T/g" 2)" = "64 256 256 1" ] &&
    [ "$(col file "$T/g" 1) $(col file "$T/g" 3)" = "$T/small.pts $T/h.pts" ] &&
    [ "$(head -n 1 "$T/g" | cut -f 10)" = file ] &&
    ok "several files: a row each, with a file column" || nok "rows per file: $(cat "$T/g")"
# --group n asks for the rows per point count over all files.
discrepancy -c star --exact --group n "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/gn"
[ "$(col n "$T/gn" 1) $(col n "$T/gn" 2) $(col sets "$T/gn" 2) $(wc -l <"$T/gn")" = "64 256 2 3" ] &&
    [ "$(head -n 1 "$T/gn" | cut -f 10)" = "" ] &&
    ok "--group n: a row per point count over the files" || nok "--group n: $(cat "$T/gn")"
# One file with a set column of sets of 64, 256 and 256 points: a row per
# point count, and no file column.
{ echo '#pts dims=2 extra=1 count=0 version=2 names=set'
  ref-sample -k random -n 64 -q -T | sed '/^#/d; s/$/ 0/'
  ref-sample -k random -n 256 -q -T | sed '/^#/d; s/$/ 1/'
  ref-sample -k halton -n 256 -q -T | sed '/^#/d; s/$/ 2/'; } >"$T/set3.txt"
discrepancy -c star --exact --per-set "$T/small.pts" "$T/r1.pts" "$T/h.pts" | cut -f 1-7 >"$T/g3a"
discrepancy -c star --exact --per-set "$T/set3.txt" | cut -f 1-7 >"$T/g3b"
cmp -s "$T/g3a" "$T/g3b" && ok "a set column: the sets of the three files" ||
    nok "a set column: $(cat "$T/g3b")"
discrepancy -c star --exact "$T/set3.txt" >"$T/g3s"
[ "$(col n "$T/g3s" 1) $(col n "$T/g3s" 2) $(col sets "$T/g3s" 2) $(wc -l <"$T/g3s")" = "64 256 2 3" ] &&
    [ "$(head -n 1 "$T/g3s" | cut -f 10)" = "" ] &&
    ok "a row per point count within a file" || nok "rows per n: $(cat "$T/g3s")"
[ "$(col method "$T/g")" = exact ] && [ "$(col shapes "$T/g")" = 0 ] &&
    ok "--exact: method exact, 0 shapes" || nok "--exact method"

# --group: all sets in one row (n the mean), or a row per file.
discrepancy -c star --exact --group all "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/ga"
[ "$(wc -l <"$T/ga")" -eq 2 ] && [ "$(col sets "$T/ga")" = 3 ] && [ "$(col n "$T/ga")" = 192 ] &&
    ok "--group all: one row, n the mean" || nok "--group all: $(cat "$T/ga")"
discrepancy -c star --exact --per-set "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/gp"
m=$(awk -F '\t' 'NR > 1 { s += $4 } END { printf "%.9g", s / 3 }' "$T/gp")
near "$m" "$(col D2 "$T/ga")" 1e-8 && ok "--group all: D2 the mean of the sets" ||
    nok "--group all: D2 $(col D2 "$T/ga"), mean $m"
discrepancy -c star --exact --group file "$T/r1.pts" "$T/r2.pts" >"$T/gf"
[ "$(wc -l <"$T/gf")" -eq 3 ] && [ "$(col file "$T/gf" 2)" = "$T/r2.pts" ] &&
    ok "--group file: a row per file, with the file" || nok "--group file: $(cat "$T/gf")"
discrepancy -c star --exact --group file "$T/r1.pts" >"$T/gf1"
[ "$(col file "$T/gf1")" = "$T/r1.pts" ] && ok "--group file, one file: the file column" ||
    nok "--group file, one file: $(cat "$T/gf1")"
[ "$(head -n 1 "$T/ga" | cut -f 10)" = "" ] && ok "--group all: no file column" ||
    nok "--group all: $(head -n 1 "$T/ga")"

# --sets N equals separate files, byte for byte.
cat "$T/r1.pts" >"$T/both.pts"
tail -c +33 "$T/r2.pts" >>"$T/both.pts"
printf '\000\002' | dd of="$T/both.pts" bs=1 seek=24 conv=notrunc 2>/dev/null
# patch the count to 512: little-endian 0x200
printf '\000\002\000\000\000\000\000\000' | dd of="$T/both.pts" bs=1 seek=24 \
    conv=notrunc 2>/dev/null
for c in "star --grid 300" "rect --grid 40" "half --grid 50" \
    "quad --shapes 2000" "circle --shapes 2000"; do
	discrepancy -c $c --group all "$T/r1.pts" "$T/r2.pts" >"$T/a" 2>"$T/err"
	discrepancy -c $c --sets 256 "$T/both.pts" >"$T/b" 2>>"$T/err"
	cmp -s "$T/a" "$T/b" && ok "--sets 256 = two files ($c)" ||
	    nok "--sets 256 = two files ($c)"
	discrepancy -c $c -j 1 --sets 256 "$T/both.pts" >"$T/c" 2>>"$T/err"
	cmp -s "$T/b" "$T/c" && ok "-j 1 = -j 2 ($c)" || nok "-j 1 = -j 2 ($c)"
done

# Same seed, same shapes; another seed, other shapes.
discrepancy -c circle --shapes 3000 -S 4 "$T/r1.pts" >"$T/s1"
discrepancy -c circle --shapes 3000 -S 4 "$T/r1.pts" >"$T/s2"
discrepancy -c circle --shapes 3000 -S 5 "$T/r1.pts" >"$T/s3"
cmp -s "$T/s1" "$T/s2" && ! cmp -s "$T/s1" "$T/s3" &&
    ok "-S: same seed same shapes" || nok "-S: seeds"

# Text and standard input.
ref-sample -k halton -n 256 -q -T -o "$T/h.txt"
discrepancy -c rect --grid 50 "$T/h.pts" >"$T/x1"
discrepancy -c rect --grid 50 - <"$T/h.txt" >"$T/x2"
cmp -s "$T/x1" "$T/x2" && ok "text on standard input" || nok "text on stdin"

# Halton beats random on every class.
for c in "star --grid 500" "rect --grid 60" "half --grid 60" \
    "quad --shapes 3000" "circle --shapes 3000"; do
	discrepancy -c $c --per-set "$T/h.pts" "$T/small.pts" "$T/r1.pts" >"$T/q"
	h=$(col D2 "$T/q" 1) r=$(col D2 "$T/q" 3)
	awk -v h="$h" -v r="$r" 'BEGIN { exit !(h < r) }' &&
	    ok "halton < random ($c)" || nok "halton $h >= random $r ($c)"
done

# --d2-only, --dinf-only: the value of the full run, the other column
# nan, the method saying which.
for c in "star --exact" "rect --exact" "star --grid 300" "rect --grid 40"; do
	discrepancy -c $c "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/full"
	discrepancy -c $c --d2-only "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/d2o"
	discrepancy -c $c --dinf-only "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/dio"
	m=$(col method "$T/full")
	[ "$(cut -f 1-5 "$T/full")" = "$(cut -f 1-5 "$T/d2o")" ] &&
	    [ "$(col Dinf "$T/d2o" 2) $(col Dinf_mean "$T/d2o" 2)" = "nan nan" ] &&
	    [ "$(col method "$T/d2o")" = "$m:D2" ] &&
	    ok "--d2-only: D2 of the full run, Dinf nan ($c)" ||
	    nok "--d2-only ($c): $(sed -n 2p "$T/d2o"), full $(sed -n 2p "$T/full")"
	[ "$(cut -f 6-7 "$T/full")" = "$(cut -f 6-7 "$T/dio")" ] &&
	    [ "$(col D2 "$T/dio" 2) $(col D2_se "$T/dio" 2)" = "nan nan" ] &&
	    [ "$(col method "$T/dio")" = "$m:Dinf" ] &&
	    ok "--dinf-only: Dinf of the full run, D2 nan ($c)" ||
	    nok "--dinf-only ($c): $(sed -n 2p "$T/dio"), full $(sed -n 2p "$T/full")"
done
[ "$(col shapes "$T/d2o")" = 608400 ] && ok "--d2-only: the grid's shapes" ||
    nok "--d2-only shapes $(col shapes "$T/d2o")"
discrepancy --exact --d2-only --per-set "$T/h.pts" >"$T/d2p"
[ "$(col Dinf "$T/d2p")" = nan ] && [ "$(col shapes "$T/d2p")" = 0 ] &&
    [ "$(col method "$T/d2p")" = exact:D2 ] && ok "--d2-only --per-set" ||
    nok "--d2-only --per-set: $(sed -n 2p "$T/d2p")"
# the classes that find both at once: the value left out all the same
discrepancy -c half --grid 50 --d2-only "$T/h.pts" >"$T/hd"
[ "$(col Dinf "$T/hd")" = nan ] && [ "$(col method "$T/hd")" = border50:D2 ] &&
    ok "--d2-only with half" || nok "--d2-only half: $(sed -n 2p "$T/hd")"
expect_fail "--d2-only --dinf-only" 2 "--d2-only and --dinf-only exclude each other" - \
    discrepancy --d2-only --dinf-only "$T/h.pts"
expect_fail "--exact --grid --d2-only" 2 "--d2-only: --grid with --exact" - \
    discrepancy --exact --grid 30 --d2-only "$T/h.pts"
expect_fail "--exact --grid --dinf-only" 2 "--dinf-only: --exact with --grid" - \
    discrepancy --exact --grid 30 --dinf-only "$T/h.pts"

# -o: atomic, nothing left on failure.
check "-o FILE" discrepancy -c star --grid 100 -o "$T/out.tsv" "$T/h.pts"
[ -s "$T/out.tsv" ] && ok "-o wrote the table" || nok "-o wrote the table"

# Bad input: exit 1, the file named, no output.
printf '#pts dims=4 extra=0 count=1\n0.1 0.2 0.3 0.4\n' >"$T/four.txt"
printf '0.1 0.2\n1.5 0.2\n' >"$T/out.txt"
printf '#pts dims=2 extra=0 count=0\n' >"$T/empty.txt"
printf 'junk\n' >"$T/junk.txt"
expect_fail "missing file" 1 "$T/nope.pts" "$T/o1" \
    discrepancy -o "$T/o1" "$T/nope.pts"
expect_fail "4-D points" 1 "four.txt: 4-dimensional points; 2 or 3 are needed" \
    "$T/o2" discrepancy -o "$T/o2" "$T/four.txt"
expect_fail "coordinate outside [0,1)" 1 "out.txt" "$T/o3" \
    discrepancy -o "$T/o3" "$T/out.txt"
expect_fail "no points" 1 "empty.txt: no points" "$T/o4" \
    discrepancy -o "$T/o4" "$T/empty.txt"
expect_fail "junk" 1 "junk.txt" "$T/o5" discrepancy -o "$T/o5" "$T/junk.txt"
expect_fail "--sets not dividing" 1 "not a whole number of sets of 100" \
    "$T/o6" discrepancy --sets 100 -o "$T/o6" "$T/h.pts"
expect_fail "truncated binary" 1 "trunc.pts" "$T/o7" sh -c \
    "head -c 100 '$T/h.pts' >'$T/trunc.pts' && discrepancy -o '$T/o7' '$T/trunc.pts'"
expect_fail "-o in a missing directory" 1 "$T/no/dir" - \
    discrepancy -o "$T/no/dir/x" "$T/h.pts"
# A header count whose bytes overflow 64 bits: said so, not 2^64-1.
cp "$T/h.pts" "$T/huge.pts"
printf '\0\0\0\0\0\0\0\100' | dd of="$T/huge.pts" bs=1 seek=24 conv=notrunc 2>/dev/null
expect_fail "a count of 2^62" 1 "header says 4611686018427387904 points but the file holds 4096 bytes of records (more than 2^64 needed)" \
    "$T/o8" discrepancy -o "$T/o8" "$T/huge.pts"
# Control bytes of a file quoted in a message are escaped, never raw.
printf 'ab\007\033[31mred\001 0.5\n' >"$T/ctl.txt"
expect_fail "control bytes in a text file" 1 "ctl.txt:1: 'ab\\x07\\x1b[31mred\\x01' is not a number" \
    "$T/o9" discrepancy -o "$T/o9" "$T/ctl.txt"
{ for i in 1 2 3 4; do printf 'x\001\377\033[2J\007\233\r\016'; done
  tail -c 100 "$T/h.pts"; } >"$T/bin.dat"
discrepancy "$T/bin.dat" 2>"$T/bin.err"
if LC_ALL=C grep -q '[^ -~]' "$T/bin.err" || [ "$(wc -l <"$T/bin.err")" -ne 1 ]; then
	nok "a binary file's message carries no raw control bytes: $(od -c "$T/bin.err" | head -n 3)"
else
	ok "a binary file's message carries no raw control bytes"
fi
# Usage errors: exit 2.
expect_fail "--exact quad" 2 "no closed form for class quad" - \
    discrepancy -c quad --exact "$T/h.pts"
expect_fail "--shapes with star" 2 "--shapes" - \
    discrepancy -c star --shapes 10 "$T/h.pts"
expect_fail "--grid with circle" 2 "--grid" - \
    discrepancy -c circle --grid 10 "$T/h.pts"
expect_fail "unknown class" 2 "unknown class 'cube'" - \
    discrepancy -c cube "$T/h.pts"
expect_fail "--grid 1" 2 "--grid" - discrepancy --grid 1 "$T/h.pts"
expect_fail "no files" 2 "no point files" - discrepancy -c star
expect_fail "--group bad" 2 "--group: 'x' is not" - \
    discrepancy --group x "$T/h.pts"

# ---- 3-D sets: the star class in [0,1)^3 -----------------------------

# pts3 N SEED: N uniform random points in the unit cube, text.
pts3() {
	awk -v n="$1" -v s="$2" 'BEGIN { srand(s); for (i = 0; i < n; i++)
		printf "%.17g %.17g %.17g\n", rand(), rand(), rand() }'
}
pts3 64 1 >"$T/c64.txt"
pts3 12 2 >"$T/c12.txt"
pts3 20 3 >"$T/c20.txt"
# ties and points on grid lines: coordinates in eighths
awk 'BEGIN { srand(4); for (i = 0; i < 30; i++)
	printf "%.17g %.17g %.17g\n", int(rand() * 8) / 8, rand(), int(rand() * 4) / 4 }' \
    >"$T/ties.txt"

check "3-D star, default grid" discrepancy -o "$T/g3" "$T/c64.txt"
[ "$(col class "$T/g3")" = star ] && [ "$(col n "$T/g3")" = 64 ] &&
    [ "$(col method "$T/g3")" = grid100 ] && [ "$(col shapes "$T/g3")" = 1000000 ] &&
    ok "3-D: grid100, 100^3 boxes" || nok "3-D grid row: $(sed -n 2p "$T/g3")"
check "3-D --exact" discrepancy --exact -o "$T/e3" "$T/c64.txt"
[ "$(col method "$T/e3")" = exact ] && [ "$(col shapes "$T/e3")" = 0 ] &&
    ok "3-D --exact: method exact, 0 shapes" || nok "3-D exact row: $(sed -n 2p "$T/e3")"
awk -F '\t' 'NR == 2 { exit !($4 > 0 && $4 <= $6) }' "$T/e3" &&
    ok "3-D: 0 < D2 <= Dinf" || nok "3-D: D2, Dinf $(sed -n 2p "$T/e3")"
check "3-D --exact --grid" discrepancy --exact --grid 50 -o "$T/eg3" "$T/c64.txt"
[ "$(col method "$T/eg3")" = exact+grid50 ] && [ "$(col shapes "$T/eg3")" = 125000 ] &&
    [ "$(col D2 "$T/eg3")" = "$(col D2 "$T/e3")" ] &&
    ok "3-D --exact --grid: exact D2, grid Dinf" || nok "3-D exact+grid: $(sed -n 2p "$T/eg3")"

# Warnock's D2 in 3-D, evaluated directly (every ordered pair) by awk.
warnock3() {
	awk 'BEGIN { n = 0 } { x[n] = $1; y[n] = $2; z[n] = $3; n++ } END {
		for (i = 0; i < n; i++) {
			s1 += (1 - x[i] ^ 2) * (1 - y[i] ^ 2) * (1 - z[i] ^ 2)
			for (j = 0; j < n; j++) {
				u = 1 - (x[i] > x[j] ? x[i] : x[j])
				v = 1 - (y[i] > y[j] ? y[i] : y[j])
				w = 1 - (z[i] > z[j] ? z[i] : z[j])
				s2 += u * v * w
			}
		}
		printf "%.12g\n", sqrt(1 / 27 - s1 / (4 * n) + s2 / (n * n)) }' "$1"
}
near "$(col D2 "$T/e3")" "$(warnock3 "$T/c64.txt")" 1e-7 &&
    ok "3-D exact D2 = Warnock's sum" ||
    nok "3-D exact D2 $(col D2 "$T/e3"), direct $(warnock3 "$T/c64.txt")"

# Dinf over every critical corner, both counts, by awk.
dinf3() {
	awk 'BEGIN { n = 0 } { x[n] = $1; y[n] = $2; z[n] = $3; n++ } END {
		x[n] = y[n] = z[n] = 1
		for (i = 0; i <= n; i++) for (j = 0; j <= n; j++) for (l = 0; l <= n; l++) {
			a = x[i]; b = y[j]; c = z[l]; v = a * b * c; o = 0; k = 0
			for (p = 0; p < n; p++) {
				o += x[p] < a && y[p] < b && z[p] < c
				k += x[p] <= a && y[p] <= b && z[p] <= c
			}
			if (v - o / n > m) m = v - o / n
			if (k / n - v > m) m = k / n - v
		}
		printf "%.12g\n", m }' "$1"
}
for f in c12 ties; do
	discrepancy --exact -o "$T/d3" "$T/$f.txt"
	near "$(col Dinf "$T/d3")" "$(dinf3 "$T/$f.txt")" 1e-8 &&
	    ok "3-D exact Dinf = brute force ($f)" ||
	    nok "3-D exact Dinf ($f): $(col Dinf "$T/d3"), brute $(dinf3 "$T/$f.txt")"
done

# The grid by awk: s^3 corners, every point.
grid3() {
	awk -v s="$2" 'BEGIN { n = 0 } { x[n] = $1; y[n] = $2; z[n] = $3; n++ } END {
		for (i = 1; i <= s; i++) for (j = 1; j <= s; j++) for (l = 1; l <= s; l++) {
			c = 0
			for (p = 0; p < n; p++)
				c += x[p] < i / s && y[p] < j / s && z[p] < l / s
			d = c / n - (i / s) * (j / s) * (l / s); d = d < 0 ? -d : d
			q += d * d; if (d > m) m = d
		}
		printf "%.12g %.12g\n", sqrt(q / (s * s * s)), m }' "$1"
}
for f in c20 ties; do
	discrepancy --grid 8 -o "$T/gg" "$T/$f.txt"
	r=$(grid3 "$T/$f.txt" 8)
	near "$(col D2 "$T/gg")" "${r% *}" 1e-7 && near "$(col Dinf "$T/gg")" "${r#* }" 1e-8 &&
	    ok "3-D grid = brute force ($f)" ||
	    nok "3-D grid ($f): $(col D2 "$T/gg") $(col Dinf "$T/gg"), brute $r"
done

# Sets, threads, standard input.
pts3 1024 5 >"$T/c1024.txt"
for m in "" "--exact" "--grid 30"; do
	discrepancy $m --sets 256 -j 1 --per-set "$T/c1024.txt" >"$T/a" 2>"$T/err"
	discrepancy $m --sets 256 -j 2 --per-set "$T/c1024.txt" >"$T/b" 2>>"$T/err"
	cmp -s "$T/a" "$T/b" && [ "$(wc -l <"$T/a")" -eq 5 ] &&
	    ok "3-D ${m:-grid}: -j 1 = -j 2, 4 sets" || nok "3-D ${m:-grid}: -j or --sets"
done
discrepancy --exact -j 1 "$T/c1024.txt" >"$T/a" 2>"$T/err"
discrepancy --exact -j 2 "$T/c1024.txt" >"$T/b" 2>>"$T/err"
cmp -s "$T/a" "$T/b" && ok "3-D --exact one set: -j 1 = -j 2" || nok "3-D one set -j"
discrepancy --exact - <"$T/c64.txt" >"$T/x" 2>"$T/err"
cmp -s "$T/x" "$T/e3" && ok "3-D text on standard input" || nok "3-D on stdin"
# an extra column (a density) is not a coordinate
awk 'BEGIN { print "#pts dims=3 extra=1" } { print $0, 7 }' "$T/c64.txt" >"$T/c64w.txt"
discrepancy --exact "$T/c64w.txt" >"$T/x" 2>"$T/err"
cmp -s "$T/x" "$T/e3" && ok "3-D with an extra column" || nok "3-D extra column"

# Random sets: mean D2^2 near (2^-3 - 3^-3)/n (20 sets of 128: the
# standard error is about 10 %).
pts3 2560 6 >"$T/c2560.txt"
discrepancy --exact --sets 128 --per-set "$T/c2560.txt" >"$T/p3"
awk -F '\t' 'NR > 1 { s += $4 * $4; k++ } END {
	e = (1 / 8 - 1 / 27) / 128; exit !(k == 20 && s / k > 0.6 * e && s / k < 1.4 * e) }' \
    "$T/p3" && ok "3-D random: mean D2^2 = (1/8 - 1/27)/n" ||
    nok "3-D random: mean D2^2 $(awk -F '\t' 'NR > 1 { s += $4 * $4; k++ } END { print s / k }' "$T/p3")"

# 3-D errors: exit 1, the file and the problem named, no output.
for c in rect quad half circle; do
	expect_fail "3-D -c $c" 1 "c64.txt: class $c is 2-D only; 3-D sets take the star class (-c star)" \
	    "$T/o3d" discrepancy -c $c -o "$T/o3d" "$T/c64.txt"
done
expect_fail "2-D then 3-D" 1 "c64.txt: 3-dimensional points after 2-dimensional" \
    "$T/o3d" discrepancy -o "$T/o3d" "$T/h.pts" "$T/c64.txt"
expect_fail "3-D then 2-D" 1 "h.pts: 2-dimensional points after 3-dimensional" \
    "$T/o3d" discrepancy -o "$T/o3d" "$T/c64.txt" "$T/h.pts"
pts3 4097 7 >"$T/c4097.txt"
expect_fail "3-D exact Dinf above 4096 points" 1 \
    "c4097.txt: 4097 points: the exact 3-D Dinf" "$T/o3d" \
    discrepancy --exact -o "$T/o3d" "$T/c4097.txt"
grep -q "use --grid" "$T/err" && ok "the limit suggests --grid" || nok "limit message"
# --d2-only: past the exact Dinf's limit, the D2 of --exact --grid
check "3-D 4097 points, --exact --d2-only" discrepancy --exact --d2-only \
    -o "$T/o3o" "$T/c4097.txt"
discrepancy --exact --grid 20 "$T/c4097.txt" >"$T/o3g2"
[ "$(col D2 "$T/o3o")" = "$(col D2 "$T/o3g2")" ] && [ "$(col Dinf "$T/o3o")" = nan ] &&
    [ "$(col method "$T/o3o")" = exact:D2 ] && ok "3-D --exact --d2-only: D2, Dinf nan" ||
    nok "3-D --d2-only: $(sed -n 2p "$T/o3o"), exact+grid $(sed -n 2p "$T/o3g2")"
discrepancy --exact --dinf-only "$T/c64.txt" >"$T/o3i"
[ "$(col Dinf "$T/o3i")" = "$(col Dinf "$T/e3")" ] && [ "$(col D2 "$T/o3i")" = nan ] &&
    ok "3-D --exact --dinf-only" || nok "3-D --dinf-only: $(sed -n 2p "$T/o3i")"
check "3-D 4097 points, --exact --grid" discrepancy --exact --grid 20 -o "$T/o3g" "$T/c4097.txt"
expect_fail "3-D --grid 1001" 1 \
    "c64.txt: grid 1001: a 3-D grid has s^3 boxes and takes O(s^3) time; 2 to 1000 allowed; set it with --grid S" "$T/o3d" \
    discrepancy --grid 1001 -o "$T/o3d" "$T/c64.txt"
# a failure in a later set leaves no output either
expect_fail "3-D bad set among good" 1 "c4097.txt" "$T/o3d" \
    discrepancy --exact -o "$T/o3d" "$T/c64.txt" "$T/c4097.txt"

# Sets that flow through a pipe: frs-sample --sets 4 writes a set column
# (pts(5) version 2; count 0 on a pipe), which discrepancy splits by with
# no --sets N; the rows are those of the four seeds run one by one.
frs-sample -q -i blob -n 200 --sets 4 | discrepancy -c star --grid 300 --per-set - >"$T/fs"
for s in 1 2 3 4; do
	frs-sample -q -i blob -n 200 -S $s | discrepancy -c star --grid 300 --per-set - | tail -n 1
done >"$T/fs1"
[ "$(tail -n +2 "$T/fs" | cut -f 1,2,4-7)" = "$(cut -f 1,2,4-7 "$T/fs1")" ] &&
    [ "$(tail -n +2 "$T/fs" | cut -f 3 | tr '\n' ' ')" = "0 1 2 3 " ] &&
    ok "frs-sample --sets 4 | discrepancy: the rows of the four seeds" ||
    nok "frs-sample --sets 4 | discrepancy: $(cat "$T/fs")"
[ "$(frs-sample -q -i blob -n 200 --sets 4 | od -A n -t u8 -j 24 -N 8 | tr -d ' ')" = 0 ] &&
    ok "the stream's header counts 0 (unknown)" || nok "stream count"
frs-sample -q -i blob -n 200 --sets 4 | discrepancy -c rect --grid 40 --group file - >"$T/ff"
for s in 1 2 3 4; do frs-sample -q -i blob -n 200 -S $s -o "$T/f$s.pts"; done
discrepancy -c rect --grid 40 --group all "$T/f1.pts" "$T/f2.pts" "$T/f3.pts" "$T/f4.pts" >"$T/ff1"
[ "$(cut -f 1-9 "$T/ff")" = "$(cat "$T/ff1")" ] && [ "$(col file "$T/ff")" = - ] &&
    ok "--group file of the stream = the four files together" ||
    nok "--group file of the stream: $(cat "$T/ff") / $(cat "$T/ff1")"
# --sets N beside a set column: the same when they agree, else an error.
ref-sample -q -k random -n 64 --sets 4 -o "$T/rs.pts"
discrepancy -c star --exact --per-set "$T/rs.pts" >"$T/rs1"
discrepancy -c star --exact --per-set --sets 64 "$T/rs.pts" >"$T/rs2"
cmp -s "$T/rs1" "$T/rs2" && [ "$(wc -l <"$T/rs1")" = 5 ] &&
    ok "--sets 64 agreeing with the set column" || nok "--sets 64 with a set column"
discrepancy -c star --exact --per-set --sets 32 "$T/rs.pts" >"$T/rs4" 2>"$T/err"
cmp -s "$T/rs1" "$T/rs4" &&
    grep -q "^discrepancy: warning: $T/rs.pts: .*set column have 64 points, not 32" "$T/err" &&
    ok "--sets 32 beside a set column of 64: its sets, a warning naming the file" ||
    nok "--sets 32 beside a set column: $(cat "$T/err")"
# Old files (pts(5) version 1, no set column) still read: the same sets
# cut by --sets 64 give the same rows; a binary file of version 1 too.
ref-sample -q -k random -n 64 --sets 4 -T |
    awk 'NR == 1 { print "#pts dims=2 extra=0 count=256"; next } { print $1, $2 }' >"$T/old.txt"
discrepancy -c star --exact --per-set --sets 64 "$T/old.txt" >"$T/rs3"
[ "$(cut -f 1-7 "$T/rs3")" = "$(cut -f 1-7 "$T/rs1")" ] &&
    ok "version 1 text, --sets 64: the rows of the set column" || nok "version 1 text"
cp "$T/r1.pts" "$T/old1.pts"
printf '\001' | dd of="$T/old1.pts" bs=1 seek=8 conv=notrunc 2>/dev/null
[ "$(od -A n -t u4 -j 8 -N 4 "$T/old1.pts" | tr -d ' ')" = 1 ] &&
    discrepancy -c star --exact "$T/old1.pts" | cut -f 1-9 >"$T/o1a" &&
    discrepancy -c star --exact "$T/r1.pts" | cut -f 1-9 >"$T/o1b" && cmp -s "$T/o1a" "$T/o1b" &&
    ok "version 1 binary: the same row" || nok "version 1 binary"
printf '#pts dims=2 extra=1 names=set\n0.1 0.2 1\n0.3 0.4 0\n' >"$T/dec.txt"
expect_fail "set column decreasing" 1 "dec.txt: point 1: set 0 after set 1" "$T/o9" \
    discrepancy -o "$T/o9" "$T/dec.txt"
printf '#pts dims=2 extra=1 names=set\n0.1 0.2 0.5\n' >"$T/half.txt"
expect_fail "set column not whole" 1 "half.txt: point 0: set 0.5 is not a whole number" "$T/o9" \
    discrepancy -o "$T/o9" "$T/half.txt"
# A pdf column: the points follow a density, but the discrepancy is that
# of the plain area; a warning names the file and says so, once per
# file, none for a file without one or under -q; the table is the same.
hsw-sample -i blob -n 300 --pdf -o "$T/pdf.pts"
hsw-sample -i blob -n 300 -o "$T/nopdf.pts"
discrepancy --grid 100 --per-set "$T/pdf.pts" "$T/pdf.pts" >"$T/w1" 2>"$T/err"
[ "$(grep -c "discrepancy: warning: $T/pdf.pts: .*pdf.*area" "$T/err")" = 2 ] &&
    [ "$(wc -l <"$T/err")" = 2 ] &&
    ok "a pdf column: a warning per file naming it, the area measured" ||
    nok "pdf column warning: $(cat "$T/err")"
discrepancy --grid 100 --per-set "$T/nopdf.pts" "$T/nopdf.pts" >"$T/w2" 2>"$T/err"
[ ! -s "$T/err" ] && [ "$(cut -f 1-7 "$T/w1")" = "$(cut -f 1-7 "$T/w2")" ] &&
    ok "no pdf column: no warning, the same discrepancies" ||
    nok "no pdf column: $(cat "$T/err")"
discrepancy -q --grid 100 "$T/pdf.pts" >/dev/null 2>"$T/err"
[ ! -s "$T/err" ] && ok "-q: no pdf warning" || nok "-q pdf warning: $(cat "$T/err")"
done_testing
