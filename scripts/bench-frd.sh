#!/bin/sh
# frd-gen: what accuracy costs.  A table of matrix size by tolerance with
# seconds, peak memory and the quality figures of frd-gen(1), then ratios
# against the brute-force reference, a plain radius-42 run and the thesis,
# and the check of the shipped default matrix.
#   scripts/bench-frd.sh [BUILD]      BENCH_QUICK=1 skips 2048^2
set -eu
BUILD=${1:-build/bench}
GEN=$BUILD/bin/frd-gen
REF=$BUILD/test/ref_frd
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
TIME=/usr/bin/time
[ -x "$TIME" ] || { echo "bench-frd: needs /usr/bin/time (scripts/deps.sh)"; exit 1; }

# run NAME ARGS...: time and peak memory of one frd-gen run, then its
# quality figures; prints one table row.
row() {
	size=$1 tol=$2
	shift 2
	if [ "$tol" = exact ]; then a=--exact; else a="--tol $tol"; fi
	$TIME -f "%e %M" -o "$T/time" "$GEN" -q -s "$size" $a "$@" -o "$T/m.frd"
	"$GEN" --quality "$T/m.frd" >"$T/q"
	awk -v s="$size" -v t="$tol" -v tf="$T/time" '
		BEGIN {
			getline tm < tf; split(tm, a, " ")
			if (t == "exact") r = "all"; else r = sprintf("%.1f", log(1 / t) ^ 2 / 2)
		}
		{ q[$1] = $2 }
		END {
			s1k = q["spread_1024"]; if (s1k == "") s1k = "-"
			printf "%-6s %-6s %6s %9.2f %8.1f %8s %8s %8s %8s %7s %7s\n", s, t, r, a[1], a[2] / 1024, q["spread_16"], s1k, q["lowpass_first_2.5%"], q["lowpass_last_2.5%"], q["peak_first_10%"], q["peak_last_10%"]
		}' "$T/q"
}

echo "frd-gen: accuracy against time ($(nproc) threads, default tol 1e-3)"
printf '%-6s %-6s %6s %9s %8s %8s %8s %8s %8s %7s %7s\n' size tol radius \
    seconds peak_MiB spread16 spread1k lp_first lp_last pk_f10 pk_l10
for s in 64 128 256; do
	for t in 1e-2 1e-3 1e-4 1e-6 exact; do row $s $t; done
done
for t in 1e-2 1e-3 1e-4 1e-6; do row 512 $t; done
for t in 1e-2 1e-3 1e-4; do row 1024 $t; done
if [ -z "${BENCH_QUICK:-}" ]; then
	for t in 1e-3 1e-4; do row 2048 $t; done
fi
echo "(lp_*: low-frequency power over the plateau of the first and last 2.5 %"
echo " of the values, white noise 1; pk_*: spectral peak of the first and last"
echo " 10 %, blue noise ~2, lattice 5+; spread: min distance over the ideal)"
echo
echo "the thesis authors' 512^2 matrix, for comparison"
"$BUILD/bin/frd-prep" --import raw32 ../shared/data/ref/authors-512x512.matrix \
    -o "$T/authors.frd" 2>/dev/null && "$GEN" --quality "$T/authors.frd" |
    awk '{ printf "%s %s  ", $1, $2 } END { print "" }' || echo "(not found)"
echo
echo "--reach: exact fields crystallise (512^2, default tol)"
printf '%-6s %8s %8s %8s %8s %8s\n' reach spread16 spread1k lp_first pk_f10 pk_l10
for r in 0 0.5 0.7 1 3; do
	"$GEN" -q -s 512 --reach $r -o "$T/r.frd"
	"$GEN" --quality "$T/r.frd" | awk -v r=$r '{ q[$1] = $2 } END {
		printf "%-6s %8s %8s %8s %8s %8s\n", r, q["spread_16"], q["spread_1024"], q["lowpass_first_2.5%"], q["peak_first_10%"], q["peak_last_10%"] }'
done

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
echo "frd-gen --tol 1e-4 against a plain radius-42 run (--reach 0, -j 1)"
printf '%-6s %12s %12s %8s\n' size plain_s ours_s ratio
for s in 512 1024; do
	$TIME -f "%e" -o "$T/tp" "$GEN" -q -j 1 --reach 0 --tol 1e-4 -s $s -o "$T/p.frd"
	$TIME -f "%e" -o "$T/to" "$GEN" -q --tol 1e-4 -s $s -o "$T/o.frd"
	awk -v s=$s -v a="$(cat "$T/tp")" -v b="$(cat "$T/to")" \
	    'BEGIN { printf "%-6s %12.2f %12.2f %8.2f\n", s, a, b, a / b }'
done

echo
echo "the shipped default matrix (data/default.frd): first values spread"
if [ -f data/default.frd ]; then
	"$GEN" --quality data/default.frd | awk '
		/^spread_/ { ok = $2 >= 0.55; bad += !ok
			printf "%-12s %.4f %s\n", $1, $2, ok ? ">= 0.55 ok" : "< 0.55 FAIL" }
		/^lowpass/ { printf "%-20s %.4f\n", $1, $2 }
		END { exit bad > 0 }'
else
	echo "data/default.frd: missing"
fi
echo "(thesis: 2048^2 took over 4 hours = 14400 s on a GTX 680)"

. "$(dirname "$0")/benchlib.sh"
echo
echo "void-and-cluster baseline (--method vac: sigma 1.5, tol 1e-4, one thread)"
echo "against frd (defaults, $(nproc) threads)"
printf '%-9s %9s %9s %8s %8s %8s %8s %8s\n' size frd_s vac_s vac/frd \
    sp16_frd sp16_vac lp_frd lp_vac
# vrow K SIZE: both methods at one size; time (benchlib.sh's timed, to the
# millisecond) and two quality figures each.
vrow() {
	timed /dev/null "$GEN" -q -k "$1" -s "$2" -o "$T/f.frd"
	tf=$SEC
	timed /dev/null "$GEN" -q --method vac -k "$1" -s "$2" -o "$T/v.frd"
	"$GEN" --quality "$T/f.frd" >"$T/qf"
	"$GEN" --quality "$T/v.frd" >"$T/qv"
	awk -v s="$2" -v a="$tf" -v b="$SEC" -v qf="$T/qf" -v qv="$T/qv" 'BEGIN {
		while ((getline l < qf) > 0) { split(l, x, " "); f[x[1]] = x[2] }
		while ((getline l < qv) > 0) { split(l, x, " "); v[x[1]] = x[2] }
		k = "lowpass_first_10%"
		if (!(k in f)) f[k] = v[k] = "-"
		printf "%-9s %9.3f %9.3f %8.2f %8s %8s %8s %8s\n", s, a, b,
		    (a > 0 ? b / a : 0), f["spread_16"], v["spread_16"], f[k], v[k] }'
}
for s in 64 128 256; do vrow 2 $s; done
vrow 3 32x32x32
echo "(vac/frd: time ratio; sp16: spread of the first 16 values; lp: low-frequency"
echo " power of the first 10 %, white noise 1; '-' where the measure is 2-D only)"
