#!/bin/sh
# The memory ceiling FRS_MAX_MEM: every program refuses a request above it
# before allocating, naming the request and the figure it needs, with exit
# status 1 and no output left behind.
. "$(dirname "$0")/lib.sh"

imap gen blob -s 600x600 -o "$T/blob.png" 2>/dev/null
ref-sample -n 30000 -T -o "$T/p.txt" 2>/dev/null

# limit WHAT MAXMEM PATTERN OUTFILE CMD...
limit() {
	what=$1 max=$2 pattern=$3 out=$4
	shift 4
	expect_fail "$what" 1 "$pattern" "$out" env FRS_MAX_MEM="$max" "$@"
}

limit "frd-gen -s: the generator's need" 1G \
    "-s 20000x20000x1: needs" "$T/a.frd" frd-gen -s 20000 -o "$T/a.frd"
limit "frd-gen: the figure is in GiB" 1G "GiB, above the memory limit of 1.0 GiB" \
    "$T/a.frd" frd-gen -s 20000 -o "$T/a.frd"
limit "frs-sample -n: the samples' need" 100M \
    "-n 100000000 (--count-only counts them): needs 1.2 GiB" "$T/a.pts" \
    frs-sample -n 100000000 -o "$T/a.pts"
limit "frs-sample: the default matrix" 8M "2048x2048 matrix: needs 16.0 MiB" \
    "$T/a.pts" frs-sample -n 100 -o "$T/a.pts"
limit "hsw-sample -n, --input dart" 10M "-n 1000000: needs 15.3 MiB" "$T/a.pts" \
    hsw-sample -i blob -n 1000000 --input dart -o "$T/a.pts"
# A generated set is made and written chunk by chunk: its memory does
# not grow with n.
if env FRS_MAX_MEM=10M hsw-sample -i blob -n 1000000 -o "$T/h.pts" 2>"$T/err"; then
	ok "hsw-sample -n 1000000 (Halton) within 10M"
else
	nok "hsw-sample -n 1000000 (Halton) within 10M: $(head -n 1 "$T/err")"
fi
rm -f "$T/h.pts"
limit "ref-sample -n" 10M "1000000 points: needs 15.3 MiB" "$T/a.pts" \
    ref-sample -n 1000000 -o "$T/a.pts"
limit "imap gen -s" 1M "2000x2000 map: needs 30.5 MiB" "$T/a.png" \
    imap gen blob -s 2000x2000 -o "$T/a.png"
limit "imap info on a PNG too large for the ceiling" 1M \
    "blob.png: 600x600 map: needs 2.7 MiB" - imap info "$T/blob.png"
limit "an EXR too large for the ceiling" 64k "needs" - \
    imap info "$TD/sunset.exr"
limit "EXR on standard input, buffered whole" 64k "<stdin>: needs" - \
    sh -c "imap info - <'$TD/sunset.exr'"
limit "pts-render -s" 1M "raster: needs 15.3 MiB" "$T/a.png" \
    pts-render -s 4000 "$T/p.txt" -o "$T/a.png"
limit "discrepancy: text points grow past the ceiling" 256k "p.txt: needs" - \
    discrepancy "$T/p.txt"
limit "dda --size" 1M "spectrum image: needs" "$T/a.tsv" \
    dda --size 1000 "$T/p.txt" -o "$T/a.tsv"
limit "a value that is not a size" lots "FRS_MAX_MEM=lots: not a size" \
    "$T/a.pts" ref-sample -n 10 -o "$T/a.pts"

# A .frd header claiming 65536x65536 on a pipe (no file length to check
# it against): refused before 16 GiB are asked for.
printf '\211FRD\r\n\032\n\001\000\000\000\002\000\000\000\000\000\001\000\000\000\001\000\001\000\000\000\000\000\000\000' \
    >"$T/big.hdr"
limit "a .frd header's size on a pipe" 1G "65536x65536 matrix: needs 16.0 GiB" \
    "$T/a.frp" sh -c "cat '$T/big.hdr' | frd-prep - -o '$T/a.frp'"

# Under the ceiling the same runs work: the check is not a blanket refusal.
if env FRS_MAX_MEM=64M frs-sample -n 1000 -o "$T/ok.pts" 2>"$T/err" &&
    env FRS_MAX_MEM=4M imap info "$T/blob.png" >/dev/null 2>&1; then
	ok "runs within the ceiling"
else
	nok "runs within the ceiling"
	sed 's/^/# /' "$T/err"
fi
done_testing
