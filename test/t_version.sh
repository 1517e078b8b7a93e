#!/bin/sh
# One version for all: src/lib/api/version.h's FRS_VERSION is what every
# program's --version prints (libfrs's frs_library_version() and frs.pc
# are checked against it by t_install), and no man page or other file
# states another as the current one.  A version other than it may appear
# only as history (on a line with "since", "appeared in", "made by" or
# "made with", and then not after it) or as the version of another piece of software, named on
# its line or the one before (see foreign below).
. "$(dirname "$0")/lib.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)

V=$(sed -n 's/^#define FRS_VERSION "\(.*\)"$/\1/p' "$TOP/src/lib/api/version.h")
case $V in
[0-9]*.[0-9]*.[0-9]*) ok "version.h: FRS_VERSION $V" ;;
*) nok "version.h: no FRS_VERSION \"X.Y.Z\" (${V:-none})" ;;
esac

n=0
for p in "$BIN"/*; do
	[ -x "$p" ] || continue
	name=${p##*/}
	n=$((n + 1))
	out=$("$p" --version 2>&1)
	[ "$out" = "$name (frs) $V" ] && ok "$name --version: $V" ||
	    nok "$name --version: '$out', not '$name (frs) $V'"
done
[ "$n" -ge 10 ] && ok "$n programs" || nok "only $n programs in $BIN"

# Every X.Y.Z in the documentation and the sources, as "FILE:LINE:
# VERSION: BAD" for those that break the rule above; one with a dot
# before it (libfrs.so.1.2.0, the API version) or after it (an address)
# is none.  foreign: the software whose versions the tree names
# (Debian's blender-data, OpenEXR, cmocka), and a section number of
# Abramowitz and Stegun.
scan() {
	awk -v v="$V" '
	function num(s, a) { split(s, a, "."); return a[1] * 1e6 + a[2] * 1e3 + a[3] }
	function foreign(s) {
		return s ~ /blender-data|OpenEXR|cmocka|Abramowitz/
	}
	FNR == 1 { prev = "" }
	{
		line = $0
		rest = line
		while (match(rest, /(^|[^0-9.])[0-9]+\.[0-9]+\.[0-9]+(\.?[^0-9.]|\.?$)/)) {
			m = substr(rest, RSTART, RLENGTH)
			before = substr(rest, 1, RSTART)
			rest = substr(rest, RSTART + RLENGTH - 1)
			sub(/^[^0-9]/, "", m)
			sub(/[^0-9]*$/, "", m)
			if (m == v)
				continue
			if (foreign(prev " " before))
				continue
			if (line ~ /[Ss]ince|appeared in|[Mm]ade (by|with)/) {
				if (num(m) > num(v))
					print FILENAME ":" FNR ": " m ": history after " v
				continue
			}
			print FILENAME ":" FNR ": " m ": states another version than " v
		}
		prev = line
	}' "$@"
}

# The scanner itself, on lines it must refuse and lines it must pass.
cat >"$T/bad.txt" <<EOF
.Qq 0.2.0 .
As of version 0.2.0,
Version: 9.9.9
since 99.0.0 (after it)
Or 0.3.9.
EOF
cat >"$T/good.txt" <<EOF
returns $V .
These functions appeared in libfrs 0.1.0
made with the defaults of frd-gen 0.3.0 (p = 0.5,
Since 0.1.1.
from Debian's blender-data 3.4.1
OpenEXRCore 3.1 and
makes 3.1.5 write
libfrs.so.1.2.0
10.0.0.1 and 1.5 and 2.25
EOF
[ "$(scan "$T/bad.txt" | wc -l)" -eq 5 ] && [ -z "$(scan "$T/good.txt")" ] &&
    ok "the scan tells a stated version from history and others'" ||
    nok "the scan: $(scan "$T/bad.txt" "$T/good.txt" | tr '\n' ';')"

cd "$TOP" || exit 1
files=$(find man src scripts mk -type f; echo README.md Makefile data/README)
scan $files >"$T/found"
[ ! -s "$T/found" ] && ok "no page or file states a version other than $V" || {
	nok "a page or file states a version other than $V"
	sed 's/^/# /' "$T/found"
}
done_testing
