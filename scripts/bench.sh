#!/bin/sh
# make bench: run every scripts/bench-*.sh against the programs of a build
# (build/rel: the one make and make install make, as users run it) and
# print their tables; bench-build.sh times build/bench (-O3
# -march=native) beside it.  Each script gets the build directory: programs in BUILD/bin,
# reference implementations and drivers (test/ref/*.c, test/bench/*.c)
# in BUILD/test.
set -eu
cd "$(dirname "$0")/.."
BUILD=${1:-build/rel}
echo "bench: $(uname -m), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ)"
for b in scripts/bench-*.sh; do
	echo
	sh "$b" "$BUILD"
done
