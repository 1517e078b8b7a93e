#!/bin/sh
# frd-prep: imports, validation and prepared matrices.
. "$(dirname "$0")/lib.sh"

# The thesis authors' matrix: raw little-endian int32, 512 x 512.
check "import the authors' raw32 matrix" frd-prep --import raw32 \
    "$TD/authors-512x512.matrix" -o "$T/a.frd"
tail -c $((4 * 512 * 512)) "$T/a.frd" | cmp -s - "$TD/authors-512x512.matrix" &&
    ok "values kept as they are" || nok "values kept as they are"
check "sample from it" frs-sample -m "$T/a.frd" -i blob -n 1000 -o "$T/a.pts"

# Text, with ranks of arbitrary values.
printf '3 0 2\n1 5 4\n' >"$T/m.txt"
frd-prep --import text "$T/m.txt" -o "$T/t.frd" &&
    [ "$(tail -c 24 "$T/t.frd" | od -A n -t u4 | tr -s ' \n' ' ')" = " 3 0 2 1 5 4 " ] &&
    ok "text import" || nok "text import"
printf '30 0 20\n10 50 40\n' >"$T/r.txt"
expect_fail "text that is no permutation" 1 "--rank" "$T/r.frd" frd-prep --import text "$T/r.txt" -o "$T/r.frd"
frd-prep --import text --rank "$T/r.txt" -o "$T/r.frd" &&
    [ "$(tail -c 24 "$T/r.frd" | od -A n -t u4 | tr -s ' \n' ' ')" = " 3 0 2 1 5 4 " ] &&
    ok "--rank turns values into ranks" || nok "--rank turns values into ranks"

# A 16-bit PNG mask: its grey levels become ranks.
imap gen ramp -s 8x4 -o "$T/mask.png"
frd-prep --import png16 "$T/mask.png" -o "$T/p.frd" && frd-prep --check "$T/p.frd" -o /dev/null &&
    ok "png16 import is a permutation" || nok "png16 import is a permutation"

# Prepared matrices.
frd-gen -s 64 -o "$T/g.frd"
check "prepare all" frd-prep -a all "$T/g.frd" -o "$T/g.frp"
head -c 8 "$T/g.frp" | od -A n -t x1 | grep -q '89 46 52 50 0d 0a 1a 0a' && ok ".frp magic" || nok ".frp magic"
frs-sample -m "$T/g.frd" -i blob -n 500 -T -o "$T/f1.txt" &&
    frs-sample -m "$T/g.frp" -i blob -n 500 -T -o "$T/f2.txt" && cmp -s "$T/f1.txt" "$T/f2.txt" &&
    ok "same points from .frd and .frp" || nok "same points from .frd and .frp"
for a in stack level1 level2; do
	frs-sample -m "$T/g.frp" -a $a -i blob -n 500 -T | grep -v '^#' | sort >"$T/$a.s"
done
grep -v '^#' "$T/f1.txt" | sort >"$T/sorted.s"
cmp -s "$T/stack.s" "$T/sorted.s" && cmp -s "$T/level2.s" "$T/sorted.s" &&
    ok "minmap implementations from a .frp" || nok "minmap implementations from a .frp"
cp "$T/g.frp" "$T/bad.frp"
printf 'X' | dd of="$T/bad.frp" bs=1 seek=100 conv=notrunc 2>/dev/null
expect_fail "damaged .frp" 1 "checksum" "$T/o.pts" frs-sample -m "$T/bad.frp" -n 10 -o "$T/o.pts"

# Bad input.
expect_fail "raw32 of the wrong length" 1 "not a whole number" "$T/o.frd" \
    sh -c "printf 'abc' >'$T/x.raw'; frd-prep --import raw32 '$T/x.raw' -o '$T/o.frd'"
expect_fail "raw32 not square" 1 "3 values are not a square; give the size with -s WxH" "$T/o.frd" \
    sh -c "head -c 12 /dev/zero >'$T/y.raw'; frd-prep --import raw32 '$T/y.raw' -o '$T/o.frd'"
expect_fail "raw32 with repeats" 1 "not a permutation" "$T/o.frd" \
    sh -c "head -c 16 /dev/zero >'$T/z.raw'; frd-prep --import raw32 '$T/z.raw' -o '$T/o.frd'"
printf '1 2\n3\n' >"$T/ragged.txt"
expect_fail "ragged text" 1 "the first row has 2" "$T/o.frd" frd-prep --import text "$T/ragged.txt" -o "$T/o.frd"
printf '1 x\n' >"$T/word.txt"
expect_fail "text with a word" 1 "not an integer" "$T/o.frd" frd-prep --import text "$T/word.txt" -o "$T/o.frd"
expect_fail "unknown import" 2 "--import" "$T/o.frd" frd-prep --import jpeg "$T/g.frd" -o "$T/o.frd"
# A .frd's values are checked to be a permutation only with --check.
cp "$T/g.frd" "$T/rep.frd"
tail -c 8 "$T/g.frd" | head -c 4 | dd of="$T/rep.frd" bs=1 \
    seek=$(($(wc -c <"$T/g.frd") - 4)) conv=notrunc 2>/dev/null
frd-prep "$T/rep.frd" -o "$T/rep2.frd" && cmp -s "$T/rep.frd" "$T/rep2.frd" &&
    ok "a .frd with a repeat is copied without --check" ||
    nok "a .frd with a repeat is copied without --check"
expect_fail "--check of a .frd with a repeat" 1 "rep.frd: not a permutation: value" \
    "$T/o.frd" frd-prep --check "$T/rep.frd" -o "$T/o.frd"
# The importers read their inputs themselves (the library's messages for
# its own inputs): standard input, a directory, the memory ceiling on
# the growing buffer; PNG through the library.
frd-prep --import text -o "$T/t2.frd" <"$T/m.txt" && cmp -s "$T/t.frd" "$T/t2.frd" &&
    ok "text import from standard input" || nok "text import from standard input"
frd-prep --import png16 -o "$T/p2.frd" <"$T/mask.png" && cmp -s "$T/p.frd" "$T/p2.frd" &&
    ok "png16 import from standard input" || nok "png16 import from standard input"
mkdir -p "$T/dir"
expect_fail "raw32 of a directory" 1 "frd-prep: $T/dir: is a directory" "$T/o.frd" \
    frd-prep --import raw32 "$T/dir" -o "$T/o.frd"
expect_fail "text that is not there" 1 "frd-prep: $T/none.txt: No such file" "$T/o.frd" \
    frd-prep --import text "$T/none.txt" -o "$T/o.frd"
seq 0 19999 >"$T/big.txt"
expect_fail "text beyond FRS_MAX_MEM" 1 \
    "frd-prep: $T/big.txt: needs 128.0 KiB, above the memory limit of 64.0 KiB (FRS_MAX_MEM)" \
    "$T/o.frd" env FRS_MAX_MEM=64K frd-prep --import text "$T/big.txt" -o "$T/o.frd"
expect_fail "png16 of a text file" 1 "frd-prep: $T/word.txt: bad PNG" "$T/o.frd" \
    frd-prep --import png16 "$T/word.txt" -o "$T/o.frd"
expect_fail "unknown algorithm" 2 "-a" "$T/o.frp" frd-prep -a fast "$T/g.frd" -o "$T/o.frp"
expect_fail "block too large" 1 "exceeds" "$T/o.frp" frd-prep -a sorted --blocks 128 "$T/g.frd" -o "$T/o.frp"

# Damaged derived data (not covered by the checksum) are caught too, when
# read: 200000 samples of const at 64^2 with sigma 1 need the lists of
# blocks of 4 and 3125 of the 4096 values, more than half, so that they
# come from the .frp (frd-prep --for says so); 500 of blob need blocks of
# 4 and 56 values, made without reading the .frp's lists.
[ "$(frd-prep --for 200000 -i const --sigma 1 "$T/g.frd" | awk -F '\t' \
    'NR == 2 { print $5, $8 }')" = "4 yes" ] &&
    ok "--for: 200000 of const, sigma 1: blocks of 4 from the .frp" ||
    nok "--for: $(frd-prep --for 200000 -i const --sigma 1 "$T/g.frd" | tr '\n' ' ')"
frd-prep -a sorted --blocks 4 "$T/g.frd" -o "$T/bad2.frp"
size=$(wc -c <"$T/bad2.frp")
printf '\377\377\377\177' | dd of="$T/bad2.frp" bs=1 seek=$((size - 8)) conv=notrunc 2>/dev/null
expect_fail "damaged sorted list" 1 "damaged sorted list" "$T/o.pts" \
    frs-sample -m "$T/bad2.frp" -i const --sigma 1 -n 200000 -o "$T/o.pts"
[ "$(grep -o 'bad2.frp' "$T/err" | wc -l)" -eq 1 ] &&
    ok "the damaged list's message names the file once" ||
    nok "the damaged list's message names the file once: $(cat "$T/err")"
expect_fail "--check reads every set of a .frp" 1 "damaged sorted list" - \
    frd-prep --check "$T/bad2.frp"

# A .frp must hold all that its header announces, though its sorted
# lists are read only when needed; --check checks a .frp.
size=$(wc -c <"$T/g.frp")
for cut in 1 100 5000; do
	head -c $((size - cut)) "$T/g.frp" >"$T/cut.frp"
	expect_fail ".frp cut by $cut bytes" 1 "cut.frp: truncated: the file has $((size - cut)) bytes" \
	    "$T/o.pts" frs-sample -m "$T/cut.frp" -n 100 -o "$T/o.pts"
	expect_fail "--check of a .frp cut by $cut bytes" 1 "cut.frp: truncated" - \
	    frd-prep --check "$T/cut.frp"
	expect_fail "--check of a .frp cut by $cut bytes, in a pipe" 1 "<stdin>: truncated sorted" - \
	    sh -c "head -c $((size - cut)) '$T/g.frp' | frd-prep --check"
done
grep -q 'set 7 of 7' "$T/err" && ok "the pipe's message names the set" ||
    nok "the pipe's message names the set: $(cat "$T/err")"
head -c 30000 "$T/g.frp" >"$T/cut.frp"
expect_fail ".frp cut in its first set" 1 "sets 1 to 7 of 7 are missing" "$T/o.pts" \
    frs-sample -m "$T/cut.frp" -n 100 -o "$T/o.pts"
{ cat "$T/g.frp"; printf 'xy'; } >"$T/long.frp"
expect_fail ".frp with trailing data" 1 "long.frp: 2 bytes of trailing data" "$T/o.pts" \
    frs-sample -m "$T/long.frp" -n 100 -o "$T/o.pts"
frd-prep --check "$T/g.frp" >"$T/chk.txt" &&
    grep -q "g.frp: a valid prepared matrix: 64x64, checksum [0-9a-f]*, a minmap, sorted lists of blocks 1,2,4,8,16,32,64$" "$T/chk.txt" &&
    ok "--check of a valid .frp says so" || nok "--check of a valid .frp: $(cat "$T/chk.txt")"
frd-prep --check <"$T/g.frp" >"$T/chk.txt" && grep -q 'valid prepared matrix' "$T/chk.txt" &&
    ok "--check of a valid .frp on standard input" || nok "--check of a valid .frp on standard input"
expect_fail "-a all of a .frp" 1 "g.frp: a prepared matrix (.frp)" "$T/o.frp" \
    frd-prep -a all "$T/g.frp" -o "$T/o.frp"
# Matrices that cannot be prepared: the message names the input.
frd-gen -q -s 48x32 -o "$T/r.frd"
expect_fail "-a all of a 48x32 matrix names the input" 1 "r.frd: the matrix is 48x32" "$T/o.frp" \
    frd-prep -a all "$T/r.frd" -o "$T/o.frp"
frd-gen -q -s 8 -k 3 -o "$T/v.frd"
expect_fail "-a all of a 3-D matrix names the input" 1 "v.frd: only 2-D" "$T/o.frp" \
    frd-prep -a all "$T/v.frd" -o "$T/o.frp"
# A damaged .frp beside its matrix is skipped with a warning.
cp "$T/g.frd" "$T/h.frd"
cp "$T/g.frp" "$T/h.frp"
printf 'X' | dd of="$T/h.frp" bs=1 seek=100 conv=notrunc 2>/dev/null
frs-sample -m "$T/h.frd" -i blob -n 500 -T -o "$T/h.txt" 2>"$T/warn" &&
    grep -q 'ignored' "$T/warn" && cmp -s "$T/h.txt" "$T/f1.txt" &&
    ok "a damaged .frp beside the matrix is skipped" || nok "a damaged .frp beside the matrix is skipped"
# Its damaged lists are not read by a run that reaches few values (it
# makes those): the points of the matrix alone, beside it or given.
cp "$T/bad2.frp" "$T/h.frp"
frs-sample -m "$T/h.frd" -i blob -n 500 -T -o "$T/h.txt" 2>"$T/warn" &&
    cmp -s "$T/h.txt" "$T/f1.txt" &&
    frs-sample -m "$T/bad2.frp" -i blob -n 500 -T -o "$T/h2.txt" 2>>"$T/warn" &&
    cmp -s "$T/h2.txt" "$T/f1.txt" &&
    ok "damaged lists unread by a small run" ||
    nok "damaged lists unread by a small run: $(cat "$T/warn")"
expect_fail "--blocks without sorted" 2 "--blocks needs" "$T/o.frd" frd-prep --blocks 8 "$T/g.frd" -o "$T/o.frd"

# --for: the block sizes Sorted needs for the counts on a map; a .frp
# made with them serves those runs without making lists, a .frp without
# them still gives the points of the .frd (its lists made, said under -v).
frd-gen -q -s 128 -o "$T/f.frd"
frd-prep --for 100,20000 -i blob --tiles plain "$T/f.frd" >"$T/for.tsv" &&
    [ "$(awk -F '\t' 'NR > 1 { printf "%s:%s:%s ", $1, $2, $5 }' "$T/for.tsv")" = "100:0:2 20000:0:32 " ] &&
    ok "--for --tiles plain: blocks 2 and 32 for 100 and 20000 on blob" ||
    nok "--for --tiles plain: $(tr '\n' ' ' <"$T/for.tsv")"
# With levels (the default), a row per level: the levels of one count
# (increasing, from 0 to at most log2 n_s), n_s halved from one to the
# next, blocks of n_s (or none: the level scans its pixels).
frd-prep --for 20000 -i blob "$T/f.frd" >"$T/lev.tsv" &&
    awk -F '\t' 'NR > 1 { if (NR > 2 && ($2 <= l || $3 * 2^($2 - l) != ns)) bad = 1;
	if ($5 != 0 && $5 != $3) bad = 1; l = $2; ns = $3; rows++ }
	END { exit !(rows >= 2 && !bad) }' "$T/lev.tsv" &&
    ok "--for with levels: a row per level, n_s halving, blocks of n_s or none" ||
    nok "--for with levels: $(tr '\n' ' ' <"$T/lev.tsv")"
frd-prep -a sorted --for 20000 -i blob "$T/f.frd" -o "$T/lev.frp"
frs-sample -q -m "$T/f.frd" -i blob -n 20000 -o "$T/l0.pts"
frs-sample -q -m "$T/lev.frp" -i blob -n 20000 -v -o "$T/l1.pts" 2>"$T/lv1"
cmp -s "$T/l0.pts" "$T/l1.pts" && ! grep -q 'no sorted lists' "$T/lv1" &&
    ok "--for's .frp serves every level" || nok "--for's .frp with levels: $(cat "$T/lv1")"
# (40000 of const with sigma 1 need blocks of 2 and 10000 values: from a
# .frp.)
frd-prep -a sorted --for 40000 -i const --sigma 1 "$T/f.frd" -o "$T/for.frp"
frd-prep -a sorted --blocks 4 "$T/f.frd" -o "$T/b4.frp"
set -- -i const --sigma 1 -n 40000
frs-sample -q -m "$T/f.frd" "$@" -o "$T/f0.pts"
frs-sample -q -m "$T/for.frp" "$@" -v -o "$T/f1.pts" 2>"$T/v1"
frs-sample -q -m "$T/b4.frp" "$@" -v -o "$T/f2.pts" 2>"$T/v2"
cmp -s "$T/f0.pts" "$T/f1.pts" && ! grep -q 'no sorted lists' "$T/v1" &&
    ok "--for's .frp: its lists used" || nok "--for's .frp: $(cat "$T/v1")"
cmp -s "$T/f0.pts" "$T/f2.pts" &&
    grep -q 'b4.frp has no sorted lists of blocks of 2: made them here' "$T/v2" &&
    ok "a .frp without the block: the same points, the lists made, said under -v" ||
    nok "a .frp without the block: $(cat "$T/v2")"
expect_fail "--for with --blocks" 2 "one or the other" "$T/x.frp" \
    frd-prep -a sorted --for 100 --blocks 4 "$T/f.frd" -o "$T/x.frp"
expect_fail "--for 0" 2 "--for" "$T/x.frp" frd-prep --for 0 "$T/f.frd" -o "$T/x.frp"
expect_fail "--for with -a stack" 2 "--for needs" "$T/x.frp" \
    frd-prep -a stack --for 100 "$T/f.frd" -o "$T/x.frp"
# The map options of frs-sample for --for's map: --size-map (frs-sample's
# -s), --equirect (the table of imap convert --equirect's map) and
# --strict (negative importance an error).
imap convert --equirect -s 64x32 sky "$T/sky-eq.exr"
frd-prep --for 100,3000 -i sky --size-map 64x32 --equirect "$T/f.frd" >"$T/fe.tsv" &&
    frd-prep --for 100,3000 -i "$T/sky-eq.exr" "$T/f.frd" >"$T/fc.tsv" &&
    cmp -s "$T/fe.tsv" "$T/fc.tsv" && [ "$(wc -l <"$T/fe.tsv")" -ge 3 ] &&
    ok "--for --equirect --size-map: the table of the converted map" ||
    nok "--for --equirect: $(cat "$T/fe.tsv" "$T/fc.tsv" | tr '\n' ' ')"
frd-prep -a sorted --for 3000 -i sky --size-map 64x32 --equirect "$T/f.frd" -o "$T/eq.frp" &&
    frs-sample -q -m "$T/eq.frp" -i sky -s 64x32 --equirect -n 3000 -v -o "$T/eq.pts" 2>"$T/v3" &&
    frs-sample -q -m "$T/f.frd" -i sky -s 64x32 --equirect -n 3000 -o "$T/eq0.pts" &&
    cmp -s "$T/eq.pts" "$T/eq0.pts" && ! grep -q 'no sorted lists' "$T/v3" &&
    ok "--for --equirect's .frp: frs-sample --equirect uses its lists" ||
    nok "--for --equirect's .frp: $(cat "$T/v3")"
expect_fail "--strict refuses negative importance" 1 "is negative" - \
    frd-prep --for 100 -i "$TD/interior.exr" --size-map 64x32 --strict "$T/f.frd"
for o in --equirect --strict "--size-map 64x32"; do
	# shellcheck disable=SC2086
	expect_fail "$o without --for" 2 "--for" - frd-prep $o "$T/f.frd" -o "$T/x.frd"
done
done_testing
