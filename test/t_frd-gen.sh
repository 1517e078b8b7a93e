#!/bin/sh
# frd-gen: output format, determinism across threads, checkpoints, bad
# arguments refused before any work.
. "$(dirname "$0")/lib.sh"

check "frd-gen -s 64" frd-gen -s 64 -o "$T/a.frd"
# The .frd layout: 32-byte header with the magic, then the parameter
# text, and the values as the last 4N bytes.
size=$(wc -c <"$T/a.frd")
plen=$(od -A n -t u4 -j 28 -N 4 "$T/a.frd" | tr -d ' ')
[ "$size" -eq $((32 + plen + 4 * 64 * 64)) ] && ok "file length is header + params + 4N" ||
    nok "file length is header + params + 4N ($size, params $plen)"
head -c 8 "$T/a.frd" | od -A n -t x1 | grep -q '89 46 52 44 0d 0a 1a 0a' &&
    ok "magic" || nok "magic"
tail -c $((4 * 64 * 64)) "$T/a.frd" | od -A n -v -t u4 | tr -s ' ' '\n' |
    grep -v '^$' | sort -n | awk '$1 != NR - 1 { bad = 1 } END { exit bad || NR != 4096 }' &&
    ok "values are a permutation of 0..4095" || nok "values are a permutation of 0..4095"
head -c $((32 + plen)) "$T/a.frd" | tail -c "$plen" | grep -q '^p=0.5$' &&
    ok "parameters recorded in the header" || nok "parameters recorded in the header"

# Same bytes for any thread count (windows large enough to be split).
frd-gen -s 128 -j 1 -o "$T/j1.frd" && frd-gen -s 128 -j 2 -o "$T/j2.frd" &&
    frd-gen -s 128 -j 5 -o "$T/j5.frd" && cmp -s "$T/j1.frd" "$T/j2.frd" &&
    cmp -s "$T/j1.frd" "$T/j5.frd" && ok "-j 1, 2, 5 give the same bytes" ||
    nok "-j 1, 2, 5 give the same bytes"
frd-gen -s 128 -S 2 -o "$T/s2.frd"
cmp -s "$T/j1.frd" "$T/s2.frd" && nok "another seed gives another matrix" ||
    ok "another seed gives another matrix"
frd-gen -s 128 -o - | cmp -s - "$T/j1.frd" && ok "standard output" ||
    nok "standard output"

# 3-D and non-square.
check "-k 3 -s 12" frd-gen -k 3 -s 12 -o "$T/c.frd"
[ "$(od -A n -t u4 -j 12 -N 16 "$T/c.frd" | tr -s ' ')" = " 3 12 12 12" ] &&
    ok "3-D header" || nok "3-D header"
check "-s 48x20" frd-gen -s 48x20 -p 1 --exact -o "$T/r.frd"

params() { # the parameter text of an .frd file
	plen=$(od -A n -t u4 -j 28 -N 4 "$1" | tr -d ' ')
	head -c $((32 + plen)) "$1" | tail -c "$plen"
}

# Quality figures of an existing matrix.
frd-gen --quality "$T/j1.frd" >"$T/q" 2>"$T/err"
awk '$1 == "spread_16" && $2 > 0 && $2 <= 1 { ok = 1 } END { exit !ok }' "$T/q" &&
    ok "--quality prints the spread" || nok "--quality prints the spread"

awk '$1 == "lattice_check" && $2 == "pass" { a = 1 } $1 == "pmax_64" { b = 1 }
    $1 == "strata_last_2.5%" { c = 1 } END { exit !(a && b && c) }' "$T/q" &&
    ok "--quality prints the level figures and the lattice check" ||
    nok "--quality prints the level figures and the lattice check"
frd-gen --quality "$T/j1.frd" "$T/s2.frd" | grep -c '^matrix ' | grep -qx 2 &&
    ok "--quality of two files: two blocks" || nok "--quality of two files: two blocks"

# --field int32, --cutoff, --force: recorded, and refused where they do not
# apply.
frd-gen -s 32 --field int32 -o "$T/i.frd" && params "$T/i.frd" | grep -q '^field=int32$' &&
    ok "--field int32 in the header" || nok "--field int32 in the header"
params "$T/a.frd" | grep -q '^cutoff=taper$' && params "$T/a.frd" | grep -q '^force=power$' &&
    ok "default force and cut-off in the header" || nok "default force and cut-off in the header"
frd-gen -s 32 --force exp --cutoff hard -o "$T/e.frd" &&
    params "$T/e.frd" | grep -q '^s=0.5$' && params "$T/e.frd" | grep -q '^q=0.5$' &&
    params "$T/e.frd" | grep -q '^cutoff=hard$' &&
    ok "--force exp takes the thesis's s = q = 1/2" || nok "--force exp takes the thesis's s = q = 1/2"
for o in "--tol 1e-3" --exact "--reach 1" "--reach-cap 0" "--cutoff hard" \
    "--force exp" "--force-q 2" "--force-s 1"; do
	# shellcheck disable=SC2086
	expect_fail "--field int32 with $o" 2 "${o%% *}: not used by --field int32" \
	    "$T/o.frd" frd-gen -s 16 --field int32 $o -o "$T/o.frd"
done
expect_fail "--field float" 2 "--field: 'float'" "$T/o.frd" frd-gen -s 16 --field float -o "$T/o.frd"
expect_fail "--cutoff soft" 2 "--cutoff: 'soft'" "$T/o.frd" frd-gen -s 16 --cutoff soft -o "$T/o.frd"
expect_fail "--force gauss" 2 "--force: 'gauss'" "$T/o.frd" frd-gen -s 16 --force gauss -o "$T/o.frd"
expect_fail "--reach-cap -1" 2 "--reach-cap" "$T/o.frd" frd-gen -s 16 --reach-cap -1 -o "$T/o.frd"
expect_fail "--field with vac" 2 "--field" "$T/o.frd" frd-gen -s 16 --method vac --field int32 -o "$T/o.frd"

# Uniform FRS on four 128^2 matrices (the whole matrix, c = 1024): no
# direction stands out.  Four sets put the anisotropy of an isotropic
# spectrum near -6 dB; without the cap the first values form a lattice and
# reach +15 dB.
aniso4() { # ARGS...: max and mean anisotropy (dB) over 4 <= f, or fail
	for s in 1 2 3 4; do
		frd-gen -q -s 128 -S $s "$@" -o "$T/u$s.frd" &&
		    frs-sample -q -m "$T/u$s.frd" -i const -n 1024 --sigma 4 -S $s \
		    -o "$T/u$s.pts" || return 1
	done
	dda -q --fourier --size 64 --radial "$T/u.rad" "$T/u1.pts" "$T/u2.pts" \
	    "$T/u3.pts" "$T/u4.pts" >/dev/null &&
	    awk -F '\t' 'NR > 1 && $1 >= 4 { n++; s += $3; if ($3 > m || n == 1) m = $3 }
	    END { if (n > 10) printf "%.1f %.1f\n", m, s / n }' "$T/u.rad"
}
a=$(aniso4)
echo "$a" | awk '{ exit !(NF == 2 && $1 <= -3 && $2 <= -5) }' &&
    ok "uniform FRS of four default matrices: anisotropy <= -3 dB, mean <= -5 ($a)" ||
    nok "uniform FRS of four default matrices: anisotropy <= -3 dB, mean <= -5 ($a)"
a=$(aniso4 --reach-cap 0)
echo "$a" | awk '{ exit !(NF == 2 && $1 > -3) }' &&
    ok "without the cap the same check fails ($a)" ||
    nok "without the cap the same check fails ($a)"

# An interrupted run resumes from its checkpoint to the same bytes.
frd-gen -s 256 --tol 1e-3 -o "$T/full.frd"
frd-gen -s 256 --tol 1e-3 --checkpoint "$T/ck" --checkpoint-every 0 \
    -o "$T/resumed.frd" 2>/dev/null &
pid=$!
i=0
while [ ! -f "$T/ck" ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i + 1)); done
kill -TERM $pid 2>/dev/null
wait $pid
if [ -f "$T/resumed.frd" ]; then
	ok "checkpoint: the run finished before it could be interrupted"
elif [ -f "$T/ck" ]; then
	frd-gen -s 256 --tol 1e-3 --checkpoint "$T/ck" -o "$T/resumed.frd" &&
	    cmp -s "$T/full.frd" "$T/resumed.frd" && [ ! -f "$T/ck" ] &&
	    ok "resumed run gives the same bytes and removes the checkpoint" ||
	    nok "resumed run gives the same bytes and removes the checkpoint"
else
	nok "checkpoint was written"
fi
[ -z "$(ls "$T" | grep '\.tmp\.')" ] && ok "no temporaries left" || nok "no temporaries left"

# Bad arguments: clear messages before any work, exit 2.
expect_fail "size 0" 2 "-s" "$T/o.frd" frd-gen -s 0 -o "$T/o.frd"
expect_fail "size 1" 2 "at least 2 cells" "$T/o.frd" frd-gen -s 1 -o "$T/o.frd"
expect_fail "no size" 2 "-s SIZE is required" "$T/o.frd" frd-gen -o "$T/o.frd"
# One range for -p, 0 excluded, stated alike on either side of it.
expect_fail "p = 0" 2 "-p: 0 is out of range (0, 1]" "$T/o.frd" \
    frd-gen -s 16 -p 0 -o "$T/o.frd"
expect_fail "p = 2" 2 "-p: 2 is out of range (0, 1]" "$T/o.frd" \
    frd-gen -s 16 -p 2 -o "$T/o.frd"
expect_fail "p = -1" 2 "-p: -1 is out of range (0, 1]" "$T/o.frd" \
    frd-gen -s 16 -p -1 -o "$T/o.frd"
expect_fail "p > 1" 2 "-p" "$T/o.frd" frd-gen -s 16 -p 1.5 -o "$T/o.frd"
expect_fail "p = nan" 2 "not a finite number" "$T/o.frd" frd-gen -s 16 -p nan -o "$T/o.frd"
expect_fail "tol = 0" 2 "--tol: 0 is out of range (0, 0.999999]; --exact" "$T/o.frd" \
    frd-gen -s 16 --tol 0 -o "$T/o.frd"
expect_fail "tol = 1" 2 "--tol: 1 is out of range (0, 0.999999]" "$T/o.frd" \
    frd-gen -s 16 --tol 1 -o "$T/o.frd"
expect_fail "k = 4" 2 "-k" "$T/o.frd" frd-gen -s 16 -k 4 -o "$T/o.frd"
expect_fail "2^32 values" 2 "2^32" "$T/o.frd" frd-gen -s 65536 -o "$T/o.frd"
expect_fail "memory that cannot be had" 1 "GiB, above the memory limit" "$T/o.frd" \
    env FRS_MAX_MEM=8G frd-gen -s 60000 -o "$T/o.frd"
expect_fail "unknown option" 2 "usage" "$T/o.frd" frd-gen -s 16 --frob -o "$T/o.frd"
expect_fail "missing directory" 1 "cannot create" "$T/no/o.frd" frd-gen -s 16 -o "$T/no/o.frd"
expect_fail "full disk" 1 "No space left" - frd-gen -s 16 -o /dev/full
: >"$T/empty.frd"
expect_fail "--quality of an empty file" 1 "empty.frd: empty file" - frd-gen --quality "$T/empty.frd"

# --method vac: the void-and-cluster baseline (src/frd-gen/vac.h).
check "--method vac -s 64" frd-gen --method vac -s 64 -o "$T/v.frd"
check "vac: a permutation (frd-prep --check)" frd-prep --check -a none \
    -o "$T/vc.frd" "$T/v.frd"
params "$T/v.frd" >"$T/vp"
grep -q '^method=vac$' "$T/vp" && grep -q '^sigma=1.5$' "$T/vp" &&
    grep -q '^tol=0.0001$' "$T/vp" && ok "vac: method and defaults in the header" ||
    nok "vac: method and defaults in the header"
frd-gen --method vac -s 96x64 -j 1 -o "$T/vj1.frd" &&
    frd-gen --method vac -s 96x64 -j 2 -o "$T/vj2.frd" &&
    cmp -s "$T/vj1.frd" "$T/vj2.frd" && ok "vac: -j 1 and -j 2 give the same bytes" ||
    nok "vac: -j 1 and -j 2 give the same bytes"
frd-gen --method vac -s 96x64 -S 2 -o "$T/vs2.frd" && ! cmp -s "$T/vj1.frd" "$T/vs2.frd" &&
    ok "vac: another seed gives another matrix" || nok "vac: another seed gives another matrix"
cmp -s "$T/v.frd" "$T/a.frd" && nok "vac differs from frd" || ok "vac differs from frd"
check "vac -k 3 -s 10x8x6" frd-gen --method vac -k 3 -s 10x8x6 -o "$T/v3.frd"
check "vac 3-D: a permutation" frd-prep --check -a none -o "$T/v3c.frd" "$T/v3.frd"
frd-gen --method vac -s 40x24 --exact --vac-sigma 2.5 -o "$T/ve.frd" &&
    frd-prep --check -a none -o "$T/vec.frd" "$T/ve.frd" && params "$T/ve.frd" >"$T/vp" &&
    grep -q '^tol=0$' "$T/vp" && grep -q '^sigma=2.5$' "$T/vp" &&
    ok "vac --exact --vac-sigma 2.5: a permutation, recorded" ||
    nok "vac --exact --vac-sigma 2.5: a permutation, recorded"
frd-gen --method vac -s 32 --tol 1e-2 -o "$T/vt.frd" && params "$T/vt.frd" |
    grep -q '^tol=0.01$' && ok "vac --tol recorded" || nok "vac --tol recorded"
frd-gen --method frd -s 64 -o "$T/f.frd" && cmp -s "$T/f.frd" "$T/a.frd" &&
    ok "--method frd is the default" || nok "--method frd is the default"
expect_fail "--method foo" 2 "--method: 'foo' is not frd or vac" "$T/o.frd" \
    frd-gen --method foo -s 16 -o "$T/o.frd"
expect_fail "--vac-sigma 0" 2 "--vac-sigma: 0 is out of range (0, 1e+06]" "$T/o.frd" \
    frd-gen --method vac --vac-sigma 0 -s 16 -o "$T/o.frd"
expect_fail "--vac-sigma -1" 2 "--vac-sigma: -1 is out of range (0, 1e+06]" "$T/o.frd" \
    frd-gen --method vac --vac-sigma -1 -s 16 -o "$T/o.frd"
expect_fail "--vac-sigma nan" 2 "not a finite number" "$T/o.frd" \
    frd-gen --method vac --vac-sigma nan -s 16 -o "$T/o.frd"
expect_fail "--vac-sigma abc" 2 "--vac-sigma: 'abc' is not a number" "$T/o.frd" \
    frd-gen --method vac --vac-sigma abc -s 16 -o "$T/o.frd"
expect_fail "--vac-sigma without vac" 2 "only with --method vac" "$T/o.frd" \
    frd-gen --vac-sigma 2 -s 16 -o "$T/o.frd"
expect_fail "-p with vac" 2 "-p: not used by --method vac" "$T/o.frd" \
    frd-gen --method vac -p 0.5 -s 16 -o "$T/o.frd"
expect_fail "--checkpoint with vac" 2 "--checkpoint: not used by --method vac" \
    "$T/o.frd" frd-gen --method vac --checkpoint "$T/ck" -s 16 -o "$T/o.frd"
expect_fail "--device cl with vac" 2 "CPU only" "$T/o.frd" \
    frd-gen --method vac --device cl -s 16 -o "$T/o.frd"
expect_fail "vac size 1" 2 "at least 2 cells" "$T/o.frd" \
    frd-gen --method vac -s 1x16 -o "$T/o.frd"
expect_fail "vac memory that cannot be had" 1 "above the memory limit" "$T/o.frd" \
    env FRS_MAX_MEM=1M frd-gen --method vac -s 1024 -o "$T/o.frd"

# OpenCL (issue 9): the same bytes as the CPU, the device list, a device
# that does not exist, a device name that is not one.
frd-gen -s 32 --device cpu -o "$T/cpu32.frd" &&
    cl_run frd-gen -s 32 --device cl -o "$T/cl32.frd" &&
    cmp -s "$T/cpu32.frd" "$T/cl32.frd" &&
    ok "--device cl -s 32 gives the bytes of --device cpu" ||
    nok "--device cl -s 32 gives the bytes of --device cpu"
frd-gen -s 48x20 -p 0.1 -S 3 -o "$T/cpur.frd" &&
    cl_run frd-gen -s 48x20 -p 0.1 -S 3 --device cl:0 -o "$T/clr.frd" &&
    cmp -s "$T/cpur.frd" "$T/clr.frd" &&
    ok "--device cl:0 -s 48x20 -p 0.1 gives the bytes of the CPU" ||
    nok "--device cl:0 -s 48x20 -p 0.1 gives the bytes of the CPU"
cl_run frd-gen --list-devices >"$T/dev" 2>"$T/err" && grep -q '^cl:0' "$T/dev" &&
    ok "--list-devices prints cl:0" || nok "--list-devices prints cl:0"
expect_fail "--device cl:63" 1 "cl:63" "$T/o.frd" cl_run frd-gen -s 16 --device cl:63 -o "$T/o.frd"
for d in cl:64 cl:99; do
	expect_fail "--device $d: no such device" 1 "OpenCL: no" "$T/o.frd" \
	    cl_run frd-gen -s 16 --device $d -o "$T/o.frd"
done
expect_fail "--device gpu" 2 "gpu" "$T/o.frd" frd-gen -s 16 --device gpu -o "$T/o.frd"
expect_fail "--device cl with --checkpoint" 2 "--checkpoint" "$T/o.frd" \
    frd-gen -s 16 --device cl --checkpoint "$T/ck" -o "$T/o.frd"
done_testing
