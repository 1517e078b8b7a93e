#!/bin/sh
# Write RES/REPORT.md from the summaries of the experiments that have run.
set -eu
cd "$(dirname "$0")/.."
RES=${RES:-results}
{
	echo "# Reproducing the thesis: report"
	echo
	echo "Generated $(date -u +%Y-%m-%dT%H:%MZ) on $(uname -m), $(nproc) cores."
	echo "Each section: our figure, our numbers beside the thesis's, and a"
	echo "verdict.  The environment map of Fig. 6.1d is the CC0 sunset.exr"
	echo "(data/), not the Grace Cathedral probe the thesis used, which"
	echo "cannot be downloaded here; ENVMAP=file.exr takes another."
	echo
	echo "| experiment | verdict | time |"
	echo "| --- | --- | --- |"
	for d in "$RES"/*/; do
		f=$d/summary.md
		[ -s "$f" ] || continue
		id=$(basename "$d")
		v=$(sed -n 's/^\*\*Verdict: \([^.]*\)\.\*\*.*/\1/p' "$f")
		t=$(sed -n 's/^Time: \(.*\)\.$/\1/p' "$f")
		echo "| $id | $v | $t |"
	done
	echo
	for d in "$RES"/*/; do
		[ -s "$d/summary.md" ] && cat "$d/summary.md"
	done
} >"$RES/REPORT.md.tmp"
mv -f "$RES/REPORT.md.tmp" "$RES/REPORT.md"
