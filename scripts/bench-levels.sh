#!/bin/sh
# The multi-level window (frs-sample --tiles levels, the default) against
# the thesis's window (--tiles plain) in one run, with shuffled tiles,
# relaxed dart throwing and HSW beside them, on the three HDR maps of
# data/ with --equirect (forest, sunset, interior; the default matrix, no
# jitter).  Each table ends with its targets and a verdict computed from
# its numbers:
#   1. lattice: the largest periodogram value of the samples in rows
#      0.6-0.9 (the ground; ref_tiles band), levels within 1.5 times
#      relaxed dart's;
#   2. spacing: nearest-neighbour distances in local spacings (ref_tiles
#      nn), 1st and 5th percentiles, the mean over SEEDS seeds; levels at
#      least 0.9 (p1) and 0.95 (p5) of plain's; and the seams: the share
#      of samples with a neighbour of another level within 1.5 spacings,
#      their p1 and the others';
#   3. integration: mc-error -f env over MC sets of 1024 (relative
#      RMSE), levels no worse than plain within the noise of the two
#      estimates (an RMSE of m sets has a relative standard error of
#      about 1 / sqrt(2 m): ratio at most 1 + 2 sqrt(1 / m));
#   4. counts: chi-square of 200000 samples in 32 x 16 blocks against the
#      map, p above 1e-4;
#   5. speed: Sorted, whole process, forest at 65536 and 2^20, the median
#      of REPS interleaved runs, levels over plain at most 1.0 (-j 1 and
#      all cores);
#   6. 3-D: shell3 (the README's line, n 4096, sigma 4), the same band
#      measure on the slab 0 < z < 0.2, outside the shell, against dart
#      throwing (uniform, 3-D) with as many points.
# usage: scripts/bench-levels.sh BUILD     (SEEDS=4, REPS=5, MC=96)
set -eu
cd "$(dirname "$0")/.."
. scripts/benchlib.sh
B=${1:-build/rel}
FRS=$B/bin/frs-sample
REF=$B/test/ref_tiles
bench_setup bench-levels "$FRS" "$REF" "$B/bin/ref-sample" \
    "$B/bin/hsw-sample" "$B/bin/mc-error"
SEEDS=${SEEDS:-4}
REPS=${REPS:-5}
MC=${MC:-96}
MAPS="forest sunset interior"

# frs MAP N SEED TILES OUT [options]: FRS of data/MAP.exr, --equirect
frs() {
	m=$1 n=$2 s=$3 t=$4 o=$5
	shift 5
	"$FRS" -q -i "data/$m.exr" --equirect -n "$n" -S "$s" --tiles "$t" "$@" -o "$o"
}
band() { "$REF" band 0.6 0.9 "$1" | awk '{ print $5 }'; }
mean() { awk '{ s += $1 } END { printf "%.3f", s / NR }'; }
verdict() { [ "$1" = 1 ] && echo "met" || echo "NOT met"; }

echo "levels: the multi-level window against the thesis's (plain) on HDR maps"
echo "(--equirect, default matrix, no jitter; $SEEDS seeds for the spacings)"
echo
echo "1-2. lattice (band max, rows 0.6-0.9) and spacing (NN in local spacings)"
printf '%-9s %6s | %7s %7s %7s %7s %7s %6s | %6s %6s %5s | %6s %6s %5s | %5s %6s %6s\n' \
    map n lev plain shuf rdart hsw lev/rd p1_lev p1_pl ratio p5_lev p5_pl \
    ratio seam% p1_sm p1_oth
ok1=1 ok2=1
for m in $MAPS; do
	for n in 4096 16384 65536; do
		: >"$T/nn.lev"
		: >"$T/nn.pl"
		for s in $(seq "$SEEDS"); do
			frs "$m" "$n" "$s" levels "$T/l$s.pts" --level-column
			frs "$m" "$n" "$s" plain "$T/p$s.pts"
			"$REF" nn "data/$m.exr" --equirect --level-col level \
			    "$T/l$s.pts" >>"$T/nn.lev"
			"$REF" nn "data/$m.exr" --equirect "$T/p$s.pts" >>"$T/nn.pl"
		done
		frs "$m" "$n" 1 shuffled "$T/s.pts"
		"$B/bin/ref-sample" -q -k relaxed-dart -i "data/$m.exr" --equirect \
		    -n "$n" -o "$T/d.pts"
		"$B/bin/hsw-sample" -q -i "data/$m.exr" --equirect -n "$n" -o "$T/h.pts"
		bl=$(band "$T/l1.pts") bp=$(band "$T/p1.pts") bs=$(band "$T/s.pts")
		bd=$(band "$T/d.pts") bh=$(band "$T/h.pts")
		# nn lines: FILE n N p1 A p5 B p10 C mean D [seam N p1 A p5 B other N p1 A p5 B]
		l1=$(awk '{ print $5 }' "$T/nn.lev" | mean)
		l5=$(awk '{ print $7 }' "$T/nn.lev" | mean)
		q1=$(awk '{ print $5 }' "$T/nn.pl" | mean)
		q5=$(awk '{ print $7 }' "$T/nn.pl" | mean)
		sm=$(awk '{ s += $13; a += $3 } END { printf "%.1f", 100 * s / a }' "$T/nn.lev")
		s1=$(awk '$15 != "nan" { print $15 }' "$T/nn.lev" | mean)
		o1=$(awk '{ print $21 }' "$T/nn.lev" | mean)
		r=$(awk -v a="$bl" -v b="$bd" 'BEGIN { printf "%.2f", a / b }')
		r1=$(awk -v a="$l1" -v b="$q1" 'BEGIN { printf "%.2f", a / b }')
		r5=$(awk -v a="$l5" -v b="$q5" 'BEGIN { printf "%.2f", a / b }')
		awk -v r="$r" 'BEGIN { exit !(r <= 1.5) }' || ok1=0
		awk -v a="$r1" -v b="$r5" 'BEGIN { exit !(a >= 0.9 && b >= 0.95) }' ||
		    ok2=0
		printf '%-9s %6s | %7.1f %7.1f %7.1f %7.1f %7.1f %6s | %6s %6s %5s | %6s %6s %5s | %5s %6s %6s\n' \
		    "$m" "$n" "$bl" "$bp" "$bs" "$bd" "$bh" "$r" "$l1" "$q1" "$r1" \
		    "$l5" "$q5" "$r5" "$sm" "$s1" "$o1"
	done
done
echo "targets: band levels/rdart <= 1.5: $(verdict $ok1); NN p1 >= 0.9 and p5 >= 0.95 of plain: $(verdict $ok2)"

echo
tol=$(awk -v m="$MC" 'BEGIN { printf "%.2f", 1 + 2 * sqrt(1 / m) }')
echo "3. integration: mc-error -f env, $MC sets of 1024 (relative RMSE)"
printf '%-9s %9s %9s %9s %9s %9s %6s\n' map levels plain shuffled hsw_rnd hsw_jit lev/pl
ok3=1
for m in $MAPS; do
	for t in levels plain shuffled; do
		frs "$m" 1024 1 "$t" "$T/mc.$t" --sets "$MC" --pdf
	done
	"$B/bin/hsw-sample" -q -i "data/$m.exr" --equirect -n 1024 --sets "$MC" \
	    --input random --pdf -o "$T/mc.hsw"
	"$B/bin/hsw-sample" -q -i "data/$m.exr" --equirect -n 1024 --sets "$MC" \
	    --input jittered --pdf -o "$T/mc.hswj"
	for f in levels plain shuffled hsw hswj; do
		"$B/bin/mc-error" -q -f env --env "data/$m.exr" --group all \
		    "$T/mc.$f" | awk 'NR == 2 { print $7 }' >"$T/e.$f"
	done
	r=$(awk -v a="$(cat "$T/e.levels")" -v b="$(cat "$T/e.plain")" \
	    'BEGIN { printf "%.2f", a / b }')
	awk -v r="$r" -v t="$tol" 'BEGIN { exit !(r <= t) }' || ok3=0
	printf '%-9s %9.5f %9.5f %9.5f %9.5f %9.5f %6s\n' "$m" "$(cat "$T/e.levels")" \
	    "$(cat "$T/e.plain")" "$(cat "$T/e.shuffled")" "$(cat "$T/e.hsw")" \
	    "$(cat "$T/e.hswj")" "$r"
done
echo "target: levels no worse than plain (ratio at most $tol): $(verdict $ok3)"

echo
echo "4. counts: 200000 samples of levels in 32 x 16 blocks against the map"
ok4=1
for m in $MAPS; do
	frs "$m" 200000 1 levels "$T/c.pts"
	line=$("$REF" chi2 32 16 "data/$m.exr" --equirect "$T/c.pts")
	p=$(echo "$line" | awk '{ print $8 }')
	awk -v p="$p" 'BEGIN { exit !(p > 1e-4) }' || ok4=0
	printf '%-9s %s\n' "$m" "$(echo "$line" | cut -d' ' -f2-)"
done
echo "target: p > 1e-4: $(verdict $ok4)"

echo
echo "5. speed: sorted, whole process, forest, median of $REPS interleaved runs"
printf '%8s %3s %9s %9s %6s\n' n j levels_s plain_s ratio
ok5=1
for n in 65536 1048576; do
	for j in 1 "$NCPU"; do
		: >"$T/tl"
		: >"$T/tp"
		for r in $(seq "$REPS"); do
			timed /dev/null frs forest "$n" 1 levels /dev/null -j "$j"
			echo "$SEC" >>"$T/tl"
			timed /dev/null frs forest "$n" 1 plain /dev/null -j "$j"
			echo "$SEC" >>"$T/tp"
		done
		a=$(sort -n "$T/tl" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
		b=$(sort -n "$T/tp" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
		r=$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f", a / b }')
		awk -v r="$r" 'BEGIN { exit !(r <= 1.0) }' || ok5=0
		printf '%8s %3s %9.4f %9.4f %6s\n' "$n" "$j" "$a" "$b" "$r"
	done
done
echo "target: levels no slower than plain: $(verdict $ok5)"

echo
echo "6. 3-D: shell3, n 4096, sigma 4, band max of the slab 0 < z < 0.2"
slab() { awk '!/^#/ && $3 > 0 && $3 < 0.2 { print $1, $2 }' "$1" >"$T/slab.txt"
	"$REF" band 0 1 "$T/slab.txt" | awk '{ print $3, $5 }'; }
"$FRS" -q -i shell3 -n 4096 --sigma 4 -T -o "$T/3l.txt"
"$FRS" -q -i shell3 -n 4096 --sigma 4 --tiles plain -T -o "$T/3p.txt"
"$B/bin/ref-sample" -q -d 3 -k dart -n 4096 -T -o "$T/3d.txt"
set -- $(slab "$T/3l.txt") $(slab "$T/3p.txt") $(slab "$T/3d.txt")
printf 'levels: %s points, max %s; plain: %s points, max %s; dart: %s points, max %s\n' \
    "$1" "$2" "$3" "$4" "$5" "$6"
echo "target: levels within 1.5 times dart's: $(verdict \
    "$(awk -v a="$2" -v b="$6" 'BEGIN { print (a <= 1.5 * b) }')")"
