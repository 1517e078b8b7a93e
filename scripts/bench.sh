#!/bin/sh
# make bench: run every scripts/bench-*.sh against the programs of a build
# (build/bench: -O3 -march=native, made by make bench) and print their
# tables.  Each script gets the build directory: programs in BUILD/bin,
# reference implementations and drivers (test/ref/*.c, test/bench/*.c)
# in BUILD/test.
set -eu
cd "$(dirname "$0")/.."
BUILD=${1:-build/bench}
echo "bench: $(uname -m), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ)"
for b in scripts/bench-*.sh; do
	echo
	sh "$b" "$BUILD"
done
