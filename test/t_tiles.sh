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
win() { frs-sample -q -v -o /dev/null "$@" 2>&1 | sed -n 's/.*n_s .*window \([0-9]*\)x\([0-9]*\).*/\1 \2/p'; }
for t in plain shuffled; do
	frs-sample -q -m "$T/m.frd" -i sky -n 400 --tiles $t -o "$T/$t.pts"
done
# shellcheck disable=SC2046
pp=$(share $(win -m "$T/m.frd" -i sky -n 400 --tiles plain) "$T/plain.pts")
# shellcheck disable=SC2046
ps=$(share $(win -m "$T/m.frd" -i sky -n 400 --tiles plain) "$T/shuffled.pts")
awk -v p="$pp" -v s="$ps" 'BEGIN { exit !(p > 0.3 && s < p / 2) }' &&
    ok "sky, n 400: repeated share plain $pp, shuffled $ps" ||
    nok "sky, n 400: repeated share plain $pp, shuffled $ps"

# The counts follow the map through shuffled tiles: blocks of sky
# against n I / sum I (chi-square, p above 1e-4).
frs-sample -q -m "$T/m.frd" -i sky -n 20000 --sigma 2 --tiles shuffled -o "$T/chi.pts"
pv=$("$REF" chi2 8 8 sky "$T/chi.pts" | awk '{ print $8 }')
awk -v p="$pv" 'BEGIN { exit !(p > 1e-4) }' && ok "sky, shuffled: block chi-square p $pv" ||
    nok "sky, shuffled: block chi-square p $pv"

# -v tells the tiles and the reuse; bad names fail
frs-sample -m "$T/m.frd" -i sky -n 400 --sigma 2 --tiles shuffled -v -o /dev/null 2>"$T/v.txt"
grep -q 'tiles ([0-9]*x[0-9]*), shuffled; .* % of the samples show a matrix element' "$T/v.txt" &&
    ok "-v: tiles, shuffled, reuse share" || nok "-v: tiles, shuffled, reuse share"
frs-sample -m "$T/m.frd" -i sky -n 400 --sigma 2 --tiles plain -o /dev/null 2>"$T/w.txt"
grep -q 'plain tiles: the window' "$T/w.txt" && ok "--tiles plain warns of the lattice" ||
    nok "--tiles plain warns of the lattice"
frs-sample -q -m "$T/m.frd" -i sky -n 400 --sigma 2 --tiles plain -o /dev/null 2>"$T/w.txt"
[ ! -s "$T/w.txt" ] && ok "-q silences it" || nok "-q silences it"
expect_fail "--tiles bogus" 2 "--tiles" "$T/o.pts" frs-sample -m "$T/m.frd" -n 10 --tiles bogus -o "$T/o.pts"
expect_fail "--tiles auto is gone" 2 "--tiles" "$T/o.pts" frs-sample -m "$T/m.frd" -n 10 --tiles auto -o "$T/o.pts"

# ---- the multi-level window (the default) ----
# -v: a line per level, its n_s halving from one to the next; the map
# sky spans five octaves of levels at n 20000 here.
frs-sample -m "$T/m.frd" -i sky -n 20000 -v -o /dev/null 2>"$T/v.txt"
awk '/^frs-sample:   level/ { l = $3 + 0; ns = $5 + 0; n++;
	if (n > 1 && ns * 2^(l - pl) != pns) bad = 1; pl = l; pns = ns }
    END { exit !(n >= 5 && !bad) }' "$T/v.txt" &&
    ok "levels by default: -v's lines, five levels or more, n_s halving" ||
    nok "levels by default: $(grep level "$T/v.txt" | tr '\n' ' ')"
grep -q 'levels; .* % of the samples show a matrix element that another one of their level' "$T/v.txt" &&
    ok "-v: the reuse share within levels" || nok "-v: the reuse share within levels"
# Every implementation and device, on levels spanning five octaves, with
# progressive steps and the thesis rule too; and any thread count.
same_all "sky, levels" "naive stack level1 level2 sorted flat1" -m "$T/m.frd" -i sky -n 20000
same_all "sky 64x32, levels, progressive" "sorted flat1" -m "$T/m.frd" -i sky -s 64x32 --progressive 2000,9000
same_all "ramp, levels, thesis rule, random jitter" "stack sorted" -m "$T/m.frd" -i ramp -n 6000 --threshold thesis --jitter random
for j in 1 2 3; do frs-sample -q -m "$T/m.frd" -i sky -n 20000 -j $j -o "$T/j$j.pts"; done
cmp -s "$T/j1.pts" "$T/j2.pts" && cmp -s "$T/j1.pts" "$T/j3.pts" &&
    ok "levels: the same bytes on 1, 2 and 3 threads" || nok "levels: the same bytes on 1, 2 and 3 threads"
# Progressive steps nest (each step only adds points), and --level-column
# names levels that -v lists.
frs-sample -q -m "$T/m.frd" -i sky --progressive 1000,5000,20000 --level-column -T -o "$T/pr.txt"
for k in 1 2; do
	awk -v k=$k '!/^#/ && $3 <= k { print $1, $2 }' "$T/pr.txt" | sort >"$T/pr$k.s"
done
[ "$(comm -23 "$T/pr1.s" "$T/pr2.s" | wc -l)" = 0 ] && [ "$(wc -l <"$T/pr1.s")" -gt 500 ] &&
    ok "levels: progressive steps nest" || nok "levels: progressive steps nest"
lv=$(awk '!/^#/ { print $4 }' "$T/pr.txt" | sort -u | tr '\n' ' ')
frs-sample -m "$T/m.frd" -i sky -n 20000 -v -o /dev/null 2>&1 |
    awk '/^frs-sample:   level/ { printf "%d ", $3 }' >"$T/vl"
[ "$lv" = "$(cat "$T/vl")" ] && ok "--level-column: the levels of -v ($lv)" ||
    nok "--level-column: $lv, -v: $(cat "$T/vl")"
# The union of --sets and exact counts hold with levels.
frs-sample -q -m "$T/m.frd" -i sky -n 3000 --exact-count --sets 3 -T -o "$T/x.txt"
awk '!/^#/ { c[$3]++ } END { exit !(c[0] == 3000 && c[1] == 3000 && c[2] == 3000) }' "$T/x.txt" &&
    ok "levels: --exact-count, 3 sets of exactly 3000" || nok "levels: --exact-count --sets 3"
frs-sample -q -m "$T/m.frd" -i sky -n 3000 -S 2 -T | grep -v '^#' >"$T/s2.txt"
awk '!/^#/ && $3 == 1 { print $1, $2 }' "$T/x.txt" >/dev/null
frs-sample -q -m "$T/m.frd" -i sky -n 3000 --sets 3 -T -o "$T/u.txt"
awk '!/^#/ && $3 == 1 { print $1, $2 }' "$T/u.txt" | cmp -s - "$T/s2.txt" &&
    ok "levels: set 1 of --sets 3 is the run of seed S+1" || nok "levels: set 1 of --sets 3"
# The counts follow the map across the levels: chi-square of blocks
# against n I / sum I (p above 1e-4) on sky (most samples at the sun)
# and on sunset.exr (most in the levels of the sky and the ground), and
# each sample's --pdf is the map's density there, I / mean I.
frs-sample -q -m "$T/m.frd" -i sky -n 20000 -o "$T/chil.pts"
pv=$("$REF" chi2 8 8 sky "$T/chil.pts" | awk '{ print $8 }')
awk -v p="$pv" 'BEGIN { exit !(p > 1e-4) }' && ok "sky, levels: block chi-square p $pv" ||
    nok "sky, levels: block chi-square p $pv"
frs-sample -q -i "$TD/sunset.exr" --equirect -s 256x128 -n 60000 --pdf -T -o "$T/chs.txt"
pv=$("$REF" chi2 16 8 "$TD/sunset.exr" --equirect "$T/chs.txt" | awk '{ print $8 }')
awk -v p="$pv" 'BEGIN { exit !(p > 1e-4) }' && ok "sunset, levels: block chi-square p $pv" ||
    nok "sunset, levels: block chi-square p $pv"
c=$(grep -vc '^#' "$T/chs.txt")
awk -v c="$c" 'BEGIN { exit !(c > 59400 && c < 60600) }' &&
    ok "sunset, levels: $c samples for 60000" || nok "sunset, levels: $c samples for 60000"
"$REF" pdf "$TD/sunset.exr" --equirect -s 256x128 "$T/chs.txt" >"$T/pdf.txt" 2>&1 &&
    ok "sunset, levels: --pdf is I / mean I at each sample" ||
    nok "sunset, levels: --pdf: $(cat "$T/pdf.txt")"
# No lattice where the map is dark: the band measure (rows 0.6-0.9, the
# ground) on the real map sunset.exr with the default matrix, plain
# against levels with the same seed; the measure itself fires on a
# planted lattice (t_ref_tiles).
for t in plain levels; do
	frs-sample -q -i "$TD/sunset.exr" --equirect -n 4096 --tiles $t -o "$T/b$t.pts"
done
bp=$("$REF" band 0.6 0.9 "$T/bplain.pts" | awk '{ print $5 }')
bl=$("$REF" band 0.6 0.9 "$T/blevels.pts" | awk '{ print $5 }')
awk -v p="$bp" -v l="$bl" 'BEGIN { exit !(p > 100 && l < 25) }' &&
    ok "sunset, band periodogram maximum: plain $bp, levels $bl" ||
    nok "sunset, band periodogram maximum: plain $bp, levels $bl"
done_testing
