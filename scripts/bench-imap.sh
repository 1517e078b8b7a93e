#!/bin/sh
# Importance-map input: seconds per load by format and size, and what
# resampling costs.  Each figure is the best of 3 whole-process runs.
set -eu
BUILD=${1:-build/rel}
IMAP=$BUILD/bin/imap
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

best() {	# best wall seconds of 3 runs of "$@"
	b=""
	for i in 1 2 3; do
		s=$(date +%s.%N)
		"$@" >/dev/null 2>&1
		e=$(date +%s.%N)
		b=$(awk -v b="$b" -v s="$s" -v e="$e" 'BEGIN {
			d = e - s; print (b == "" || d < b) ? d : b }')
	done
	echo "$b"
}

"$IMAP" gen sky -s 1024x512 -o "$T/sky-zip.exr"
"$IMAP" gen sky -s 1024x512 -o "$T/sky.png"
"$IMAP" gen blob -s 4096x4096 -o "$T/big.exr"
dwa=data/sunset.exr

echo "imap: load and describe a map (imap info), best of 3"
printf '%-34s %10s %12s\n' "input" "seconds" "Mpixel/s"
row() {	# NAME PIXELS imap-info-arguments...
	n=$1 p=$2
	shift 2
	s=$(best "$IMAP" info "$@")
	awk -v n="$n" -v s="$s" -v p="$p" 'BEGIN {
		printf "%-34s %10.4f %12.1f\n", n, s, p / s / 1e6 }'
}
row "1024x512 EXR DWAB (C++ library)" 524288 "$dwa"
row "1024x512 EXR ZIP float (C core)" 524288 "$T/sky-zip.exr"
row "1024x512 PNG 16-bit" 524288 "$T/sky.png"
row "4096x4096 EXR ZIP float" 16777216 "$T/big.exr"
row "procedural sky 1024x512" 524288 -s 1024x512 sky
row "procedural blob 4096x4096" 16777216 -s 4096x4096 blob

echo
echo "imap: area-weighted resampling of a 4096x4096 map (imap convert -s)"
printf '%-34s %10s\n' "target" "seconds"
for t in 128x128 1024x1024 3000x3000; do
	s=$(best "$IMAP" convert -s "$t" "$T/big.exr" "$T/o.exr")
	printf '%-34s %10.4f\n' "$t" "$s"
done
