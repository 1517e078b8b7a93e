#!/bin/sh
# A clone alone: the repository as `git clone` gives it, in a directory
# with no ../shared beside it, holds everything the tests read.  Nothing
# in test/, scripts/, mk/, .ci/ or the Makefile names the project's
# shared folder, and a shell test that reads the real maps and the
# authors' matrix (t_imap, t_frd-prep) passes inside the clone.
. "$(dirname "$0")/lib.sh"

top=$PWD
if ! command -v git >/dev/null 2>&1 || ! git -C "$top" rev-parse HEAD >/dev/null 2>&1; then
	skip_all "not a git checkout (a tarball): nothing to clone"
fi
mkdir -p "$T/empty"
if git clone -q "$top" "$T/empty/frs" 2>"$T/err"; then
	ok "git clone into an empty directory"
else
	nok "git clone into an empty directory"
	sed 's/^/# /' "$T/err"
	done_testing
	exit 0
fi
[ ! -e "$T/empty/shared" ] && ok "no shared folder beside the clone" ||
    nok "no shared folder beside the clone"

cd "$T/empty/frs" || exit 1
# (this file names what it looks for; FRS_SHAREDIR is the install's)
hits=$(grep -rlE 'FRS_SHARED\b|\.\./shared' test scripts mk .ci Makefile 2>/dev/null |
    grep -v '^test/t_clone\.sh$')
[ -z "$hits" ] && ok "nothing in test, scripts, mk, .ci or the Makefile reads ../shared" ||
    nok "these read ../shared: $(echo $hits)"
for f in data/sunset.exr data/forest.exr data/interior.exr \
    data/authors-512x512.matrix data/default.frd data/default3.frd; do
	[ -s "$f" ] && ok "the clone has $f" || nok "the clone has $f"
done

# The shell tests that read the data, run in the clone with the programs
# of this build: their own checks count here as one each.
for t in t_imap t_frd-prep; do
	if sh "test/$t.sh" >"$T/$t.out" 2>&1 && ! grep -q '^not ok' "$T/$t.out"; then
		ok "$t passes in the clone ($(grep -c '^ok' "$T/$t.out") checks)"
	else
		nok "$t passes in the clone"
		grep '^not ok' "$T/$t.out" | sed 's/^/# /'
	fi
done
cd "$top" || exit 1
done_testing
