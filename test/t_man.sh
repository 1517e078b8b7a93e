#!/bin/sh
# The manuals as a reader sees them (mandoc -Tutf8; run.sh's lint-man
# checks the source): no quote opens inside another on one line, as
# mdoc's enclosing macros do when two share a line (".Ql 512M , Ql 8G"
# rendered "‘512M, ‘8G’’"), and FRS_MAX_MEM's units read plainly.
. "$(dirname "$0")/lib.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)
command -v mandoc >/dev/null || skip_all "mandoc is missing"

# nested FILE...: "page: line" for each rendered line on which a quote
# (single or double) opens before the one before it has closed.
nested() {
	for pg in "$@"; do
		mandoc -Tutf8 "$pg" 2>/dev/null | col -b | awk -v pg="${pg##*/}" '
		{
			s = $0; d1 = 0; d2 = 0; bad = 0
			while (s != "") {
				c = substr(s, 1, 1)
				# "‘" and "“" are 3 bytes in UTF-8, as are their closers.
				q = substr(s, 1, 3)
				if (q == "‘") { if (d1) bad = 1; d1 = 1; s = substr(s, 4); continue }
				if (q == "’") { d1 = 0; s = substr(s, 4); continue }
				if (q == "“") { if (d2) bad = 1; d2 = 1; s = substr(s, 4); continue }
				if (q == "”") { d2 = 0; s = substr(s, 4); continue }
				s = substr(s, 2)
			}
			if (bad) print pg ": " $0
		}'
	done
}

# The check itself, on a page with the broken construct and a sound one.
printf '.Dd May 1, 2026\n.Dt X 1\n.Os\n.Sh NAME\n.Nm x\n.Nd y\n.Sh DESCRIPTION\nSuffix\n.Pq Ql 512M , Ql 8G ;\nand\n.Ql one\nor\n.Dq two .\n' \
    >"$T/x.1"
sed '/Pq Ql 512M/d' "$T/x.1" >"$T/y.1"
[ -n "$(nested "$T/x.1")" ] && [ -z "$(nested "$T/y.1")" ] &&
    ok "nested quotes are seen" || nok "nested quotes: $(nested "$T/x.1" "$T/y.1")"

nested "$TOP"/man/man*/*.[0-9] >"$T/found"
[ ! -s "$T/found" ] && ok "no quote opens inside another in any manual" || {
	nok "no quote opens inside another in any manual"
	sed 's/^/# /' "$T/found"
}

# FRS_MAX_MEM in frs(7) and every page that names it: the suffixes and
# the examples as plain words, no quote marks around them.
for pg in "$TOP"/man/man*/*.[0-9]; do
	grep -q 'FRS_MAX_MEM' "$pg" || continue
	mandoc -Tutf8 "$pg" | col -b | tr '\n' ' ' | tr -s ' \t' '  ' |
	    grep -o 'optional binary suffix[^;]*;' | grep -q '[‘’]' &&
	    echo "${pg##*/}"
done >"$T/quoted"
[ ! -s "$T/quoted" ] && ok "FRS_MAX_MEM's suffixes read plainly" ||
    nok "FRS_MAX_MEM's suffixes are quoted in: $(tr '\n' ' ' <"$T/quoted")"
done_testing
