# Helpers for the samplers' shell tests (t_frs-sample, t_hsw-sample,
# t_ref-sample, hard/t_hard); source it after lib.sh.

# pts_count FILE: the point count in the header of the pts(5) file FILE.
pts_count() { od -A n -t u8 -j 24 -N 8 "$1" | tr -d ' '; }

# impls_same TEXT ARGS...: frs-sample ARGS -T gives the points of the
# text file TEXT, order and comments aside, with each of -a naive, stack,
# level1 and level2.
impls_same() {
	_text=$1
	shift
	grep -v '^#' "$_text" | sort >"$T/impls.s"
	for _a in naive stack level1 level2; do
		frs-sample "$@" -a $_a -T | grep -v '^#' | sort |
		    cmp -s - "$T/impls.s" || return 1
	done
}

# writes_points WHAT N FILE CMD...: one check, that CMD succeeds and
# writes N points to FILE; its messages shown when it fails.
writes_points() {
	_what=$1 _n=$2 _file=$3
	shift 3
	if "$@" 2>"$T/err" && [ "$(pts_count "$_file")" = "$_n" ]; then
		ok "$_what"
	else
		nok "$_what"
		sed 's/^/# /' "$T/err"
	fi
}
