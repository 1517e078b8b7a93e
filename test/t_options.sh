#!/bin/sh
# Every program's options, against its usage text and its manual: each
# option a program takes (its options string, read through cli.h's
# CLI_OPTIONS) is in its -h text and is an item of its manual's option
# list, with its short letter where it has one; and every long option the
# manual lists as an item is one the program takes.
. "$(dirname "$0")/lib.sh"
TOP=$(cd "$(dirname "$0")/.." && pwd)

progs="dda discrepancy frd-gen frd-prep frs-sample hsw-sample imap mc-error
    pts-render ref-sample"
common="help version output text seed threads quiet progress"

# The words of a program's options string: "name" or "x=name".
option_words() {
	awk '/^static const char options\[\] =/ { on = 1; next }
	    on { s = s $0; if ($0 ~ /;[ \t]*$/) exit }
	    END { gsub(/"[ \t]*"/, "", s); gsub(/[";]/, "", s); print s }' \
	    "$TOP/src/$1/$1.c"
}

for p in $progs; do
	words=$(option_words "$p")
	[ -n "$words" ] || { nok "$p: no options string in src/$p/$p.c"; continue; }
	"$BIN/$p" -h >"$T/usage" 2>&1
	man=$TOP/man/man1/$p.1
	# The manual's items: ".It Fl x , Fl -name Ar ..." and the like.
	grep '^\.It ' "$man" | tr ',|' '\n\n' |
	    sed -n 's/.*Fl -\([a-z0-9][a-z0-9-]*\).*/\1/p' | sort -u >"$T/items"
	grep '^\.It ' "$man" >"$T/itlines"
	bad=""
	for w in $words; do
		name=${w#?=}
		grep -qe "--$name\\b" "$T/usage" || bad="$bad --$name not in -h;"
		grep -qx "$name" "$T/items" || bad="$bad --$name not an item of $p.1;"
		case $w in
		?=*)
			l=${w%%=*}
			grep -q "Fl $l\\b.*Fl -$name\\b" "$T/itlines" ||
			    bad="$bad -$l, --$name not one item of $p.1;"
			;;
		esac
	done
	for name in $(cat "$T/items"); do
		case " $common $(echo $words | sed 's/[^ ]=//g') " in
		*" $name "*) ;;
		*) bad="$bad $p.1 lists --$name, which $p does not take;" ;;
		esac
	done
	[ -z "$bad" ] && ok "$p: options, -h and $p.1 agree" ||
	    nok "$p:$bad"
done
done_testing
