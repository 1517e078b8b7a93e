#!/bin/sh
# The library's layout (README, Layout): a folder of src/lib includes
# headers only from itself and the folders before it, base, maps,
# formats, sample, api (test/layers.sh); only api includes the public
# frs.h (and maps/imap.h and formats/frdio.h, for the public map and
# matrix types, and base/rng.h, for the public random numbers); nothing
# in src/lib
# includes the programs' src/cli; every include names its folder; no two
# headers include each other, directly or through others; and no two
# modules (a .c and its .h) depend on each other that way.  The
# programs, one folder each, include frs.h, cli/cli.h, their own headers
# and a listed set of the library's; the headers of their shared src/cli
# include only frs.h and src/cli's own.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/layers.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)

# "FILE TARGET" for every quoted include of src/lib.
(cd "$TOP" && grep -Ho '#include "[^"]*"' src/lib/*/*.[ch] src/lib/*/*.cc) |
    sed 's/:#include "\(.*\)"$/ \1/' >"$T/inc"
[ -s "$T/inc" ] && ok "the library's includes are listed" ||
    nok "the library's includes are listed"

: >"$T/bad"
while read -r file target; do
	from=${file#src/lib/}
	from=${from%%/*}
	case $target in
	# The public types (struct frs_imap, struct frs_matrix) and the
	# public random numbers (API 2.2: frs_rand64, struct frs_rng and
	# the rest, defined in base/rng.c): the headers of their stages
	# take their declarations from frs.h, where they are written once;
	# no other file below api includes it (no module below api calls
	# into it either: the call graph below has no cycle).
	frs.h) [ "$from" = api ] || [ "$file" = src/lib/maps/imap.h ] ||
	    [ "$file" = src/lib/formats/frdio.h ] ||
	    [ "$file" = src/lib/base/rng.h ] ||
	    echo "$file: frs.h outside api" ;;
	cli/*) echo "$file: includes the programs' $target" ;;
	paths.h | ../../../cl/*.cl) ;;	# generated; the kernels' source
	*/*)
		to=${target%%/*}
		[ -f "$TOP/src/lib/$target" ] ||
		    echo "$file: $target is not in src/lib"
		if [ "$to" != "$from" ] &&
		    [ "$(layer_rank "$to")" -ge "$(layer_rank "$from")" ]; then
			echo "$file: $from includes $target"
		fi ;;
	*) echo "$file: \"$target\" names no folder" ;;
	esac
done <"$T/inc" >"$T/bad"
[ ! -s "$T/bad" ] && ok "every include goes to the folder's own or an earlier stage" || {
	nok "every include goes to the folder's own or an earlier stage"
	sed 's/^/# /' "$T/bad"
}

# Cycles among the headers: follow each header's includes (tsort says
# when the graph has one).
grep '\.h ' "$T/inc" | while read -r file target; do
	case $target in */*) echo "${file#src/lib/} $target" ;; esac
done >"$T/edges"
if tsort "$T/edges" >/dev/null 2>"$T/cycle"; then
	ok "no include cycle among the headers"
else
	nok "no include cycle among the headers"
	sed 's/^/# /' "$T/cycle" | head -n 10
fi

# Cycles among the modules (maps/imap for imap.c and imap.h): A depends
# on B when A.c or A.h includes B.h.  A cycle marks a file with two jobs
# (a type and the loader that calls back into it).
while read -r file target; do
	case $target in
	../*) ;;
	*/*)
		from=${file#src/lib/}
		from=${from%.*}
		to=${target%.h}
		[ "$from" = "$to" ] || echo "$from $to" ;;
	esac
done <"$T/inc" >"$T/modules"
if tsort "$T/modules" >/dev/null 2>"$T/cycle"; then
	ok "no dependency cycle among the modules"
else
	nok "no dependency cycle among the modules"
	sed 's/^/# /' "$T/cycle" | head -n 10
fi

# Calls: A calls B when A.o leaves undefined a symbol that B.o defines
# (nm, on the build's own objects).  Includes can be in order while the
# calls go round (draw.c calling lev.c calling back into draw.c): a
# cycle of calls is a module that cannot be read or tested before
# another that needs it.
OBJ=$BIN/../lib
# The objects of the library's sources: a build directory keeps those of
# modules that have moved out until `make clean`.
objs() {
	(cd "$OBJ" && for o in */*.o; do
		s=$TOP/src/lib/${o%.o}
		if [ -f "$s.c" ] || [ -f "$s.cc" ]; then echo "$o"; fi
	done)
}
if [ -d "$OBJ/api" ] && command -v nm >/dev/null 2>&1; then
	(cd "$OBJ" && for o in $(objs); do
		nm -g --defined-only "$o" | awk -v m="${o%.o}" \
		    '$2 ~ /^[TDBR]$/ { print $3, m }'
	done) | sort -u >"$T/defs"
	(cd "$OBJ" && for o in $(objs); do
		nm -u "$o" | awk -v m="${o%.o}" '{ print $2, m }'
	done) | sort >"$T/uses"
	join "$T/uses" "$T/defs" | awk '$2 != $3 { print $2, $3 }' |
	    sort -u >"$T/calls"
	if [ -s "$T/calls" ] && tsort "$T/calls" >/dev/null 2>"$T/cycle"; then
		ok "no call cycle among the modules ($(wc -l <"$T/calls") calls between modules)"
	else
		nok "no call cycle among the modules"
		sed 's/^/# /' "$T/cycle" | head -n 10
	fi
else
	ok "# SKIP no objects in $OBJ or no nm: the call graph is not checked"
fi

# The programs (README, Layout): a program's files lie in its folder
# src/P/ (its main P.c and the work only it does) and include frs.h, the
# programs' one shared header cli/cli.h, the headers of their own folder
# and the library headers listed here for it, a list that only shrinks:
# a header a program no longer includes must be struck from it; of
# src/cli they include cli/cli.h alone.  src/cli includes no program's
# folder.
libheaders() {
	case $1 in
	dda) echo ;;
	discrepancy) echo ;;
	frd-gen) echo ;;
	frd-prep) echo ;;
	frs-sample) echo ;;
	hsw-sample) echo ;;
	imap) echo ;;
	mc-error) echo ;;
	pts-render) echo ;;
	ref-sample) echo ;;
	esac
}
progs="dda discrepancy frd-gen frd-prep frs-sample hsw-sample imap mc-error
    pts-render ref-sample"
: >"$T/bad"
total=0
for p in $progs; do
	if [ ! -f "$TOP/src/$p/$p.c" ]; then
		echo "src/$p/$p.c: no main in the program's folder"
		continue
	fi
	allowed=$(libheaders "$p")
	(cd "$TOP" && grep -Ho '#include "[^"]*"' src/"$p"/*.[ch]) |
	    sed 's/:#include "\(.*\)"$/ \1/' >"$T/pinc"
	while read -r file target; do
		case $target in
		frs.h | cli/cli.h | ../../cl/*.cl) ;;
		cli/*) echo "$file: $target: of src/cli a program includes cli/cli.h alone" ;;
		"$p"/*) [ -f "$TOP/src/$target" ] ||
		    echo "$file: $target is not in src/$p" ;;
		*) case " $allowed " in
		    *" $target "*) ;;
		    *) echo "$file: $target, a library header not listed for $p" ;;
		    esac ;;
		esac
	done <"$T/pinc"
	for h in $allowed; do
		awk '{ print $2 }' "$T/pinc" | grep -qx "$h" ||
		    echo "$p: no longer includes $h: strike it from the list"
	done
	total=$((total + $(echo $allowed | wc -w)))
done >"$T/bad"
(cd "$TOP" && grep -Ho '#include "[^"]*"' src/cli/*.[ch]) |
    sed 's/:#include "\(.*\)"$/ \1/' | while read -r file target; do
	case $target in
	frs.h) ;;
	cli/*) [ -f "$TOP/src/$target" ] ||
	    echo "$file: $target is not in src/cli" ;;
	*) [ -f "$TOP/src/lib/$target" ] ||
	    echo "$file: $target is not the library's" ;;
	esac
done >>"$T/bad"
what="the programs include frs.h, cli/cli.h, their own headers and"
what="$what their listed library headers"
[ ! -s "$T/bad" ] && ok "$what ($total in all)" || {
	nok "$what"
	sed 's/^/# /' "$T/bad"
}

# What cli/cli.h brings a program is src/cli's own and frs.h: a header
# of src/cli that included one of the library's would hand it to every
# program, unlisted.  The library's headers stay in src/cli's .c files,
# but for two that cli.h itself hands on, each the one definition for
# the library and the programs, which a copy in src/cli would duplicate
# and forwarders would only rename: base/num.h, the arithmetic kit
# (header-only inlines and pure functions, no state), and base/ocl.h,
# the OpenCL plumbing of the library's device code and the programs'
# (cli.h says more).
(cd "$TOP" && grep -Ho '#include "[^"]*"' src/cli/*.h) |
    sed 's/:#include "\(.*\)"$/ \1/' | while read -r file target; do
	case $file:$target in
	*:frs.h | *:cli/*) ;;
	src/cli/cli.h:base/num.h | src/cli/cli.h:base/ocl.h) ;;
	*) echo "$file: includes $target" ;;
	esac
done >"$T/bad"
what="the headers of src/cli include only frs.h and src/cli's own"
what="$what (and cli.h base/num.h and base/ocl.h)"
[ ! -s "$T/bad" ] && ok "$what" || {
	nok "$what"
	sed 's/^/# /' "$T/bad"
}

done_testing
