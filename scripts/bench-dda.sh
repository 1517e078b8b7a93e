#!/bin/sh
# dda: what the spectra and distances cost.  (a) the exact Fourier
# spectrum of 10 sets of 1024 points at K = 128 (the thesis view), one and
# all threads, against the direct-sum reference (test/ref/ref_dda.c), psa
# and a numpy matrix product (published), and the approximate method's
# time and error; (b) DDA of 10 sets of 1024; (c) density of 2^20 points
# by the grid search, against the O(n^2) reference on 2^14 points.
#   scripts/bench-dda.sh [BUILD]      BENCH_QUICK=1: no reference at 2^16
set -eu
BUILD=${1:-build/rel}
DDA=$BUILD/bin/dda
GEN=$BUILD/bin/ref-sample
REF=$BUILD/test/ref_dda
. "$(dirname "$0")/benchlib.sh"
bench_setup bench-dda "$DDA" "$GEN" "$REF"

"$GEN" -q -k dart -n 1024 --sets 10 -o "$T/dart.pts"
"$GEN" -q -k random -n 1024 --sets 10 -o "$T/rand.pts"

echo "dda: Fourier power spectrum, 10 sets of 1024 dart-throwing points,"
echo "K = 128 (257 x 257 frequencies)"
echo "(psa: 5.75 s on two threads; numpy matrix product: 0.22 s; both"
echo " published; ref: test/ref/ref_dda.c, a direct sum of cos and sin)"
printf '%-22s %8s %9s %9s %9s %s\n' method seconds vs_psa vs_numpy vs_ref max_rel_err
timed "$T/ref" "$REF" fourier 128 1024 "$T/dart.pts"
ref=$SEC
for m in "exact -j 1" "exact -j $NCPU" "approx -j 1" "approx -j $NCPU"; do
	set -- $m
	a=""
	[ "$1" = approx ] && a=--approx
	# shellcheck disable=SC2086
	timed "$T/$1$3" "$DDA" --fourier $a --size 128 --sets 1024 -j "$3" \
	    "$T/dart.pts"
	if [ "$1" = approx ]; then
		err=$(paste "$T/exact1" "$T/$1$3" | awk -F '\t' 'NR > 1 {
			d = $3 - $6; if (d < 0) d = -d; e = d / ($3 > 1 ? $3 : 1)
			if (e > m) m = e } END { printf "%.2g", m }')
	else
		err=-
	fi
	awk -v m="$m" -v s=$SEC -v r=$ref -v e="$err" 'BEGIN {
		printf "%-22s %8.3f %8.1fx %8.2fx %8.1fx %s\n", m, s, 5.75 / s,
		    0.22 / s, r / s, e }'
done
echo "(max_rel_err: largest |P_approx - P_exact| / max(P_exact, 1) over the"
echo " frequencies, limited by the 9 digits of the table; ref took ${ref} s)"

echo
echo "dda: differential domain analysis, 10 sets of 1024, eps = 12, 257 x 257"
printf '%-22s %8s\n' sets seconds
for k in dart rand; do
	timed "$T/d" "$DDA" --dda --sets 1024 "$T/$k.pts"
	printf '%-22s %8.3f\n' "$k -j $NCPU" "$SEC"
done
"$GEN" -q -k relaxed-dart -i blob -n 1024 --sets 10 -o "$T/rd.pts"
timed "$T/d" "$DDA" --dda -i blob --sets 1024 "$T/rd.pts"
printf '%-22s %8.3f\n' "relaxed-dart -i blob" "$SEC"

echo
echo "dda: density rho, grid nearest-neighbour search against all pairs"
printf '%-10s %10s %10s %8s %12s\n' n dda_s ref_s speedup dmin_equal
for e in 14 16 20; do
	n=$((1 << e))
	"$GEN" -q -k random -n $n -o "$T/n.pts"
	timed "$T/dn" "$DDA" --density "$T/n.pts"
	ours=$SEC
	d=$(awk -F '\t' 'NR == 2 { print $3 }' "$T/dn")
	if [ $e -le 14 ] || { [ $e -le 16 ] && [ -z "${BENCH_QUICK:-}" ]; }; then
		timed "$T/rn" "$REF" dmin "$T/n.pts"
		r=$(awk '{ print $2 }' "$T/rn")
		eq=$(awk -v a="$d" -v b="$r" 'BEGIN { d = a - b; if (d < 0) d = -d
			print d <= 1e-8 * b ? "yes" : "NO" }')
		awk -v n=$n -v s=$ours -v r=$SEC -v q=$eq 'BEGIN {
			printf "%-10d %10.3f %10.3f %7.0fx %12s\n", n, s, r, r / s, q }'
	else
		awk -v n=$n -v s=$ours 'BEGIN {
			printf "%-10d %10.3f %10s %8s %12s\n", n, s, "-", "-", "-" }'
	fi
done
