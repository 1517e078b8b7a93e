#!/bin/sh
# Write RES/REPORT.md from the summaries of the experiments that have run:
# the setup they share (RES/.setup), a table of the thesis's claims and one
# of our own (explib.sh's OWN_CLAIMS: verdict, checks held, reversals, the
# last quick- and full-mode times), then every summary, the thesis's first.
set -eu
cd "$(dirname "$0")/.."
RES=${RES:-results}
# secs ID MODE: the time of ID's last run in MODE, or "-"
secs() {
	if [ -s "$RES/.times/$1.$2" ]; then echo "$(cat "$RES/.times/$1.$2") s"; else echo -; fi
}
# The experiments of claims of ours, not the thesis's: explib.sh's
# OWN_CLAIMS, its one definition.
OWN=$(sed -n 's/^OWN_CLAIMS="\(.*\)"$/\1/p' scripts/explib.sh)
own() { case " $OWN " in *" $1 "*) return 0 ;; esac; return 1; }
# ids own|thesis: the experiments that have run, of that kind.
ids() {
	for d in "$RES"/*/; do
		[ -s "$d/summary.md" ] || continue
		id=$(basename "$d")
		if own "$id"; then [ "$1" = own ] && echo "$id"; else [ "$1" = thesis ] && echo "$id"; fi
	done
	:
}
# table IDS...: the verdict table of those experiments.
table() {
	echo "| experiment | verdict | checks held | reversed | quick | full |"
	echo "| --- | --- | --- | --- | --- | --- |"
	for id in "$@"; do
		d=$RES/$id
		v=$(sed -n 's/^\*\*Verdict: \([^.]*\)\.\*\*.*/\1/p' "$d/summary.md")
		c=$(awk -F '\t' 'NR > 1 { n++; h += ($3 == "holds"); r += ($3 == "reversed") }
		    END { printf "%d/%d\t%d", h, n, r }' "$d/checks.tsv" 2>/dev/null || echo "-	-")
		echo "| $id | $v | $(echo "$c" | cut -f 1) | $(echo "$c" | cut -f 2) | $(secs "$id" quick) | $(secs "$id" full) |"
	done
}
{
	echo "# Reproducing the thesis: report"
	echo
	echo "Generated $(date -u +%Y-%m-%dT%H:%MZ) on $(uname -m), $(nproc) cores."
	echo "Each section: our figure, our numbers beside the thesis's, the"
	echo "claims of the thesis checked on this run's numbers, each with the"
	echo "condition it was tested by, and a verdict computed from those"
	echo "checks (reproduced: every check holds)."
	echo
	for f in "$RES"/.setup/*.txt; do
		[ -s "$f" ] && printf 'Setup shared by the experiments: %s\n\n' "$(cat "$f")"
	done
	echo "## The thesis's claims"
	echo
	# shellcheck disable=SC2046
	table $(ids thesis)
	echo
	if [ -n "$(ids own)" ]; then
		echo "## Our own claims, checked"
		echo
		echo "Not in the thesis: claims of ours about this implementation,"
		echo "checked the same way; their verdict is confirmed (every check"
		echo "holds) or not confirmed."
		echo
		# shellcheck disable=SC2046
		table $(ids own)
		echo
	fi
	for id in $(ids thesis) $(ids own); do
		cat "$RES/$id/summary.md"
	done
} >"$RES/REPORT.md.tmp"
mv -f "$RES/REPORT.md.tmp" "$RES/REPORT.md"
