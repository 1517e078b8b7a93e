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

check "star on two sets" discrepancy -c star --grid 300 -o "$T/t" \
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

# Rows per point count, in order of first appearance.
discrepancy -c star --exact "$T/small.pts" "$T/r1.pts" "$T/h.pts" >"$T/g"
[ "$(col n "$T/g" 1) $(col n "$T/g" 2) $(col sets "$T/g" 2)" = "64 256 2" ] &&
    ok "a row per point count" || nok "rows per n: $(cat "$T/g")"
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
[ "$(wc -l <"$T/gf")" -eq 3 ] && ok "--group file: a row per file" || nok "--group file"

# --sets N equals separate files, byte for byte.
cat "$T/r1.pts" >"$T/both.pts"
tail -c +33 "$T/r2.pts" >>"$T/both.pts"
printf '\000\002' | dd of="$T/both.pts" bs=1 seek=24 conv=notrunc 2>/dev/null
# patch the count to 512: little-endian 0x200
printf '\000\002\000\000\000\000\000\000' | dd of="$T/both.pts" bs=1 seek=24 \
    conv=notrunc 2>/dev/null
for c in "star --grid 300" "rect --grid 40" "half --grid 50" \
    "quad --shapes 2000" "circle --shapes 2000"; do
	discrepancy -c $c "$T/r1.pts" "$T/r2.pts" >"$T/a" 2>"$T/err"
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

# -o: atomic, nothing left on failure.
check "-o FILE" discrepancy -c star --grid 100 -o "$T/out.tsv" "$T/h.pts"
[ -s "$T/out.tsv" ] && ok "-o wrote the table" || nok "-o wrote the table"

# Bad input: exit 1, the file named, no output.
printf '#pts dims=3 extra=0 count=1\n0.1 0.2 0.3\n' >"$T/three.txt"
printf '0.1 0.2\n1.5 0.2\n' >"$T/out.txt"
printf '#pts dims=2 extra=0 count=0\n' >"$T/empty.txt"
printf 'junk\n' >"$T/junk.txt"
expect_fail "missing file" 1 "$T/nope.pts" "$T/o1" \
    discrepancy -o "$T/o1" "$T/nope.pts"
expect_fail "3-D points" 1 "three.txt: 3-dimensional points" "$T/o2" \
    discrepancy -o "$T/o2" "$T/three.txt"
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
