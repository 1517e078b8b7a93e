#!/bin/sh
# frs-sample --tiles: shuffled tiles give the same points from every
# implementation and device, in 2-D (square and not), in 3-D and when a
# pixel holds several tiles; they break the repetition that plain tiling
# shows (the measure of test/ref/ref_tiles.c, which must fire on planted
# periodic and mirrored sets); the counts still follow the map.
. "$(dirname "$0")/lib.sh"
REF=$BIN/../test/ref_tiles

frd-gen -s 64 --tol 1e-2 -o "$T/m.frd"
frd-gen -s 64x32 --tol 1e-2 -o "$T/r.frd"
frd-gen -s 16 --tol 1e-2 -o "$T/s.frd"

# every implementation and OpenCL: sorted output of each against sorted
same_all() {	# what, the OpenCL implementations, then the frs-sample options
	what=$1
	cls=$2
	shift 2
	frs-sample -q "$@" -T | grep -v '^#' | sort >"$T/ref.s"
	good=1
	for a in naive stack level1 level2; do
		frs-sample -q "$@" -a $a -T | grep -v '^#' | sort >"$T/x.s"
		cmp -s "$T/x.s" "$T/ref.s" || good=0
	done
	for a in $cls; do
		frs-sample -q "$@" -a "$(echo $a | sed s/flat1/stack/)" -T -o "$T/cpu.txt"
		cl_run frs-sample -q "$@" -a $a --device cl -T -o "$T/cl.txt" &&
		    cmp -s "$T/cpu.txt" "$T/cl.txt" || good=0
	done
	[ "$(wc -l <"$T/ref.s")" -gt 100 ] || good=0
	[ $good = 1 ] && ok "$what: every implementation and device agree" ||
	    nok "$what: every implementation and device agree"
}
same_all "sky, 64^2, shuffled" "naive stack level2 sorted flat1" -m "$T/m.frd" -i sky -n 2000 --tiles shuffled
same_all "64x32, shuffled" "sorted" -m "$T/r.frd" -i blob -s 64x32 -n 1500 --tiles shuffled
same_all "16^2, n_s above the matrix" "sorted flat1" -m "$T/s.frd" -i sky -s 32 -n 4000 --tiles shuffled
frs-sample -q -m "$T/s.frd" -i sky -s 32 -n 4000 --tiles shuffled -v -o /dev/null 2>"$T/v.txt"
awk '/n_s/ { for (i = 1; i < NF; i++) if ($i == "n_s") ns = $(i + 1) + 0 }
    END { exit !(ns > 16) }' "$T/v.txt" && ok "16^2: n_s exceeds the matrix" ||
    nok "16^2: n_s exceeds the matrix ($(grep n_s "$T/v.txt"))"

# progressive steps and the thesis rule through the shuffled tiles
for opts in "--progressive 300,900,2000" "--threshold thesis --jitter random"; do
	# shellcheck disable=SC2086
	frs-sample -q -m "$T/m.frd" -i sky -n 2000 --tiles shuffled -a stack $opts -o "$T/a.pts" &&
	    frs-sample -q -m "$T/m.frd" -i sky -n 2000 --tiles shuffled -a sorted $opts -T |
	    grep -v '^#' | sort >"$T/b.s" &&
	    cl_run frs-sample -q -m "$T/m.frd" -i sky -n 2000 --tiles shuffled -a sorted $opts --device cl -o "$T/c.pts" &&
	    frs-sample -q -m "$T/m.frd" -i sky -n 2000 --tiles shuffled -a sorted $opts -o "$T/d.pts" &&
	    cmp -s "$T/c.pts" "$T/d.pts" && ok "shuffled $opts: CPU and OpenCL" ||
	    nok "shuffled $opts: CPU and OpenCL"
done

# 3-D: naive and sorted agree with shuffled tiles (48 symmetries)
frd-gen -k 3 -s 8 --tol 1e-2 -o "$T/m3.frd"
frs-sample -q -m "$T/m3.frd" -i blob3 -s 16 -n 3000 --tiles shuffled -a naive -T | grep -v '^#' | sort >"$T/n3.s"
frs-sample -q -m "$T/m3.frd" -i blob3 -s 16 -n 3000 --tiles shuffled -T | grep -v '^#' | sort >"$T/s3.s"
frs-sample -q -m "$T/m3.frd" -i blob3 -s 16 -n 3000 --tiles plain -T | grep -v '^#' | sort >"$T/p3.s"
cmp -s "$T/n3.s" "$T/s3.s" && ! cmp -s "$T/s3.s" "$T/p3.s" &&
    ok "3-D shuffled: naive and sorted agree, and differ from plain" ||
    nok "3-D shuffled: naive and sorted agree, and differ from plain"

# The repetition measure fires on planted sets: a 4 x 4 tiling of one
# random set of 60 points (periodic), and the same with every other copy
# mirrored (a repetition up to a symmetry).
awk 'BEGIN { srand(7); for (i = 0; i < 60; i++) { x[i] = int(rand() * 64); y[i] = int(rand() * 64) }
    for (ty = 0; ty < 4; ty++) for (tx = 0; tx < 4; tx++) for (i = 0; i < 60; i++)
        printf "%.9f %.9f\n", (tx * 64 + x[i] + 0.5) / 256, (ty * 64 + y[i] + 0.5) / 256 }' >"$T/per.txt"
awk 'BEGIN { srand(7); for (i = 0; i < 60; i++) { x[i] = int(rand() * 64); y[i] = int(rand() * 64) }
    for (ty = 0; ty < 4; ty++) for (tx = 0; tx < 4; tx++) for (i = 0; i < 60; i++) {
        u = (tx + ty) % 2 ? 63 - x[i] : x[i]
        printf "%.9f %.9f\n", (tx * 64 + u + 0.5) / 256, (ty * 64 + y[i] + 0.5) / 256 } }' >"$T/mir.txt"
awk 'BEGIN { srand(7); for (i = 0; i < 960; i++) printf "%.9f %.9f\n", rand(), rand() }' >"$T/rnd.txt"
# (random points on a finer grid, where equal neighbourhoods are chance)
share() { "$REF" repeat "$1" "$2" "$3" | awk '{ print $6 }'; }
p=$(share 256 256 "$T/per.txt")
m=$(share 256 256 "$T/mir.txt")
r=$(share 4096 4096 "$T/rnd.txt")
awk -v p="$p" -v m="$m" -v r="$r" 'BEGIN { exit !(p > 0.9 && m > 0.9 && r < 0.02) }' &&
    ok "repetition measure: periodic $p, mirrored $m, random $r" ||
    nok "repetition measure: periodic $p, mirrored $m, random $r"

# Our output: plain tiling of a 64^2 matrix over a sky window repeats;
# shuffled does far less (seed fixed); a window inside the matrix has
# nothing to repeat.
win() { frs-sample -q -v -o /dev/null "$@" 2>&1 | sed -n 's/.*window \([0-9]*\)x\([0-9]*\).*/\1 \2/p'; }
for t in plain shuffled; do
	frs-sample -q -m "$T/m.frd" -i sky -n 400 --tiles $t -o "$T/$t.pts"
done
# shellcheck disable=SC2046
pp=$(share $(win -m "$T/m.frd" -i sky -n 400) "$T/plain.pts")
# shellcheck disable=SC2046
ps=$(share $(win -m "$T/m.frd" -i sky -n 400) "$T/shuffled.pts")
awk -v p="$pp" -v s="$ps" 'BEGIN { exit !(p > 0.3 && s < p / 2) }' &&
    ok "sky, n 400: repeated share plain $pp, shuffled $ps" ||
    nok "sky, n 400: repeated share plain $pp, shuffled $ps"

# The counts follow the map through shuffled tiles: blocks of sky
# against n I / sum I (chi-square, p above 1e-4).
frs-sample -q -m "$T/m.frd" -i sky -n 20000 --sigma 2 --tiles shuffled -o "$T/chi.pts"
pv=$("$REF" chi2 8 8 sky "$T/chi.pts" | awk '{ print $8 }')
awk -v p="$pv" 'BEGIN { exit !(p > 1e-4) }' && ok "sky, shuffled: block chi-square p $pv" ||
    nok "sky, shuffled: block chi-square p $pv"

# -v tells the tiles and the reuse; auto picks; bad names fail
frs-sample -m "$T/m.frd" -i sky -n 400 --sigma 2 --tiles auto -v -o /dev/null 2>"$T/v.txt"
grep -q 'tiles ([0-9]*x[0-9]*), shuffled; .* % of the samples show a matrix element' "$T/v.txt" &&
    ok "-v: tiles, shuffled by auto, reuse share" || nok "-v: tiles, shuffled by auto, reuse share"
frs-sample -m "$T/m.frd" -n 4000 --tiles auto -v -o /dev/null 2>"$T/v.txt"
grep -q 'tiles ([0-9]*x[0-9]*), plain' "$T/v.txt" && ok "auto: plain past S_M^2/sigma^2" ||
    nok "auto: plain past S_M^2/sigma^2"
frs-sample -m "$T/m.frd" -i sky -n 400 --sigma 2 --tiles plain -o /dev/null 2>"$T/w.txt"
grep -q 'plain tiles: the window' "$T/w.txt" && ok "--tiles plain warns of the lattice" ||
    nok "--tiles plain warns of the lattice"
frs-sample -q -m "$T/m.frd" -i sky -n 400 --sigma 2 --tiles plain -o /dev/null 2>"$T/w.txt"
[ ! -s "$T/w.txt" ] && ok "-q silences it" || nok "-q silences it"
expect_fail "--tiles bogus" 2 "--tiles" "$T/o.pts" frs-sample -m "$T/m.frd" -n 10 --tiles bogus -o "$T/o.pts"
frs-sample -m "$T/m.frd" -i sky -n 400 --sigma 2 -v -o /dev/null 2>"$T/v.txt"
grep -q 'tiles ([0-9]*x[0-9]*), plain' "$T/v.txt" && ok "plain by default" || nok "plain by default"
done_testing
