#!/bin/sh
# make install into a staging directory (DESTDIR, PREFIX=/usr), then the
# library as a user has it: test/api_example.c built with pkg-config,
# against libfrs.so and against libfrs.a, prints frs-sample's points;
# the .so exports the API of src/lib/frs.h and nothing else; make
# uninstall takes everything away again.  Then make install into a
# prefix of its own: the example linked with frs.pc (and its rpath) and
# with frs-static.pc runs with LD_LIBRARY_PATH unset and finds the
# shipped matrix; the installed programs find their data after the
# prefix is moved, FRS_DATA overrides, and a failed search names every
# place looked at.  The build has SRCDATA empty: nothing installed can
# fall back on the source tree.
. "$(dirname "$0")/lib.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)
# A rel build of its own beside the tested one (BUILD-inst for BUILD),
# kept between runs so that later runs only relink what changed.
IB=${FRS_INSTALL_BUILD:-${BIN%/bin}-inst}
D=$T/dest
U=$D/usr
# This runs inside make check: not the outer make's flags and jobserver.
unset MAKEFLAGS MFLAGS MAKELEVEL
mk() {
	make -C "$TOP" --no-print-directory -j"$(nproc)" VARIANT=rel B="$IB" \
	    SRCDATA= PREFIX=/usr DESTDIR="$D" "$@"
}

if mk install >"$T/make.log" 2>&1; then
	ok "make install (build in $IB)"
else
	nok "make install"
	tail -n 20 "$T/make.log" | sed 's/^/# /'
	exit 1
fi

# ---- what is installed -------------------------------------------------

progs=$(awk '/^PROGS =/ { on = 1; sub(/^PROGS =/, "") }
    on { l = $0; sub(/\\$/, "", l); printf "%s ", l; if ($0 !~ /\\$/) exit }' \
    "$TOP/Makefile")
missing=""
for p in $progs; do
	[ -x "$U/bin/$p" ] || missing="$missing bin/$p"
done
# The soname's major and the file's minor are the API version's (frs.h).
maj=$(sed -n 's/^#define FRS_API_VERSION_MAJOR //p' "$TOP/src/lib/frs.h")
min=$(sed -n 's/^#define FRS_API_VERSION_MINOR //p' "$TOP/src/lib/frs.h")
so=libfrs.so.$maj.$min.0
for f in include/frs.h lib/libfrs.a lib/$so \
    lib/pkgconfig/frs.pc lib/pkgconfig/frs-static.pc share/frs/default.frd \
    share/frs/default3.frd \
    share/frs/sunset.exr; do
	[ -f "$U/$f" ] || missing="$missing $f"
done
for f in "$TOP"/man/man[1357]/*.[1357]; do
	[ -f "$f" ] || continue
	s=${f##*.}
	[ -f "$U/share/man/man$s/${f##*/}" ] || missing="$missing man$s/${f##*/}"
done
[ -z "$missing" ] && ok "programs, header, libraries, frs.pc, matrix, man pages" ||
    nok "not installed:$missing"
cmp -s "$TOP/src/lib/frs.h" "$U/include/frs.h" && ok "frs.h as in src/lib/" ||
    nok "frs.h as in src/lib/"
[ "$(readlink "$U/lib/libfrs.so.$maj")" = $so ] &&
    [ "$(readlink "$U/lib/libfrs.so")" = $so ] &&
    ok "libfrs.so and libfrs.so.$maj link to $so" ||
    nok "libfrs.so and libfrs.so.$maj link to $so"
readelf -d "$U/lib/$so" | grep -q "SONAME.*\[libfrs\.so\.$maj\]" &&
    ok "soname libfrs.so.$maj" || nok "soname libfrs.so.$maj"

# The exported functions are those the header declares, no more (its
# static inline ones, frs_imap_pixel_of, are the caller's own code).
grep -v '^static inline' "$TOP/src/lib/frs.h" | grep -o 'frs_[a-z0-9_]*(' |
    tr -d '(' | sort -u >"$T/api.txt"
nm -D --defined-only "$U/lib/$so" |
    awk '$2 != "A" { sub(/@.*/, "", $3); print $3 }' | sort -u >"$T/exported.txt"
if cmp -s "$T/api.txt" "$T/exported.txt"; then
	ok "libfrs.so exports the $(wc -l <"$T/api.txt") functions of frs.h"
else
	nok "libfrs.so exports the functions of frs.h"
	diff "$T/api.txt" "$T/exported.txt" | head -n 20 | sed 's/^/# /'
fi
nm -D --defined-only "$U/lib/$so" | grep -qw -e imap_load -e frs_fail &&
    nok "internal symbols (imap_load, frs_fail) exported" ||
    ok "internal symbols (imap_load, frs_fail) not exported"

# ---- pkg-config ----------------------------------------------------------

# The staged tree as if it were /: the sysroot goes before -I and -L,
# which must not be dropped as system directories (-I/usr/include).
pc() {
	PKG_CONFIG_PATH="$U/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}" \
	    PKG_CONFIG_SYSROOT_DIR="$D" PKG_CONFIG_ALLOW_SYSTEM_CFLAGS=1 \
	    PKG_CONFIG_ALLOW_SYSTEM_LIBS=1 pkg-config "$@"
}
CFLAGS_FRS=$(pc --cflags frs) && LIBS_FRS=$(pc --libs frs) &&
    LIBS_STATIC=$(pc --static --libs frs) &&
    ok "pkg-config: $CFLAGS_FRS $LIBS_FRS" || nok "pkg-config --cflags --libs frs"
cat >"$T/version.c" <<'EOF'
#include <stdio.h>
#include <frs.h>
int main(void) { puts(frs_library_version()); return 0; }
EOF
if cc -o "$T/version" "$T/version.c" $CFLAGS_FRS $LIBS_FRS 2>"$T/err" &&
    [ "$(LD_LIBRARY_PATH="$U/lib" "$T/version")" = "$(pc --modversion frs)" ]; then
	ok "pkg-config --modversion frs is frs_library_version()"
else
	nok "pkg-config --modversion frs is frs_library_version()"
	sed 's/^/# /' "$T/err" | head -n 5
fi
V=$(sed -n 's/^#define FRS_VERSION "\(.*\)"$/\1/p' "$TOP/src/lib/api/version.h")
[ -n "$V" ] && [ "$(pc --modversion frs)" = "$V" ] &&
    [ "$(pc --modversion frs-static)" = "$V" ] &&
    ok "frs.pc and frs-static.pc: version.h's $V" ||
    nok "frs.pc and frs-static.pc: $(pc --modversion frs), not version.h's ${V:-?}"
# The header alone, as C with every warning and as C++.
printf '#include <frs.h>\nint main(void) { return FRS_OK; }\n' >"$T/h.c"
check "frs.h: C11 -Wall -Wextra -pedantic -Werror" cc -std=c11 -Wall -Wextra \
    -pedantic -Werror -c "$T/h.c" -o "$T/h.o" $CFLAGS_FRS
cp "$T/h.c" "$T/h.cc"
check "frs.h: C++" c++ -Wall -Wextra -Werror -c "$T/h.cc" -o "$T/hcc.o" \
    $CFLAGS_FRS

# ---- the example, as frs-sample ----------------------------------------

# A float EXR map, which both read as the same values.
"$U/bin/imap" gen -q -s 96x64 -o "$T/map.exr" blob
M=$U/share/frs/default.frd
# frs-sample writes the shortest round-trip form, the example %.17g:
# awk reads the values back exactly and prints them as the example does
# (4096 samples, seed 1).
refpts() {
	"${FS:-$U/bin/frs-sample}" -q -m "$1" -i "$T/map.exr" -n 4096 -S 1 -T |
	    awk '!/^#/ { printf "%.17g %.17g\n", $1, $2 }'
}
refpts "$M" >"$T/ref.txt"
# same_points OUT WHAT: OUT holds the reference points; else not ok WHAT
# with the first lines of the standard error ($T/err) and of the
# difference.
same_points() {
	if cmp -s "$1" "$T/ref.txt"; then
		ok "$2"
	else
		nok "$2"
		sed 's/^/# /' "$T/err" | head -n 5
		diff "$1" "$T/ref.txt" | head -n 5 | sed 's/^/# /'
	fi
}
[ "$(wc -l <"$T/ref.txt")" -gt 3000 ] && ok "frs-sample: $(wc -l <"$T/ref.txt") points" ||
    nok "frs-sample: $(wc -l <"$T/ref.txt") points"
WARN="-std=c11 -Wall -Wextra -Wconversion -Werror"

# The example is the one in libfrs(3) and frs_draw(3), character for
# character once the roff escapes are undone.
for page in libfrs.3 frs_draw.3; do
	awk '/example:begin/ { on = 1; next } on && /^\.Bd/ { next }
	    on && /^\.Ed/ { exit } on' "$TOP/man/man3/$page" |
	    sed -e 's/\\e/\\/g' -e 's/^\\&//' >"$T/page.c"
	cmp -s "$T/page.c" "$TOP/test/api_example.c" &&
	    ok "$page: its example is test/api_example.c" || {
		nok "$page: its example is test/api_example.c"
		diff "$T/page.c" "$TOP/test/api_example.c" | head -n 10 | sed 's/^/# /'
	}
done

# Dynamic: libfrs.so.$maj from the staging directory.
if cc $WARN -o "$T/ex_dyn" "$TOP/test/api_example.c" $CFLAGS_FRS $LIBS_FRS \
    2>"$T/err"; then
	ok "api_example.c built against libfrs.so"
	readelf -d "$T/ex_dyn" | grep -q "NEEDED.*\[libfrs\.so\.$maj\]" &&
	    ok "it needs libfrs.so.$maj" || nok "it needs libfrs.so.$maj"
	LD_LIBRARY_PATH="$U/lib" "$T/ex_dyn" "$T/map.exr" "$M" \
	    >"$T/dyn.txt" 2>"$T/err"
	same_points "$T/dyn.txt" "dynamic: frs-sample's points"
	# The staged tree is not where it was built for (/usr): the
	# default matrix found beside libfrs.so.
	LD_LIBRARY_PATH="$U/lib" "$T/ex_dyn" "$T/map.exr" >"$T/dyn.txt" 2>"$T/err"
	same_points "$T/dyn.txt" "dynamic: frs_default_matrix beside libfrs.so"
else
	nok "api_example.c built against libfrs.so"
	sed 's/^/# /' "$T/err" | head -n 10
fi

# Static: libfrs.a and what pkg-config --static adds (the other
# libraries stay shared: static copies of them are seldom installed).
ST=$(echo "$LIBS_STATIC" | sed 's/-lfrs\b/-Wl,-Bstatic -lfrs -Wl,-Bdynamic/')
if cc $WARN -o "$T/ex_st" "$TOP/test/api_example.c" $CFLAGS_FRS $ST \
    2>"$T/err"; then
	ok "api_example.c built against libfrs.a: $ST"
	readelf -d "$T/ex_st" | grep -q 'libfrs' && nok "it does not need libfrs.so" ||
	    ok "it does not need libfrs.so"
	"$T/ex_st" "$T/map.exr" "$M" >"$T/st.txt" 2>"$T/err"
	same_points "$T/st.txt" "static: frs-sample's points"
	FRS_DATA=$U/share/frs "$T/ex_st" "$T/map.exr" >"$T/st.txt" 2>"$T/err"
	same_points "$T/st.txt" "static: frs_default_matrix in FRS_DATA"
else
	nok "api_example.c built against libfrs.a: $ST"
	sed 's/^/# /' "$T/err" | head -n 10
fi
"$T/ex_st" "$T/nonexistent.exr" "$M" >/dev/null 2>"$T/err"
[ $? -eq 1 ] && grep -q 'FRS_E_IO' "$T/err" && ok "example: a missing map is FRS_E_IO" ||
    nok "example: a missing map is FRS_E_IO"

# ---- uninstall -----------------------------------------------------------

if mk uninstall >"$T/make.log" 2>&1; then
	left=$(find "$D" ! -type d | sed "s|^$D||")
	[ -z "$left" ] && ok "make uninstall removes every file" ||
	    nok "make uninstall left:" $left
else
	nok "make uninstall"
	tail -n 10 "$T/make.log" | sed 's/^/# /'
fi

# ---- a prefix of one's own, then moved --------------------------------

# Paths as the programs see them (realpath of /proc/self/exe).
R=$(cd "$T" && pwd -P)
P=$R/prefix
if make -C "$TOP" --no-print-directory -j"$(nproc)" VARIANT=rel B="$IB" \
    SRCDATA= PREFIX="$P" install >"$T/make.log" 2>&1; then
	ok "make install PREFIX=$P"
else
	nok "make install PREFIX=$P"
	tail -n 20 "$T/make.log" | sed 's/^/# /'
	exit 1
fi
pcp() { PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config "$@"; }
unset LD_LIBRARY_PATH FRS_DATA FRS_MATRIX FRS_MATRIX3
[ "$("$P/bin/frs-sample" --data-dir 2>&1)" = "$P/share/frs" ] &&
    ok "frs-sample --data-dir: $P/share/frs" ||
    nok "frs-sample --data-dir: $("$P/bin/frs-sample" --data-dir 2>&1)"

# link_run PC EXE [FLAGS...]: the example linked with pkg-config PC (and
# FLAGS) into EXE, which prints frs-sample's points with the default
# matrix; 0 if it linked.
link_run() {
	_pc=$1 _exe=$2
	shift 2
	if ! cc $WARN -o "$_exe" "$TOP/test/api_example.c" $(pcp --cflags "$_pc") \
	    $(pcp --libs "$_pc") "$@" 2>"$T/err"; then
		nok "linked with pkg-config $_pc"
		sed 's/^/# /' "$T/err" | head -n 10
		return 1
	fi
	ok "linked with pkg-config $_pc"
	"$_exe" "$T/map.exr" >"$T/p.txt" 2>"$T/err"
	same_points "$T/p.txt" \
	    "$_pc.pc: frs-sample's points with the default matrix"
}
# frs.pc with its rpath: libfrs.so of the prefix, found without
# LD_LIBRARY_PATH, and the shipped matrix beside it.
link_run frs "$T/p_dyn" $(pcp --variable=rpath frs) &&
    { ldd "$T/p_dyn" | grep -q "libfrs\.so\.$maj => $P/lib/" &&
    ok "it loads $P/lib/libfrs.so.$maj" || nok "it loads $P/lib/libfrs.so.$maj"; }
# frs-static.pc: libfrs.a by its path, no libfrs.so needed.
pcp --libs frs-static | grep -q -- "$P/lib/libfrs\.a" &&
    ok "pkg-config --libs frs-static names $P/lib/libfrs.a" ||
    nok "pkg-config --libs frs-static names libfrs.a: $(pcp --libs frs-static)"
link_run frs-static "$T/p_st" &&
    { readelf -d "$T/p_st" | grep -q 'NEEDED.*libfrs' &&
    nok "frs-static: it needs libfrs.so" || ok "frs-static: it does not need libfrs.so"; }

# The prefix moved: its programs find their data where they are now.
Q=$R/moved
mv "$P" "$Q"
[ "$("$Q/bin/frs-sample" --data-dir 2>&1)" = "$Q/share/frs" ] &&
    ok "moved: frs-sample --data-dir: $Q/share/frs" ||
    nok "moved: frs-sample --data-dir: $("$Q/bin/frs-sample" --data-dir 2>&1)"
"$Q/bin/frs-sample" -q -i "$T/map.exr" -n 4096 -S 1 -T 2>"$T/err" |
    awk '!/^#/ { printf "%.17g %.17g\n", $1, $2 }' >"$T/q.txt"
same_points "$T/q.txt" "moved: frs-sample without -m"
"$Q/bin/imap" convert -q -s 32x16 "$("$Q/bin/frs-sample" --data-dir)/sunset.exr" \
    "$T/env.exr" 2>"$T/err" && ok "moved: --data-dir names sunset.exr" ||
    nok "moved: --data-dir names sunset.exr"
LD_LIBRARY_PATH="$Q/lib" "$T/p_dyn" "$T/map.exr" >"$T/p.txt" 2>"$T/err"
same_points "$T/p.txt" "moved: frs_default_matrix beside libfrs.so"

# FRS_DATA: another directory, the only one looked in.
mkdir "$T/alt"
"$Q/bin/frd-gen" -q -s 64 -S 3 -o "$T/alt/default.frd"
FS=$Q/bin/frs-sample refpts "$T/alt/default.frd" >"$T/alt.txt"
[ "$(wc -l <"$T/alt.txt")" -gt 3000 ] && ! cmp -s "$T/alt.txt" "$T/ref.txt" &&
    ok "FRS_DATA: another matrix, other points" ||
    nok "FRS_DATA: another matrix, other points"
[ "$(FRS_DATA=$T/alt "$Q/bin/frs-sample" --data-dir 2>&1)" = "$T/alt" ] &&
    ok "FRS_DATA: frs-sample --data-dir" || nok "FRS_DATA: frs-sample --data-dir"
FRS_DATA=$T/alt "$Q/bin/frs-sample" -q -i "$T/map.exr" -n 4096 -S 1 -T 2>"$T/err" |
    awk '!/^#/ { printf "%.17g %.17g\n", $1, $2 }' >"$T/q.txt"
cmp -s "$T/q.txt" "$T/alt.txt" && ok "FRS_DATA: frs-sample's default matrix" ||
    nok "FRS_DATA: frs-sample's default matrix"
FRS_DATA=$T/alt LD_LIBRARY_PATH="$Q/lib" "$T/p_dyn" "$T/map.exr" >"$T/p.txt" 2>"$T/err"
cmp -s "$T/p.txt" "$T/alt.txt" && ok "FRS_DATA: frs_default_matrix (libfrs.so)" ||
    nok "FRS_DATA: frs_default_matrix (libfrs.so)"
FRS_DATA=$T/alt "$T/p_st" "$T/map.exr" >"$T/p.txt" 2>"$T/err"
cmp -s "$T/p.txt" "$T/alt.txt" && ok "FRS_DATA: frs_default_matrix (libfrs.a)" ||
    nok "FRS_DATA: frs_default_matrix (libfrs.a)"
expect_fail "FRS_DATA without the matrix: named" 1 \
    "no default matrix (looked for $T/default.frd; FRS_DATA is set)" "$T/o.pts" \
    env FRS_DATA="$T" "$Q/bin/frs-sample" -n 10 -o "$T/o.pts"

# Nothing anywhere: every place looked at is named.
"$Q/bin/ref-sample" -q -k random -n 16 -o "$T/r.pts"
mv "$Q/share/frs" "$T/frs-gone"
expect_fail "no data: frs-sample names every place" 1 \
    "no default matrix (looked for $Q/share/frs/default.frd and $P/share/frs/default.frd); give -m MATRIX" \
    "$T/o.pts" "$Q/bin/frs-sample" -n 10 -o "$T/o.pts"
expect_fail "no data: frs-sample --data-dir" 1 \
    "--data-dir: no shipped data (looked for $Q/share/frs/default.frd and $P/share/frs/default.frd)" \
    - "$Q/bin/frs-sample" --data-dir
expect_fail "no data: mc-error -f env names every place" 1 \
    "env: no default environment map (looked for $Q/share/frs/sunset.exr and $P/share/frs/sunset.exr)" \
    - "$Q/bin/mc-error" -f env "$T/r.pts"
"$T/p_st" "$T/map.exr" >/dev/null 2>"$T/err"
[ $? -eq 1 ] && grep -qF "FRS_E_IO" "$T/err" &&
    grep -qF "no default matrix (looked for $(dirname "$R")/share/frs/default.frd and $P/share/frs/default.frd)" "$T/err" &&
    ok "no data: frs_default_matrix is FRS_E_IO, naming the places" || {
	nok "no data: frs_default_matrix is FRS_E_IO, naming the places"
	sed 's/^/# /' "$T/err" | head -n 5
}
done_testing
