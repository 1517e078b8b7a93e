#!/bin/sh
# frs-sample: output, determinism, options, hard cases and bad input.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/ptsutil.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)

# A small matrix keeps the tests fast; the default one is tried once.
frd-gen -s 256 --tol 1e-2 -o "$T/m.frd"
M=$T/m.frd

check "blob, 2000 samples" frs-sample -m "$M" -i blob -n 2000 -o "$T/a.pts"
cnt=$(pts_count "$T/a.pts")
[ "$cnt" -gt 1900 ] && [ "$cnt" -lt 2100 ] && ok "about n samples ($cnt)" ||
    nok "about n samples ($cnt)"
[ "$(wc -c <"$T/a.pts")" -eq $((32 + 16 * cnt)) ] && ok "binary .pts layout" ||
    nok "binary .pts layout"

# Same bytes for any thread count and implementation order aside.
frs-sample -m "$M" -i blob -n 3000 -j 1 -T -o "$T/j1.txt"
frs-sample -m "$M" -i blob -n 3000 -j 2 -T -o "$T/j2.txt"
cmp -s "$T/j1.txt" "$T/j2.txt" && ok "-j 1 and -j 2 give the same bytes" ||
    nok "-j 1 and -j 2 give the same bytes"
impls_same "$T/j1.txt" -m "$M" -i blob -n 3000 &&
    ok "all implementations give the same points" ||
    nok "all implementations give the same points"
frs-sample -m "$M" -i blob -n 3000 -S 2 -T -o "$T/s2.txt"
cmp -s "$T/j1.txt" "$T/s2.txt" && nok "another seed moves the window" ||
    ok "another seed moves the window"

# Columns: --pdf adds I / mean I; jitter keeps points in their elements.
frs-sample -m "$M" -i const -n 500 --pdf -T -o "$T/pdf.txt"
awk '!/^#/ && ($3 < 0.999999 || $3 > 1.000001) { bad = 1 } END { exit bad }' "$T/pdf.txt" &&
    ok "--pdf of a constant map is 1" || nok "--pdf of a constant map is 1"
head -n 1 "$T/pdf.txt" | grep -q 'dims=2 extra=1 .* names=pdf$' && ok "--pdf header" || nok "--pdf header"
frs-sample -m "$M" -i blob -n 1000 --jitter random -T -o "$T/jr.txt" &&
    frs-sample -m "$M" -i blob -n 1000 --jitter halton -T -o "$T/jh.txt" &&
    frs-sample -m "$M" -i blob -n 1000 -T -o "$T/jn.txt" &&
    [ "$(grep -vc '^#' "$T/jr.txt")" = "$(grep -vc '^#' "$T/jn.txt")" ] &&
    ! cmp -s "$T/jr.txt" "$T/jn.txt" && ! cmp -s "$T/jh.txt" "$T/jr.txt" &&
    ok "jitter moves points, keeps the count" || nok "jitter moves points, keeps the count"

# Progressive: the union of the steps is the one-shot set at the last count.
frs-sample -m "$M" -i blob --progressive 200,800,2000 -T -o "$T/prog.txt"
frs-sample -m "$M" -i blob -n 2000 -T -o "$T/one.txt"
awk '!/^#/ { print $1, $2 }' "$T/prog.txt" | sort >"$T/prog.s"
grep -v '^#' "$T/one.txt" | sort >"$T/one.s"
cmp -s "$T/prog.s" "$T/one.s" && ok "progressive union equals one shot" ||
    nok "progressive union equals one shot"
awk '!/^#/ { if ($3 < last) bad = 1; last = $3 } END { exit bad || last != 3 }' "$T/prog.txt" &&
    ok "steps come in order 1, 2, 3" || nok "steps come in order 1, 2, 3"

# Count only, with window math past 2^32 (n = 2^34).
n=$(frs-sample -m "$M" -i blob -n 17179869184 --count-only -q)
awk -v n="$n" 'BEGIN { exit !(n > 0.999 * 17179869184 && n < 1.001 * 17179869184) }' &&
    ok "--count-only at 2^34 ($n)" || nok "--count-only at 2^34 ($n)"
frs-sample -m "$M" -i blob -n 100000 2>"$T/warn" >/dev/null
grep -q 'Table 4.1' "$T/warn" && ok "warning past the matrix's unique samples" ||
    nok "warning past the matrix's unique samples"

# The default matrix and a prepared one beside it.
check "default matrix" frs-sample -i blob -n 100 -o "$T/d.pts"
frd-prep -a all "$M" -o "$T/m.frp"
frs-sample -m "$T/m.frp" -i blob -n 3000 -T -o "$T/frp.txt"
cmp -s "$T/frp.txt" "$T/j1.txt" && ok "a .frp gives the same points" ||
    nok "a .frp gives the same points"
# A stale .frp beside the matrix (made from another) is ignored with a
# warning: the run goes on with the matrix alone, as frs(7), frd(5) and
# frs-sample(1) say; no manual calls it refused.
frd-gen -s 256 --tol 1e-2 -S 9 -o "$T/m2.frd"
cp "$T/m.frp" "$T/m2.frp"
mkdir "$T/alone" && cp "$T/m2.frd" "$T/alone/m2.frd"
frs-sample -m "$T/alone/m2.frd" -i blob -n 100 -T -o "$T/alone.txt" 2>"$T/err"
if frs-sample -m "$T/m2.frd" -i blob -n 100 -T -o "$T/stale.txt" 2>"$T/warn" &&
    grep -qF "warning: $T/m2.frp is stale (made from another matrix than $T/m2.frd); ignored" \
	"$T/warn" && cmp -s "$T/stale.txt" "$T/alone.txt"; then
	ok "a stale .frp beside the matrix is ignored with a warning"
else
	nok "a stale .frp beside the matrix is ignored with a warning"
	sed 's/^/# /' "$T/warn"
fi
# A matrix whose values are not a permutation is refused, naming the
# first repeated value and where it repeats: element 1 made a copy of
# element 0.
L=$(od -A n -t u4 -j 28 -N 4 "$M" | tr -d ' ')
v0=$(od -A n -t u4 -j $((32 + L)) -N 4 "$M" | tr -d ' ')
cp "$M" "$T/dup.frd"
dd if="$M" of="$T/dup.frd" bs=1 skip=$((32 + L)) seek=$((36 + L)) count=4 \
    conv=notrunc 2>/dev/null
expect_fail "a matrix that is not a permutation is refused" 1 \
    "dup.frd: not a permutation: value $v0 repeats at (1, 0, 0)" "$T/dup.pts" \
    frs-sample -m "$T/dup.frd" -i blob -n 100 -o "$T/dup.pts"
# The manuals: none says a stale .frp is refused, or that the values go
# unchecked.
for pg in "$TOP"/man/man*/*.[0-9]; do
	command -v mandoc >/dev/null || break
	mandoc -Tascii "$pg" | col -b | tr '\n' ' ' | tr -s ' ' |
	    grep -oiE 'stale[^.]*refused|readers? (does|do) not check[^.]*' |
	    sed "s|^|${pg##*/}: |"
done >"$T/says"
if ! command -v mandoc >/dev/null; then
	ok "# SKIP the manuals on .frp and permutations: no mandoc"
elif [ ! -s "$T/says" ]; then
	ok "no manual calls a stale .frp refused or a permutation unchecked"
else
	nok "no manual calls a stale .frp refused or a permutation unchecked"
	sed 's/^/# /' "$T/says"
fi

# --sets M: set i is the set of -S S+i, each record followed by its set
# (the column named set, pts(5) version 2); one header counts them all.
u32() { od -A n -t u4 -j "$2" -N 4 "$1" | tr -d ' '; }
# recs FILE SKIP NCOL: the records after SKIP bytes, one per line in hex
recs() { tail -c +$(($2 + 1)) "$1" | od -A n -t x8 -v -w$((8 * $3)); }
sethex() { case $1 in 0) echo 0000000000000000 ;; 1) echo 3ff0000000000000 ;;
	2) echo 4000000000000000 ;; esac; }
for opts in "-i blob" "-i blob --pdf --jitter random -a level1" "-m $T/m.frp -i ramp"; do
	case $opts in *--pdf*) nc=3 names="pdf set " ;; *) nc=2 names="set     " ;; esac
	# shellcheck disable=SC2086
	frs-sample -m "$M" $opts -n 800 -S 5 --sets 3 -q -o "$T/sets.pts"
	: >"$T/cat.hex"
	tot=0
	for s in 5 6 7; do
		# shellcheck disable=SC2086
		frs-sample -m "$M" $opts -n 800 -S $s -q -o "$T/one.pts"
		h=$(sethex $((s - 5)))
		recs "$T/one.pts" $((32 + 8 * (nc - 2))) $nc |
		    sed "s/\$/ $h/" >>"$T/cat.hex"
		tot=$((tot + $(pts_count "$T/one.pts")))
	done
	if recs "$T/sets.pts" 40 $((nc + 1)) | cmp -s - "$T/cat.hex" &&
	    [ "$(pts_count "$T/sets.pts")" = "$tot" ] &&
	    [ "$(u32 "$T/sets.pts" 8) $(u32 "$T/sets.pts" 16) $(u32 "$T/sets.pts" 20)" = "2 $((nc - 1)) 8" ] &&
	    [ "$(head -c 40 "$T/sets.pts" | tail -c 8 | tr '\0' ' ')" = "$names" ]; then
		ok "$opts --sets 3 -S 5: the sets of -S 5, 6, 7 and their set column, count $tot"
	else
		nok "$opts --sets 3 -S 5: the sets of -S 5, 6, 7 and their set column, count $tot"
	fi
done
frs-sample -m "$M" -i blob -n 300 -S 2 --sets 2 -T -o "$T/sets.txt"
{ frs-sample -m "$M" -i blob -n 300 -S 2 -T | sed '/^#/d; s/$/ 0/'
  frs-sample -m "$M" -i blob -n 300 -S 3 -T | sed '/^#/d; s/$/ 1/'; } >"$T/cat.txt"
head -n 1 "$T/sets.txt" | grep -qx '#pts dims=2 extra=1 count=0 version=2 names=set' &&
    grep -v '^#' "$T/sets.txt" | cmp -s - "$T/cat.txt" &&
    ok "--sets 2 -T: the records of -S 2 and 3, then their set" ||
    nok "--sets 2 -T: the records of -S 2 and 3, then their set"
frs-sample -m "$M" -i blob -n 300 -S 2 --sets 2 | tail -c +41 >"$T/pipe.bin"
frs-sample -m "$M" -i blob -n 300 -S 2 --sets 2 -o "$T/sets2.pts"
tail -c +41 "$T/sets2.pts" | cmp -s - "$T/pipe.bin" &&
    ok "--sets 2 to a pipe: the same records" || nok "--sets 2 to a pipe: the same records"
# --sets with --progressive: the step, then the set column, each set's
# steps in turn: set i is -S 1+i --progressive with the set appended.
frs-sample -m "$M" -i blob --pdf --progressive 50,200 --sets 3 -T -o "$T/ps.txt"
for s in 0 1 2; do
	frs-sample -m "$M" -i blob --pdf --progressive 50,200 -S $((s + 1)) -T |
	    sed "/^#/d; s/\$/ $s/"
done >"$T/ps1.txt"
head -n 1 "$T/ps.txt" | grep -qx '#pts dims=2 extra=3 count=0 version=2 names=pdf,step,set' &&
    grep -v '^#' "$T/ps.txt" | cmp -s - "$T/ps1.txt" &&
    [ "$(awk '!/^#/ { print $4, $5 }' "$T/ps.txt" | uniq | tr '\n' ' ')" = "1 0 2 0 1 1 2 1 1 2 2 2 " ] &&
    ok "--sets 3 --progressive: step and set columns, each set's steps in turn" ||
    nok "--sets 3 --progressive: step and set columns"
frs-sample -m "$M" -i blob --progressive 50,200 --sets 2 -o "$T/ps.pts" &&
    [ "$(head -c 48 "$T/ps.pts" | tail -c 16 | tr '\0' ' ')" = "step set        " ] &&
    ok "--sets --progressive: binary names step, set" || nok "--sets --progressive: binary names"
frs-sample -m "$M" -i blob -n 800 -S 5 --sets 3 --count-only -o "$T/counts.txt"
for s in 5 6 7; do frs-sample -m "$M" -i blob -n 800 -S $s --count-only; done >"$T/counts1.txt"
cmp -s "$T/counts.txt" "$T/counts1.txt" && ok "--sets 3 --count-only: a line per set" ||
    nok "--sets 3 --count-only: a line per set"
for a in "-i blob" "-i blob --pdf -T" "--progressive 100,400 -i blob" "-i const --jitter halton -S 0"; do
	# shellcheck disable=SC2086
	frs-sample -m "$M" $a -n 400 -q -o "$T/a.pts"
	# shellcheck disable=SC2086
	frs-sample -m "$M" $a -n 400 -q --sets 1 -o "$T/b.pts"
	cmp -s "$T/a.pts" "$T/b.pts" && ok "$a: --sets 1 gives the same bytes" ||
	    nok "$a: --sets 1 gives the same bytes"
done
expect_fail "--sets 0" 2 "--sets" "$T/o.pts" frs-sample -m "$M" -n 10 --sets 0 -o "$T/o.pts"
expect_fail "junk --sets" 2 "--sets" "$T/o.pts" frs-sample -m "$M" -n 10 --sets ten -o "$T/o.pts"
expect_fail "--sets past 2^56 samples in all (64-bit product)" 2 "2^56" "$T/o.pts" \
    frs-sample -m "$M" -n 1099511627776 --sets 65537 -o "$T/o.pts"
expect_fail "--sets past seed 2^64-1" 2 "2^64-1" "$T/o.pts" \
    frs-sample -m "$M" -n 10 -S 18446744073709551615 --sets 2 -o "$T/o.pts"

# Hard maps: negative values clamped with a warning or refused, a real
# HDR map, a map of one row.
frs-sample -m "$M" -i "$TD/interior.exr" -s 128x64 -n 1000 -o "$T/int.pts" 2>"$T/warn"
grep -q 'negative pixels clamped' "$T/warn" && ok "negative importance clamped with a warning" ||
    nok "negative importance clamped with a warning"
expect_fail "--strict refuses negative importance" 1 "is negative" "$T/strict.pts" \
    frs-sample -m "$M" --strict -i "$TD/interior.exr" -n 100 -o "$T/strict.pts"
check "1x4096 map" frs-sample -m "$M" -i ramp -s 1x4096 -n 500 -o "$T/thin.pts"

# --exact-count: exactly n samples (each step too), nested with the
# default set, the same set on every algorithm, thread count, device.
allexact=1
for map in blob ramp sky const; do
	for s in 1 2 3; do
		c=$(frs-sample -m "$M" -i $map -n 1024 -S $s --exact-count -q -o "$T/x.pts" &&
		    pts_count "$T/x.pts")
		c2=$(frs-sample -m "$M" -i $map -n 1024 -S $s --exact-count --count-only -q)
		[ "$c" = 1024 ] && [ "$c2" = 1024 ] || { allexact=0; echo "# $map -S $s: $c, $c2"; }
	done
done
[ $allexact = 1 ] && ok "--exact-count: 1024 for blob, ramp, sky, const, seeds 1-3" ||
    nok "--exact-count: 1024 for blob, ramp, sky, const, seeds 1-3"
frs-sample -m "$M" -i blob -n 1024 --sets 10 --exact-count -q -o "$T/x10.pts"
[ "$(pts_count "$T/x10.pts")" = 10240 ] && ok "--exact-count --sets 10: 10 x 1024" ||
    nok "--exact-count --sets 10: 10 x 1024 ($(pts_count "$T/x10.pts"))"
nest=1
for s in 1 2 3 4 5 6; do
	frs-sample -m "$M" -i sky -n 700 -S $s -T -q | grep -v '^#' | sort >"$T/d.s"
	frs-sample -m "$M" -i sky -n 700 -S $s -T -q --exact-count | grep -v '^#' | sort >"$T/e.s"
	nd=$(wc -l <"$T/d.s") both=$(comm -12 "$T/d.s" "$T/e.s" | wc -l)
	[ "$(wc -l <"$T/e.s")" -eq 700 ] || nest=0
	if [ "$nd" -ge 700 ]; then [ "$both" -eq 700 ] || nest=0
	else [ "$both" -eq "$nd" ] || nest=0; fi
done
[ $nest = 1 ] && ok "--exact-count nests with the default set" ||
    nok "--exact-count nests with the default set"
frs-sample -m "$M" -i blob -n 3000 -S 4 --exact-count -q -j 1 -T -o "$T/xj1.txt"
frs-sample -m "$M" -i blob -n 3000 -S 4 --exact-count -q -j 2 -T -o "$T/xj2.txt"
cmp -s "$T/xj1.txt" "$T/xj2.txt" &&
    impls_same "$T/xj1.txt" -m "$M" -i blob -n 3000 -S 4 --exact-count -q &&
    ok "--exact-count: the same points for -j 1, 2 and every algorithm" ||
    nok "--exact-count: the same points for -j 1, 2 and every algorithm"
frs-sample -m "$M" -i ramp --progressive 100,400,1500 --exact-count -q -T -o "$T/xp.txt"
awk '!/^#/ { c[$3]++ } END { exit !(c[1] == 100 && c[2] == 300 && c[3] == 1100) }' \
    "$T/xp.txt" && ok "--exact-count --progressive: each step exact" ||
    nok "--exact-count --progressive: each step exact"
frs-sample -m "$M" -i ramp -n 1500 --exact-count -q -T | grep -v '^#' | sort >"$T/x1.s"
awk '!/^#/ { print $1, $2 }' "$T/xp.txt" | sort | cmp -s - "$T/x1.s" &&
    ok "--exact-count --progressive: the union is the exact one-shot set" ||
    nok "--exact-count --progressive: the union is the exact one-shot set"
for opts in "-i blob -n 3000 -S 4" "-i sky -n 2000 -a naive --pdf" \
    "-i ramp --progressive 100,400,1500 -a level2"; do
	# shellcheck disable=SC2086
	frs-sample -m "$M" $opts --exact-count -q -o "$T/cpu.out" &&
	    cl_run frs-sample -m "$M" $opts --exact-count -q --device cl -o "$T/cl.out" &&
	    cmp -s "$T/cpu.out" "$T/cl.out" && ok "--device cl --exact-count $opts: the same bytes" ||
	    nok "--device cl --exact-count $opts: the same bytes"
done
frs-sample -m "$M" -i blob -n 3000 -S 4 --exact-count -q -a stack -T -o "$T/xstack.txt"
cl_run frs-sample -m "$M" -i blob -n 3000 -S 4 --exact-count -q -a flat1 --device cl -T \
    -o "$T/xflat1.txt"
cmp -s "$T/xstack.txt" "$T/xflat1.txt" && ok "--exact-count -a flat1 gives Stack's bytes" ||
    nok "--exact-count -a flat1 gives Stack's bytes"
M3=$T/m3.frd
frd-gen -k 3 -s 32 --tol 1e-2 -o "$M3"
frs-sample -m "$M3" -i blob3 -s 16 -n 900 --exact-count -q -T | grep -v '^#' | sort >"$T/x3s.s"
frs-sample -m "$M3" -i blob3 -s 16 -n 900 --exact-count -q -T -a naive -j 2 | grep -v '^#' |
    sort | cmp -s - "$T/x3s.s" && [ "$(wc -l <"$T/x3s.s")" -eq 900 ] &&
    ok "--exact-count on a volume: 900, Naive's set is Sorted's" ||
    nok "--exact-count on a volume: 900, Naive's set is Sorted's"
frs-sample -m "$M" -i blob -n 1000 --exact-count -v -o /dev/null 2>"$T/v.txt"
grep -q 'exact-count: tau .* count passes' "$T/v.txt" && ok "--exact-count -v: tau and passes" ||
    nok "--exact-count -v: tau and passes"
expect_fail "--exact-count with the thesis rule" 2 "needs --threshold unbiased" "$T/o.pts" \
    frs-sample -m "$M" -n 100 --exact-count --threshold thesis -o "$T/o.pts"

# Bad input.
expect_fail "all-zero map" 1 "zero everywhere" "$T/z.pts" frs-sample -m "$M" -i const:0 -n 10 -o "$T/z.pts"
expect_fail "no count" 2 "-n COUNT is required" "$T/o.pts" frs-sample -m "$M" -o "$T/o.pts"
expect_fail "n = 0" 2 "-n" "$T/o.pts" frs-sample -m "$M" -n 0 -o "$T/o.pts"
expect_fail "unknown implementation" 2 "unknown implementation" "$T/o.pts" frs-sample -m "$M" -n 10 -a quick -o "$T/o.pts"
expect_fail "sigma below 1" 2 "--sigma" "$T/o.pts" frs-sample -m "$M" -n 10 --sigma 0.5 -o "$T/o.pts"
expect_fail "progressive not increasing" 2 "increase" "$T/o.pts" frs-sample -m "$M" --progressive 100,50 -o "$T/o.pts"
expect_fail "bad jitter" 2 "--jitter" "$T/o.pts" frs-sample -m "$M" -n 10 --jitter some -o "$T/o.pts"
expect_fail "missing matrix" 1 "nothere.frd" "$T/o.pts" frs-sample -m "$T/nothere.frd" -n 10 -o "$T/o.pts"
echo junk >"$T/junk.frd"
expect_fail "not a matrix" 1 "junk.frd" "$T/o.pts" frs-sample -m "$T/junk.frd" -n 10 -o "$T/o.pts"
frd-gen -s 48x40 -o "$T/odd.frd"
expect_fail "stack on a non-power-of-two matrix" 1 "power-of-two" "$T/o.pts" \
    frs-sample -m "$T/odd.frd" -a stack -n 10 -o "$T/o.pts"
check "naive on a non-power-of-two matrix" frs-sample -m "$T/odd.frd" -a naive -i blob -n 100 -o "$T/odd.pts"
expect_fail "missing directory" 1 "cannot create" "$T/no/o.pts" frs-sample -m "$M" -n 10 -o "$T/no/o.pts"
expect_fail "full disk" 1 "No space left" - frs-sample -m "$M" -n 10 -o /dev/full
expect_fail "a count too large to store" 1 "--count-only" "$T/big.pts" \
    frs-sample -m "$M" -i blob -n 1099511627776 -o "$T/big.pts"
frs-sample -m "$M" -i blob -n 1000 --count-only -o "$T/count.txt" &&
    [ "$(cat "$T/count.txt")" -gt 900 ] && ok "--count-only writes to -o" ||
    nok "--count-only writes to -o"

# OpenCL (PoCL in make check): the same bytes as the CPU path.
for opts in "-i blob -n 3000" "-i ramp -n 2000 -a naive --jitter random -T" \
    "-i blob --progressive 200,800,2000 -a stack --pdf" \
    "-i sky -n 1500 -a level1 --threshold thesis --jitter halton" \
    "-i blob -n 800 -a level2 -S 5 --sets 3" "-m $T/m.frp -i const -n 1000" \
    "-i blob -n 5000 --count-only"; do
	# shellcheck disable=SC2086
	frs-sample -m "$M" $opts -q -o "$T/cpu.out" &&
	    cl_run frs-sample -m "$M" $opts -q --device cl -o "$T/cl.out" &&
	    cmp -s "$T/cpu.out" "$T/cl.out" && ok "--device cl $opts: the same bytes" ||
	    nok "--device cl $opts: the same bytes"
done
frs-sample -m "$M" -i blob -n 3000 -a stack -T -o "$T/stack.txt"
cl_run frs-sample -m "$M" -i blob -n 3000 -a flat1 --device cl:0 -T -o "$T/flat1.txt"
cmp -s "$T/stack.txt" "$T/flat1.txt" && ok "-a flat1 gives Stack's bytes" ||
    nok "-a flat1 gives Stack's bytes"
# n = 1 on const with the default matrix: no sample, so empty buffers
# (once CL_INVALID_VALUE from every OpenCL algorithm)
for a in naive sorted flat1; do
	frs-sample -i const -n 1 -a "$([ $a = flat1 ] && echo stack || echo $a)" \
	    -o "$T/c1.pts" &&
	    cl_run frs-sample -i const -n 1 -a $a --device cl -o "$T/l1.pts" &&
	    cmp -s "$T/c1.pts" "$T/l1.pts" &&
	    ok "--device cl -a $a -n 1 on const (no sample): the CPU's bytes" ||
	    nok "--device cl -a $a -n 1 on const (no sample): the CPU's bytes"
done
cl_run frs-sample --list-devices >"$T/dev.txt" && head -n 1 "$T/dev.txt" | grep -q '^cl:0' &&
    ok "--list-devices starts with cl:0" || nok "--list-devices starts with cl:0"
expect_fail "--device cl:63" 1 "cl:63" "$T/o.pts" cl_run frs-sample -m "$M" -n 10 --device cl:63 -o "$T/o.pts"
# Any cl:N parses: a device that is not there is exit 1, whatever N.
for d in cl:64 cl:99 cl:99999999999999999999; do
	expect_fail "--device $d: no such device" 1 "OpenCL: no" "$T/o.pts" \
	    cl_run frs-sample -m "$M" -n 10 --device $d -o "$T/o.pts"
done
grep -q 'device); see --list-devices\|devices); see --list-devices\|no platform' "$T/err" &&
    ok "--device cl:N: how many devices there are" || nok "--device cl:N: $(cat "$T/err")"
grep -q 'see --list-devices, or use --device cpu$' "$T/err" &&
    ok "--device cl:N: the advice to use the CPU" ||
    nok "--device cl:N: no advice to use the CPU: $(cat "$T/err")"
for d in cl: cl:-1 cl:1x; do
	expect_fail "--device $d: a usage error" 2 "is not cpu, cl or cl:N" "$T/o.pts" \
	    frs-sample -m "$M" -n 10 --device $d -o "$T/o.pts"
done
expect_fail "--device gpu" 2 "--device" "$T/o.pts" frs-sample -m "$M" -n 10 --device gpu -o "$T/o.pts"
expect_fail "-a flat1 without OpenCL" 2 "OpenCL" "$T/o.pts" frs-sample -m "$M" -n 10 -a flat1 -o "$T/o.pts"
# Flat 1 runs only on a device: no advice to use the CPU.
expect_fail "-a flat1 --device cl:64" 1 "no device cl:64" "$T/o.pts" \
    cl_run frs-sample -m "$M" -n 10 -a flat1 --device cl:64 -o "$T/o.pts"
grep -q 'see --list-devices$' "$T/err" &&
    ok "-a flat1, no such device: no advice to use the CPU" ||
    nok "-a flat1, no such device: $(cat "$T/err")"
expect_fail "-a flat1 --device cpu" 2 "OpenCL" "$T/o.pts" frs-sample -m "$M" -n 10 -a flat1 --device cpu -o "$T/o.pts"
# frs-sample(1)'s first example, as the page writes it: the shipped map
# three ways, three different sets (issue 32: the "shuffled" one was the
# default's bytes), and -v lists the levels.
man_example man/man1/frs-sample.1 'tiles \$t' >"$T/ex1.sh"
if [ -s "$T/ex1.sh" ] && (mkdir "$T/ex1" && cd "$T/ex1" && sh -e ../ex1.sh 2>err) &&
    ! cmp -s "$T/ex1/levels.pts" "$T/ex1/plain.pts" &&
    ! cmp -s "$T/ex1/levels.pts" "$T/ex1/shuffled.pts" &&
    ! cmp -s "$T/ex1/plain.pts" "$T/ex1/shuffled.pts" &&
    [ -s "$T/ex1/levels.png" ] && grep -q 'level [0-9]*: n_s' "$T/ex1/err"; then
	ok "frs-sample(1)'s first example: levels, plain and shuffled, three sets"
else
	nok "frs-sample(1)'s first example: $(head -n 5 "$T/ex1.sh" "$T/ex1/err" 2>&1)"
fi
done_testing
