#!/bin/sh
# Every thresholding implementation of frs-sample (Naive, Stack, Level 1,
# Level 2, Sorted; the CPU and the OpenCL device) against ref_frs
# (test/ref/ref_frs.c), a brute force written from the thesis's
# definitions (Listing 5.1, the threshold of Eq. 4.14 and the unbiased
# rule) that shares no code with src/lib/sample/frs.c: the setup (n_s,
# the window, tau) and the set of window elements that pass, element for
# element, on the thesis's plain tiles without jitter.
. "$(dirname "$0")/lib.sh"
REF=$BIN/../test/ref_frs
M=$TD/default.frd

# elems FILE W H: the window elements of frs-sample's text points (no
# jitter: element centres (x + 1/2) / W, so x = floor(X W)) in
# ref_frs's order.
elems() {
	awk -v w="$2" -v h="$3" '!/^#/ { printf "%d %d\n", int($1 * w), int($2 * h) }' \
	    "$1" | sort -k2,2n -k1,1n
}

# same NAME MAP SIZE N REFOPTS -- FRSOPTS...: frs-sample's setup (-v) and
# elements against the oracle's.  SIZE "-" for a file at its own size.
same() {
	name=$1 map=$2 size=$3 n=$4 ropts=$5
	shift 6
	if [ "$size" = - ]; then sz=; else sz="-s $size"; fi
	# shellcheck disable=SC2086
	if ! "$@" -q -v -m "$M" -i "$map" $sz -n "$n" --tiles plain -T \
	    -o "$T/p.txt" 2>"$T/v"; then
		nok "$name: frs-sample failed"
		sed 's/^/# /' "$T/v" | head -n 5
		return
	fi
	# "n N, sigma S, n_s NS, window WxH at (WX, WY), tau TAU, ..."
	set -- $(sed -n 's/.* n_s \([0-9]*\), window \([0-9]*\)x\([0-9]*\) at (\([0-9]*\), \([0-9]*\)), tau \([0-9.e+-]*\),.*/\1 \2 \3 \4 \5 \6/p' "$T/v" | head -n 1)
	ns=$1 w=$2 h=$3 wx=$4 wy=$5 tau=$6
	sigma=$(sed -n 's/.* sigma \([0-9.]*\),.*/\1/p' "$T/v" | head -n 1)
	# shellcheck disable=SC2086
	set -- $("$REF" setup $sz $ropts "$M" "$map" "$n" "$sigma")
	if [ "$2" = "$ns" ] && [ "$4" = "$w" ] && [ "$5" = "$h" ] &&
	    awk -v a="$tau" -v b="$7" 'BEGIN { exit !(a / b - 1 < 1e-7 && b / a - 1 < 1e-7) }'; then
		ok "$name: setup n_s $ns, window ${w}x$h, tau $tau as Listing 5.1"
	else
		nok "$name: setup n_s $ns, window ${w}x$h, tau $tau; Listing 5.1: $*"
	fi
	# shellcheck disable=SC2086
	"$REF" pass $sz $ropts "$M" "$map" "$w" "$h" "$wx" "$wy" "$7" \
	    >"$T/ref.txt"
	elems "$T/p.txt" "$w" "$h" >"$T/got.txt"
	nr=$(wc -l <"$T/ref.txt")
	if [ "$nr" -gt 0 ] && cmp -s "$T/ref.txt" "$T/got.txt"; then
		ok "$name: the $nr elements of the brute force"
	else
		nok "$name: $(wc -l <"$T/got.txt") elements, the brute force $nr"
		diff "$T/ref.txt" "$T/got.txt" | head -n 5 | sed 's/^/# /'
	fi
}

for a in naive stack level1 level2 sorted; do
	same "blob 32x32 n 4000 -a $a" blob 32x32 4000 "" -- \
	    frs-sample -a $a -j 2
done
same "blob seed 7, sigma 3" blob 32x32 3000 "-S 7" -- frs-sample -S 7 --sigma 3
same "ramp 48x20 (not square, not a power of two) -a level2" ramp 48x20 \
    6000 "" -- frs-sample -a level2
for a in naive sorted; do
	same "ramp 48x20 n 5000 --threshold thesis -a $a" ramp 48x20 5000 "--thesis" \
	    -- frs-sample -a $a --threshold thesis
done
same "sunset.exr at 256x128 --equirect n 2000 (HDR)" "$TD/sunset.exr" 256x128 \
    2000 "--equirect" -- frs-sample --equirect --sigma 2
# A 32 x 32 matrix under a window of 128 x 128 elements a pixel: each
# pixel's block holds every value 16 times, floor(T) among them, so that
# the rule at v = floor(T) (the coin, or --thesis's v < T) decides some
# elements of every pixel.
frd-gen -q -s 32 -S 3 -o "$T/m32.frd"
M=$T/m32.frd
for a in naive sorted; do
	same "32x32 matrix, blob 16x16 n 3000 -a $a" blob 16x16 3000 "" -- \
	    frs-sample -a $a
	same "32x32 matrix, blob 16x16 n 3000 --threshold thesis -a $a" blob \
	    16x16 3000 "--thesis" -- frs-sample -a $a --threshold thesis
done
M=$TD/default.frd
if frs-sample --list-devices >/dev/null 2>&1; then
	for a in sorted stack; do
		same "blob -a $a --device cl" blob 32x32 4000 "" -- \
		    cl_run frs-sample -a $a --device cl
	done
fi

done_testing
