#!/bin/sh
# ref-sample: seconds for 10 sets of 1024 points of each reference
# distribution (the thesis measures against 10 sets, Table 6.1).
set -eu
BUILD=${1:-build/rel}
REF=$BUILD/bin/ref-sample
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

echo "ref-sample: 10 sets of 1024 points"
printf '%-13s %10s %12s\n' kind seconds per_set_ms
for k in random regular jittered halton hammersley sobol dart relaxed-dart; do
	args=""
	[ $k = relaxed-dart ] && args="-i blob"
	s=$(date +%s.%N)
	ok=1
	for seed in 1 2 3 4 5 6 7 8 9 10; do
		"$REF" -q -k $k $args -n 1024 -S $seed -o "$T/x.pts" 2>/dev/null || ok=0
	done
	e=$(date +%s.%N)
	if [ $ok = 1 ]; then
		awk -v k=$k -v s="$s" -v e="$e" 'BEGIN {
			printf "%-13s %10.3f %12.2f\n", k, e - s, (e - s) * 100 }'
	else
		printf '%-13s %10s\n' $k "n/a"
	fi
done
