#!/bin/sh
# frd-gen: which matrix, and what it costs.
#  1. the defaults against the alternatives they beat (no cap, hard
#     cut-off, the thesis's force, the previous defaults, the authors'
#     integer field and matrix, void-and-cluster): the level figures of
#     frd-gen --quality and the uniform-FRS targets of frd-gen(1), over
#     4 seeds at 512^2;
#  2. the 2048^2 matrix: this release against the previous defaults in the
#     same run, and the shipped data/default.frd;
#  3. accuracy against time: size by tolerance;
#  4. the brute-force reference, and void-and-cluster by size.
#   scripts/bench-frd.sh [BUILD]      BENCH_QUICK=1 skips 2048^2 and int32
set -eu
BUILD=${1:-build/rel}
GEN=$BUILD/bin/frd-gen
FRS=$BUILD/bin/frs-sample
DDA=$BUILD/bin/dda
REF=$BUILD/test/ref_frd
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
TIME=/usr/bin/time
[ -x "$TIME" ] || { echo "bench-frd: needs /usr/bin/time (scripts/deps.sh)"; exit 1; }
. "$(dirname "$0")/benchlib.sh"

OLD="--force exp --reach 0.7 --reach-cap 0 --cutoff hard --tol 1e-3"

# figures FILE...: "pmax_worst strata_worst passed/total" over matrices.
figures() {
	for _f in "$@"; do "$GEN" --quality "$_f"; done | awk '
		$1 == "pmax_worst" && $2 > p { p = $2 }
		$1 == "strata_worst" && $2 > s { s = $2 }
		$1 == "lattice_check" { n++; ok += $2 == "pass" }
		END { printf "%8.1f %8.3f %5d/%d", p, s, ok, n }'
}

# vrow NAME SECONDS FILE...: one row of the variants table.
vrow() {
	_name=$1 _sec=$2
	shift 2
	printf '%-22s %8s %s %s\n' "$_name" "$_sec" "$(figures "$@")" \
	    "$(uniform_frs "$FRS" "$DDA" "$@" | awk '{ printf "%6s %6s %6s %6s %6s", $1, $2, $3, $4, $5 }')"
}

# gen NAME SEEDS SIZE ARGS...: make the matrices NAME-SEED.frd; seconds
# per matrix in SEC.
gen() {
	_n=$1 _k=$2 _sz=$3
	shift 3
	_t0=$(now)
	_s=1
	while [ $_s -le "$_k" ]; do
		"$GEN" -q -s "$_sz" -S $_s "$@" -o "$T/$_n-$_s.frd"
		_s=$((_s + 1))
	done
	SEC=$(awk -v a="$_t0" -v b="$(now)" -v k="$_k" 'BEGIN { printf "%.2f", (b - a) / k }')
}

echo "frd-gen: the defaults against the alternatives, 512^2 ($(nproc) threads)"
echo "(pmax, strata: worst level over the seeds, bounds 30 and 0.95; check:"
echo " matrices passing both; uniform FRS -n 1024, 10 sets: radial peak, ring"
echo " beyond 1.5 peaks, anisotropy max and mean in dB, rho; targets: peak"
echo " 1.4-1.8, ring <= 1.25, aniso max <= -7, mean -11..-9, rho >= 0.65)"
printf '%-22s %8s %8s %8s %7s %6s %6s %6s %6s %6s\n' variant s/matrix pmax \
    strata check peak ring an_max an_avg rho
gen def 4 512
vrow "default" "$SEC" "$T"/def-*.frd
gen nocap 4 512 --reach-cap 0
vrow "--reach-cap 0" "$SEC" "$T"/nocap-*.frd
gen hard 4 512 --cutoff hard
vrow "--cutoff hard" "$SEC" "$T"/hard-*.frd
gen q05 4 512 --force exp
vrow "--force exp" "$SEC" "$T"/q05-*.frd
gen q07 4 512 --force exp --force-q 0.7
vrow "--force exp --force-q 0.7" "$SEC" "$T"/q07-*.frd
gen p1 4 512 -p 1
vrow "-p 1" "$SEC" "$T"/p1-*.frd
# shellcheck disable=SC2086
gen old 4 512 $OLD
vrow "previous defaults" "$SEC" "$T"/old-*.frd
gen vac 4 512 --method vac
vrow "--method vac" "$SEC" "$T"/vac-*.frd
if [ -z "${BENCH_QUICK:-}" ]; then
	gen int 1 512 --field int32
	vrow "--field int32 (1 seed)" "$SEC" "$T"/int-1.frd
fi
if "$BUILD/bin/frd-prep" -q --import raw32 \
    data/authors-512x512.matrix -o "$T/authors.frd" 2>/dev/null; then
	vrow "the authors' 512^2" - "$T/authors.frd"
fi
echo "(previous defaults: $OLD)"

echo
echo "the 2048^2 matrix: this release against the previous defaults"
printf '%-22s %9s %9s %s\n' matrix seconds peak_MiB \
    "pmax strata check peak ring an_max an_avg rho"
# row2048 NAME ARGS...
row2048() {
	_name=$1
	shift
	$TIME -f "%e %M" -o "$T/time" "$GEN" -q -s 2048 "$@" -o "$T/big.frd"
	printf '%-22s %9s %9s %s %s\n' "$_name" "$(cut -d' ' -f1 "$T/time")" \
	    "$(awk '{ printf "%.0f", $2 / 1024 }' "$T/time")" \
	    "$(figures "$T/big.frd")" "$(uniform_frs "$FRS" "$DDA" "$T/big.frd")"
	cp "$T/time" "$T/time-$_name"
}
if [ -z "${BENCH_QUICK:-}" ]; then
	row2048 default
	# shellcheck disable=SC2086
	row2048 previous $OLD
	awk '{ a = $1 } END { printf "time ratio default / previous: ", a }' "$T/time-default"
	awk -v a="$(cut -d' ' -f1 "$T/time-default")" '{ printf "%.2f\n", a / $1 }' \
	    "$T/time-previous"
fi
if [ -f data/default.frd ]; then
	printf '%-22s %9s %9s %s %s\n' "data/default.frd" - - \
	    "$(figures data/default.frd)" "$(uniform_frs "$FRS" "$DDA" data/default.frd)"
fi
echo "(thesis: 2048^2 took over 4 hours = 14400 s on a GTX 680)"

echo
echo "accuracy against time: size by tolerance (defaults otherwise)"
printf '%-6s %-6s %9s %8s %8s %8s %7s\n' size tol seconds peak_MiB pmax \
    strata check
trow() {
	if [ "$2" = exact ]; then _a=--exact; else _a="--tol $2"; fi
	# shellcheck disable=SC2086
	$TIME -f "%e %M" -o "$T/time" "$GEN" -q -s "$1" $_a -o "$T/m.frd"
	printf '%-6s %-6s %9s %8s %s\n' "$1" "$2" "$(cut -d' ' -f1 "$T/time")" \
	    "$(awk '{ printf "%.1f", $2 / 1024 }' "$T/time")" "$(figures "$T/m.frd")"
}
for s in 128 256; do
	for t in 1e-1 1e-2 1e-4 exact; do trow $s $t; done
done
for t in 1e-1 1e-2 1e-4 1e-6; do trow 512 $t; done
for t in 1e-2 1e-4; do trow 1024 $t; done

echo
echo "frd-gen against the brute-force reference (exact, p = 1, one thread)"
printf '%-6s %12s %12s %8s %s\n' size ref_s frd-gen_s speedup same
for s in 64 128; do
	$TIME -f "%e" -o "$T/tr" "$REF" $s $s 1 0 0 1 >"$T/ref.u32"
	$TIME -f "%e" -o "$T/tg" "$GEN" -q -j 1 -s $s -p 1 --exact --reach 0 -S 1 \
	    -o "$T/g.frd"
	tail -c $((4 * s * s)) "$T/g.frd" | cmp -s - "$T/ref.u32" && same=yes || same=NO
	awk -v s=$s -v a="$(cat "$T/tr")" -v b="$(cat "$T/tg")" -v same=$same \
	    'BEGIN { printf "%-6s %12.2f %12.2f %8.1f %s\n", s, a, b, a / b, same }'
done

echo
echo "void-and-cluster (--method vac: sigma 1.5, tol 1e-4, one thread) against"
echo "frd (defaults, $(nproc) threads)"
printf '%-9s %9s %9s %8s %8s %8s %8s %8s\n' size frd_s vac_s vac/frd \
    pmax_frd pmax_vac str_frd str_vac
vacrow() {
	timed /dev/null "$GEN" -q -k "$1" -s "$2" -o "$T/f.frd"
	tf=$SEC
	timed /dev/null "$GEN" -q --method vac -k "$1" -s "$2" -o "$T/v.frd"
	printf '%-9s %9.3f %9.3f %8.2f %s %s\n' "$2" "$tf" "$SEC" \
	    "$(awk -v a="$tf" -v b="$SEC" 'BEGIN { print (a > 0 ? b / a : 0) }')" \
	    "$(figures "$T/f.frd" | awk '{ printf "%8s", $1 }')" \
	    "$(figures "$T/v.frd" | awk '{ printf "%8s", $1 }') $(figures "$T/f.frd" |
	    awk '{ printf "%8s", $2 }') $(figures "$T/v.frd" | awk '{ printf "%8s", $2 }')"
}
for s in 128 256; do vacrow 2 $s; done
vacrow 3 32x32x32
echo "(pmax, str: the worst level's periodogram maximum and strata share)"
