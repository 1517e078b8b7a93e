#!/bin/sh
# Write RES/REPORT.md from the summaries of the experiments that have run:
# a table (verdict, checks held, reversals, the last quick- and full-mode
# times), then every summary.
set -eu
cd "$(dirname "$0")/.."
RES=${RES:-results}
# secs ID MODE: the time of ID's last run in MODE, or "-"
secs() {
	if [ -s "$RES/.times/$1.$2" ]; then echo "$(cat "$RES/.times/$1.$2") s"; else echo -; fi
}
{
	echo "# Reproducing the thesis: report"
	echo
	echo "Generated $(date -u +%Y-%m-%dT%H:%MZ) on $(uname -m), $(nproc) cores."
	echo "Each section: our figure, our numbers beside the thesis's, the"
	echo "claims of the thesis checked on this run's numbers, and a verdict"
	echo "computed from those checks (reproduced: every check holds)."
	echo
	echo "| experiment | verdict | checks held | reversed | quick | full |"
	echo "| --- | --- | --- | --- | --- | --- |"
	for d in "$RES"/*/; do
		f=$d/summary.md
		[ -s "$f" ] || continue
		id=$(basename "$d")
		v=$(sed -n 's/^\*\*Verdict: \([^.]*\)\.\*\*.*/\1/p' "$f")
		c=$(awk -F '\t' 'NR > 1 { n++; h += ($3 == "holds"); r += ($3 == "reversed") }
		    END { printf "%d/%d\t%d", h, n, r }' "$d/checks.tsv" 2>/dev/null || echo "-	-")
		echo "| $id | $v | $(echo "$c" | cut -f 1) | $(echo "$c" | cut -f 2) | $(secs "$id" quick) | $(secs "$id" full) |"
	done
	echo
	for d in "$RES"/*/; do
		[ -s "$d/summary.md" ] && cat "$d/summary.md"
	done
} >"$RES/REPORT.md.tmp"
mv -f "$RES/REPORT.md.tmp" "$RES/REPORT.md"
