#!/bin/sh
# README.md's "A pipeline to paste", its lines taken from the README so
# that the two stay in step, run as a user pastes it from the repository
# root: every file it makes lands in the scratch directory of its
# mktemp -d, none in the tree; the shipped data are named through
# frs-sample --data-dir.  The programs under test stand in for bin/: the
# README's PATH line is left out (test/lib.sh puts $BIN first on PATH).
. "$(dirname "$0")/lib.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)

awk '/^## A pipeline to paste/ { on = 1; next } on && /^## / { exit }
    on && /^    / { print substr($0, 5) }' "$TOP/README.md" >"$T/all.sh"
grep -v '^PATH=' "$T/all.sh" >"$T/pipe.sh"
[ "$(wc -l <"$T/all.sh")" -gt 10 ] && grep -q 'mktemp -d' "$T/pipe.sh" &&
    ok "README: the pipeline, $(wc -l <"$T/pipe.sh") lines, into mktemp -d" ||
    nok "README: a pipeline of more than 10 lines that starts in mktemp -d"

untracked() {
	git -C "$TOP" ls-files --others --exclude-standard 2>/dev/null | sort
}
untracked >"$T/before"
mkdir "$T/tmp"
# FRS_DATA unset: the programs find the data themselves.
if (cd "$TOP" && unset FRS_DATA FRS_MATRIX FRS_MATRIX3 &&
    TMPDIR="$T/tmp" sh -e "$T/pipe.sh") >"$T/out" 2>"$T/err"; then
	ok "README pipeline runs"
else
	nok "README pipeline runs"
	sed 's/^/# /' "$T/err" | tail -n 10
fi
grep -qE 'Sanitizer|runtime error' "$T/err" && nok "README pipeline: a sanitizer report"
# Its last line is pwd: the scratch directory.
dir=$(tail -n 1 "$T/out")
case $dir in
"$T"/tmp/tmp.*) ok "the files are in $dir" ;;
*) nok "the pipeline's last line is its scratch directory: '$dir'" ;;
esac
missing=""
for f in blob.exr X.pts X.png M.frd S.pts S.png V.frd env.exr env.pts env.png; do
	[ -s "$dir/$f" ] || missing="$missing $f"
done
[ -z "$missing" ] && ok "it made its ten files there" || nok "not made:$missing"
untracked >"$T/after"
cmp -s "$T/before" "$T/after" && ok "no new untracked files in the tree" || {
	nok "no new untracked files in the tree"
	diff "$T/before" "$T/after" | head -n 10 | sed 's/^/# /'
}
done_testing
