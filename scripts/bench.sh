#!/bin/sh
# make bench: run every scripts/bench-*.sh against the programs in BINDIR
# (built with -O3 -march=native by make bench) and print their tables.
set -eu
cd "$(dirname "$0")/.."
BINDIR=${1:-bin}
echo "bench: $(uname -m), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ)"
for b in scripts/bench-*.sh; do
	echo
	sh "$b" "$BINDIR"
done
