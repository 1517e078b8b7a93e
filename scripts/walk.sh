#!/bin/sh
# The walk a reader follows through frs-sample's setup (issue 36): from
# main to the first threshold (frs_thr_make), the calls that go to
# another file of ours, each (caller, callee) once, leaving out the
# utilities (src/lib/base), the programs' option handling (src/cli) and
# the libraries'.  "Ups" counts where the walk, read in order, comes back
# to a higher layer (the program above the library's stages, in
# test/layers.sh's order) than the call before.
#   sh scripts/walk.sh [FRS-SAMPLE ARGS...]
# default: the shipped matrix and interior.exr, as a user would start.
# Builds frs-sample with -finstrument-functions into build/walk
# (test/walk/tracer.c records the calls).
set -eu
TOP=$(cd "$(dirname "$0")/.." && pwd)
. "$TOP/test/layers.sh"
cd "$TOP"
B=build/walk
mkdir -p "$B"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
[ $# -gt 0 ] || set -- -i data/interior.exr --equirect -n 4096
${CC:-cc} -std=c11 -O2 -c test/walk/tracer.c -o "$B/tracer.o"
rm -f "$B/bin/frs-sample"
make --no-print-directory -s B="$B" OPT="-O0 -g -finstrument-functions" \
    LDFLAGS="$TOP/$B/tracer.o" "$B/bin/frs-sample" >&2
# "OFFSET NAME FILE" of every function, the file relative to src/.
nm -l "$B/bin/frs-sample" | awk 'NF >= 3 && $2 ~ /^[tTwW]$/ {
	f = NF > 3 ? $4 : "?"; sub(/:[0-9]+$/, "", f); sub(/.*\/src\//, "", f)
	print $1, $3, f }' >"$T/syms"
stop=$(awk '$2 == "frs_thr_make" { print $1 }' "$T/syms")
WALK_TRACE=$T/trace WALK_STOP=$stop "$B/bin/frs-sample" "$@" -j 1 -q \
    -o /dev/null
awk -v layers="$LAYERS" '
function layer(f) {
	if (f ~ /^lib\/[a-z]+\//) { split(f, p, "/"); return p[2] }
	if (f ~ /^cli\//) return "cli"
	if (f ~ /\.c$/) return "prog"
	return "other"
}
function rank(l) {
	return l == "prog" ? nlayer : (l in stage) ? stage[l] : -1
}
BEGIN {
	nlayer = split(layers, st, " ")
	for (i = 1; i <= nlayer; i++) {
		k = split(st[i], part, ",")
		for (j = 1; j <= k; j++)
			stage[part[j]] = i - 1
	}
}
FNR == NR { name[$1] = $2; file[$1] = $3; next }
$1 == "E" {
	n = name[$2]; f = file[$2]
	caller = d > 0 ? stack[d] : ""
	stack[++d] = $2
	if (caller == "" || file[caller] == f) next
	l = layer(f)
	if (l == "base" || l == "cli" || l == "other" || n ~ /^_Z/) next
	if ((caller, n) in seen) next
	seen[caller, n] = 1
	calls++
	if (!(f in files)) { files[f] = 1; nfiles++ }
	if (calls > 1 && rank(l) > rank(last)) ups++
	last = l
	printf "%-28s -> %-28s %s\n", name[caller], n, f
	next
}
$1 == "X" { d-- }
END { printf "%d calls through %d files, %d returns to a higher layer\n",
    calls, nfiles, ups }
' "$T/syms" "$T/trace"
