#!/bin/sh
# make install into a staging directory (DESTDIR, PREFIX=/usr), then the
# library as a user has it: test/api_example.c built with pkg-config,
# against libfrs.so and against libfrs.a, prints frs-sample's points;
# the .so exports the API of src/lib/frs.h and nothing else; make
# uninstall takes everything away again.
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
	    PREFIX=/usr DESTDIR="$D" "$@"
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
for f in include/frs.h lib/libfrs.a lib/libfrs.so.1.2.0 \
    lib/pkgconfig/frs.pc share/frs/default.frd share/frs/default3.frd \
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
[ "$(readlink "$U/lib/libfrs.so.1")" = libfrs.so.1.2.0 ] &&
    [ "$(readlink "$U/lib/libfrs.so")" = libfrs.so.1.2.0 ] &&
    ok "libfrs.so and libfrs.so.1 link to libfrs.so.1.2.0" ||
    nok "libfrs.so and libfrs.so.1 link to libfrs.so.1.2.0"
readelf -d "$U/lib/libfrs.so.1.2.0" | grep -q 'SONAME.*\[libfrs\.so\.1\]' &&
    ok "soname libfrs.so.1" || nok "soname libfrs.so.1"

# The exported functions are those the header declares, no more.
grep -o 'frs_[a-z0-9_]*(' "$TOP/src/lib/frs.h" | tr -d '(' | sort -u \
    >"$T/api.txt"
nm -D --defined-only "$U/lib/libfrs.so.1.2.0" |
    awk '$2 != "A" { sub(/@.*/, "", $3); print $3 }' | sort -u >"$T/exported.txt"
if cmp -s "$T/api.txt" "$T/exported.txt"; then
	ok "libfrs.so exports the $(wc -l <"$T/api.txt") functions of frs.h"
else
	nok "libfrs.so exports the functions of frs.h"
	diff "$T/api.txt" "$T/exported.txt" | head -n 20 | sed 's/^/# /'
fi
nm -D --defined-only "$U/lib/libfrs.so.1.2.0" | grep -qw -e imap_load -e frs_fail &&
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
# awk reads the values back exactly and prints them as the example does.
"$U/bin/frs-sample" -q -m "$M" -i "$T/map.exr" -n 5000 -S 7 -T |
    awk '!/^#/ { printf "%.17g %.17g\n", $1, $2 }' >"$T/ref.txt"
[ "$(wc -l <"$T/ref.txt")" -gt 4000 ] && ok "frs-sample: $(wc -l <"$T/ref.txt") points" ||
    nok "frs-sample: $(wc -l <"$T/ref.txt") points"
WARN="-std=c11 -Wall -Wextra -Wconversion -Werror"

# Dynamic: libfrs.so.1 from the staging directory.
if cc $WARN -o "$T/ex_dyn" "$TOP/test/api_example.c" $CFLAGS_FRS $LIBS_FRS \
    2>"$T/err"; then
	ok "api_example.c built against libfrs.so"
	readelf -d "$T/ex_dyn" | grep -q 'NEEDED.*\[libfrs\.so\.1\]' &&
	    ok "it needs libfrs.so.1" || nok "it needs libfrs.so.1"
	LD_LIBRARY_PATH="$U/lib" "$T/ex_dyn" "$T/map.exr" "$M" 5000 7 \
	    >"$T/dyn.txt" 2>"$T/err"
	cmp -s "$T/dyn.txt" "$T/ref.txt" && ok "dynamic: frs-sample's points" || {
		nok "dynamic: frs-sample's points"
		sed 's/^/# /' "$T/err" | head -n 5
		diff "$T/dyn.txt" "$T/ref.txt" | head -n 5 | sed 's/^/# /'
	}
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
	"$T/ex_st" "$T/map.exr" "$M" 5000 7 >"$T/st.txt" 2>"$T/err"
	cmp -s "$T/st.txt" "$T/ref.txt" && ok "static: frs-sample's points" || {
		nok "static: frs-sample's points"
		sed 's/^/# /' "$T/err" | head -n 5
	}
else
	nok "api_example.c built against libfrs.a: $ST"
	sed 's/^/# /' "$T/err" | head -n 10
fi
"$T/ex_st" "$T/nonexistent.exr" "$M" 10 1 >/dev/null 2>"$T/err"
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
