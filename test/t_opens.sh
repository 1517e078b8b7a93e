#!/bin/sh
# One path from a file to its use: frs-sample opens its matrix file once
# (its kind, dimensions, values and permutation check in one read), for
# a .frd, a .frp, the shipped default and a 3-D matrix; and its map or
# volume once, whether a matrix named says which it is or the file's
# first bytes do (and so which default matrix to take); imap(1) its
# source once, whose first bytes say whether it is a volume.  Counted with
# strace (LeakSanitizer, itself a tracer, off under it); skipped where
# strace is missing or cannot trace.
. "$(dirname "$0")/lib.sh"

command -v strace >/dev/null 2>&1 || skip_all "no strace"
strace -f -e trace=openat -o "$T/probe" true 2>/dev/null ||
    skip_all "strace cannot trace here"

frd-prep -a all -o "$T/m.frp" "$TD/default.frd" 2>/dev/null
cp "$TD/default3.frd" "$T/m3.frd"
cp "$TD/default.frd" "$T/m.frd"
cp "$TD/sunset.exr" "$T/map.exr"
imap gen -s 8 -o "$T/v.frv" blob3 2>/dev/null
# A small matrix whose runs below take its sorted lists from the .frp
# (half the values or more pass), which is not opened again for them.
frd-gen -s 64 -S 1 -o "$T/s.frd" 2>/dev/null
frd-prep -a all -o "$T/s.frp" "$T/s.frd" 2>/dev/null
mkdir "$T/t"
cp "$T/s.frd" "$T/s.frp" "$T/t/"

# opens WHAT FILE WANT ARGS...: frs-sample ARGS opens FILE WANT times.
opens() {
	what=$1 file=$2 want=$3
	shift 3
	if ! nolsan strace -f -e trace=open,openat -o "$T/trace" frs-sample -q \
	    -n 1000 -o /dev/null "$@" 2>"$T/err"; then
		nok "$what: frs-sample failed: $(head -n 1 "$T/err")"
		return
	fi
	got=$(grep -c "\"$file\"" "$T/trace")
	if [ "$got" -eq "$want" ]; then
		ok "$what: $file opened $want time(s)"
	else
		nok "$what: $file opened $got times, not $want"
	fi
}

opens ".frd" "$TD/default.frd" 1 -m "$TD/default.frd" -i blob
opens ".frd with its twin .frp" "$T/m.frd" 1 -m "$T/m.frd" -i blob
opens "the twin .frp of a .frd" "$T/m.frp" 1 -m "$T/m.frd" -i blob
opens ".frp" "$T/m.frp" 1 -m "$T/m.frp" -i blob
opens "3-D .frd" "$T/m3.frd" 1 -m "$T/m3.frd" -i blob3
opens ".frp, its sorted lists too" "$T/s.frp" 1 -m "$T/s.frp" -i const \
    --tiles plain --sigma 1 -n 10000
opens "a twin .frp, its sorted lists too" "$T/t/s.frp" 1 -m "$T/t/s.frd" \
    -i const --tiles plain --sigma 1 -n 10000
opens "-a naive" "$TD/default.frd" 1 -m "$TD/default.frd" -i blob -a naive
FRS_MATRIX=$T/m.frd
export FRS_MATRIX
opens "the default matrix (FRS_MATRIX)" "$T/m.frd" 1 -i blob
unset FRS_MATRIX
# The shipped one, wherever the data directory lies.
dir=$(frs-sample --data-dir)
opens "the shipped default matrix" "$dir/default.frd" 1 -i blob
opens "a map, the matrix named" "$T/map.exr" 1 -m "$TD/default.frd" \
    -i "$T/map.exr"
opens "a map, no matrix named" "$T/map.exr" 1 -i "$T/map.exr" --equirect
opens "a volume, the 3-D matrix named" "$T/v.frv" 1 -m "$TD/default3.frd" \
    -i "$T/v.frv"
opens "a volume, no matrix named" "$T/v.frv" 1 -i "$T/v.frv"

# imap_opens WHAT FILE ARGS...: imap ARGS opens FILE once (3c04e07's
# opened a map twice and a volume three times: to tell whether it is a
# volume, then to read it).
imap_opens() {
	what=$1 file=$2
	shift 2
	if ! nolsan strace -f -e trace=open,openat -o "$T/trace" imap "$@" \
	    >/dev/null 2>"$T/err"; then
		nok "imap $what: failed: $(head -n 1 "$T/err")"
		return
	fi
	got=$(grep -c "\"$file\"" "$T/trace")
	[ "$got" -eq 1 ] && ok "imap $what: $file opened once" ||
	    nok "imap $what: $file opened $got times, not once"
}
imap_opens "info of a map" "$T/map.exr" info "$T/map.exr"
imap_opens "info of a volume" "$T/v.frv" info "$T/v.frv"
imap_opens "info -s of a volume" "$T/v.frv" info -s 8 "$T/v.frv"
imap_opens "convert" "$T/map.exr" convert -s 16 "$T/map.exr" "$T/o.png"
done_testing
