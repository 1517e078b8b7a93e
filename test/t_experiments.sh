#!/bin/sh
# The experiment scripts in their tiny mode: each writes tab-separated data
# with a header, a PNG and a summary with a verdict; the report lists
# them; tab6.1's FRS density in quick mode is where the thesis puts it.
. "$(dirname "$0")/lib.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)
export RES="$T/res" MODE=tiny BIN JOBS=2

for s in "$TOP"/scripts/exp-*.sh; do
	id=$(basename "$s" .sh)
	id=${id#exp-}
	if ! nolsan sh "$s" >"$T/out" 2>"$T/err"; then
		nok "$id: exit status"
		sed 's/^/# /' "$T/err" | tail -n 8
		continue
	fi
	d=$RES/$id
	grep -q '^\*\*Verdict: \(reproduced\|differs\|not reproducible here\)' \
	    "$d/summary.md" 2>/dev/null && ok "$id: summary with a verdict" ||
	    nok "$id: summary with a verdict"
	png=0
	for f in "$d"/*.png; do
		[ -e "$f" ] || continue
		[ "$(head -c 8 "$f" | od -A n -t x1 | tr -d ' ')" = 89504e470d0a1a0a ] &&
		    png=$((png + 1))
	done
	[ $png -ge 1 ] && ok "$id: $png PNG" || nok "$id: no PNG"
	bad=0 ndat=0
	for f in "$d"/*.dat "$d"/*.tsv; do
		[ -e "$f" ] || continue
		ndat=$((ndat + 1))
		# a header line of names, then rows of as many fields
		awk -F '\t' 'NR == 1 { n = NF; if ($1 ~ /^[-0-9.]+$/) exit 1; next }
		    NF != n { exit 1 } END { exit NR < 2 }' "$f" || bad=$((bad + 1))
	done
	[ $ndat -ge 1 ] && [ $bad = 0 ] && ok "$id: $ndat tables with headers" ||
	    nok "$id: tables ($ndat, $bad bad)"
done

sh "$TOP/scripts/report.sh" && grep -q '^| fig6.9 |' "$RES/REPORT.md" &&
    ok "REPORT.md lists the experiments" || nok "REPORT.md"

# ONLY selects by id or alias; an unknown one is an error.
MODE=tiny ONLY=fig6.9 nolsan sh "$TOP/scripts/experiments.sh" >/dev/null 2>"$T/err" &&
    ok "ONLY=fig6.9" || nok "ONLY=fig6.9: $(tail -n 1 "$T/err")"
expect_fail "ONLY=nothing" 2 "no experiment matches" - \
    env MODE=tiny ONLY=nothing sh "$TOP/scripts/experiments.sh"

# tab6.1 in quick mode: FRS's uniform density where the thesis puts it
# (0.650; Lagae and Dutre's good range starts at 0.65).
if MODE=quick RES="$T/q" nolsan sh "$TOP/scripts/exp-tab6.1.sh" >/dev/null 2>"$T/err"; then
	v=$(awk -F '\t' '$1 == "frs" { print $2 }' "$T/q/tab6.1/tab6.1.tsv")
	awk -v v="$v" 'BEGIN { exit !(v >= 0.6 && v <= 0.72) }' &&
	    ok "tab6.1 quick: FRS density $v in [0.6, 0.72]" ||
	    nok "tab6.1 quick: FRS density $v not in [0.6, 0.72]"
else
	nok "tab6.1 quick mode"
	sed 's/^/# /' "$T/err" | tail -n 5
fi
