#!/bin/sh
# mc-error: estimates and errors against oracles, weights, sets, groups
# and bad input.
. "$(dirname "$0")/lib.sh"

# col NAME FILE [ROW]: the value of column NAME in data row ROW (1).
col() {
	awk -F '\t' -v c="$1" -v r="${3:-1}" 'NR == 1 {
		for (i = 1; i <= NF; i++) if ($i == c) k = i } NR == r + 1 {
		print $k }' "$2"
}

# The exact values, computed here independently of the program.
GAUSS=0.14112914561122003	# (0.15 sqrt(2 pi) erf(0.5 / (0.15 sqrt 2)))^2
DISC=0.38484510006474967	# pi 0.35^2
STEP=0.45			# 0.2 + 0.5 / 2

ref-sample -k regular -n 4096 -T -q -o "$T/grid.txt"
ref-sample -k random --sets 200 -n 256 -q -o "$T/rand.pts"
ref-sample -k random -n 256 -S 3 -q -o "$T/r3.pts"

check "default: all integrands" mc-error -o "$T/all" "$T/grid.txt"
[ "$(head -n 1 "$T/all")" = "$(printf 'integrand\tn\tsets\testimate_mean\tabs_error\trmse\trel_rmse')" ] &&
    ok "header" || nok "header: $(head -n 1 "$T/all")"
[ "$(cut -f 1 "$T/all" | tail -n +2 | tr '\n' ' ')" = "gauss disc step " ] &&
    ok "rows in fixed order" || nok "rows: $(cut -f 1 "$T/all")"

# (1) The 64 x 64 grid is the midpoint rule: the mean equals an awk
# midpoint sum, and the error is the midpoint rule's, about 1.3e-6
# (h^2/24 times the jump of f' per axis); 1e-5 bounds it.
mid=$(awk '!/^#/ && NF { n++; dx = $1 - 0.5; dy = $2 - 0.5
	s += exp(-(dx * dx + dy * dy) / (2 * 0.15 * 0.15)) }
	END { printf "%.17g", s / n }' "$T/grid.txt")
mc-error -f gauss "$T/grid.txt" >"$T/g"
near "$(col estimate_mean "$T/g")" "$mid" 1e-8 &&
    ok "grid: gauss estimate = midpoint sum" ||
    nok "grid: gauss $(col estimate_mean "$T/g"), midpoint $mid"
near "$(col estimate_mean "$T/g")" "$GAUSS" 1e-5 &&
    awk -v e="$(col abs_error "$T/g")" 'BEGIN { exit !(e > 0 && e < 1e-5) }' &&
    ok "grid: gauss within 1e-5 of exact" ||
    nok "grid: gauss error $(col abs_error "$T/g")"
e=$(col estimate_mean "$T/g"); a=$(col abs_error "$T/g")
awk -v e="$e" -v a="$a" -v x="$GAUSS" 'BEGIN { d = e - x; if (d < 0) d = -d
	exit !(d - a < 1e-9 && a - d < 1e-9) }' &&
    ok "abs_error = |estimate - exact|" || nok "abs_error $a, estimate $e"

# (2) Uniform random points: the rmse of disc is the binomial
# sqrt(p (1 - p) / n), p = pi r^2, within 20% (200 sets).
check "--sets 256" mc-error -f disc --sets 256 -o "$T/d" "$T/rand.pts"
[ "$(col sets "$T/d")" = 200 ] && [ "$(col n "$T/d")" = 256 ] &&
    ok "--sets: 200 sets of 256" || nok "--sets row: $(sed -n 2p "$T/d")"
th=$(awk -v p="$DISC" 'BEGIN { printf "%.9g", sqrt(p * (1 - p) / 256) }')
near "$(col rmse "$T/d")" "$th" 0.2 &&
    ok "disc rmse $(col rmse "$T/d") ~ $th" || nok "disc rmse $(col rmse "$T/d"), theory $th"
r=$(awk -v a="$(col rmse "$T/d")" -v p="$DISC" 'BEGIN { printf "%.9g", a / p }')
near "$(col rel_rmse "$T/d")" "$r" 1e-8 && ok "rel_rmse = rmse / exact" ||
    nok "rel_rmse $(col rel_rmse "$T/d"), expected $r"
# The mean over the sets of the per-set estimates: one set of 51200
# points has the same mean (equal set sizes).  rand.pts has a set column
# (ref-sample --sets), which mc-error splits by: the file without it is
# the one set.
ref-sample -k random --sets 200 -n 256 -q -T | awk '!/^#/ { print $1, $2 }' >"$T/rand1.txt"
mc-error -f disc "$T/rand.pts" >"$T/d0"
cmp -s "$T/d0" "$T/d" && ok "the set column splits as --sets 256 does" || nok "set column: $(cat "$T/d0")"
mc-error -f disc "$T/rand1.txt" >"$T/d1"
# The same file cut by --sets 256: the rows of the set column, and a
# warning naming the file; --sets 128 beside the set column: its sets.
mc-error -f disc --sets 256 "$T/rand1.txt" >"$T/d2" 2>"$T/err"
[ "$(cut -f 1-6 "$T/d2")" = "$(cut -f 1-6 "$T/d")" ] &&
    grep -q "^mc-error: warning: $T/rand1.txt: no set column: cut in file order into 200 sets" "$T/err" &&
    ok "no set column, --sets 256: 200 blocks, a warning naming the file" ||
    nok "--sets 256 without a set column: $(cat "$T/err")"
mc-error -f disc --sets 128 "$T/rand.pts" >"$T/d3" 2>"$T/err"
cmp -s "$T/d3" "$T/d" && grep -q "rand.pts: .*256 points, not 128" "$T/err" &&
    ok "--sets 128 beside a set column of 256: its sets, a warning" ||
    nok "--sets 128 beside a set column: $(cat "$T/err")"
near "$(col estimate_mean "$T/d1")" "$(col estimate_mean "$T/d")" 1e-9 &&
    [ "$(col sets "$T/d1")" = 1 ] && ok "one set: same mean" || nok "one set"

# step on random points: the estimate is the share below the line.
mc-error -f step "$T/r3.pts" >"$T/s"
ref-sample -k random -n 256 -S 3 -T -q -o "$T/r3.txt"
share=$(awk '!/^#/ && NF { n++; if ($2 < 0.2 + 0.5 * $1) k++ }
	END { printf "%.9g", k / n }' "$T/r3.txt")
near "$(col estimate_mean "$T/s")" "$share" 1e-12 &&
    ok "step: share below the line" || nok "step: $(col estimate_mean "$T/s"), share $share"

# (3) Weights: f / pdf averaged, exactly.  step is 1 at the 1st, 3rd
# and 4th point: (1/2 + 0 + 1/4 + 2) / 4 = 0.6875; unweighted 3/4.
cat >"$T/w.txt" <<'EOF'
#pts dims=2 extra=1 count=4
0.1 0.1 2
0.5 0.9 0.5
0.9 0.3 4
0.6 0.2 0.5
EOF
mc-error -f step "$T/w.txt" >"$T/w"
[ "$(col estimate_mean "$T/w")" = 0.6875 ] && [ "$(col abs_error "$T/w")" = 0.2375 ] &&
    ok "pdf column: weighted mean" || nok "weighted: $(sed -n 2p "$T/w")"
mc-error -f step --weights "$T/w.txt" >"$T/w2"
cmp -s "$T/w" "$T/w2" && ok "--weights = the default with a pdf" || nok "--weights"
mc-error -f step --no-pdf "$T/w.txt" >"$T/w3"
[ "$(col estimate_mean "$T/w3")" = 0.75 ] && ok "--no-pdf: plain mean" ||
    nok "--no-pdf: $(sed -n 2p "$T/w3")"
# gauss with a constant pdf 2: half the plain mean.
awk '!/^#/ && NF { print $1, $2, 2 } /^#/ { print "#pts dims=2 extra=1" }' \
    "$T/grid.txt" >"$T/g2.txt"
mc-error -f gauss "$T/g2.txt" >"$T/g2"
near "$(col estimate_mean "$T/g2")" "$(awk -v m="$mid" 'BEGIN { printf "%.17g", m / 2 }')" 1e-8 &&
    ok "pdf 2: half the plain mean" || nok "pdf 2: $(col estimate_mean "$T/g2")"

# --group, several files, determinism, text and standard input.
mc-error --group file "$T/rand1.txt" "$T/r3.pts" >"$T/gf"
[ "$(wc -l <"$T/gf")" -eq 7 ] && [ "$(col n "$T/gf" 2)" = 256 ] &&
    [ "$(col n "$T/gf" 1)" = 51200 ] && [ "$(col file "$T/gf" 1)" = "$T/rand1.txt" ] &&
    [ "$(col file "$T/gf" 2)" = "$T/r3.pts" ] &&
    ok "--group file: a row per file and integrand, with the file" ||
    nok "--group file: $(cat "$T/gf")"
mc-error -f disc --group file "$T/r3.pts" >"$T/gf1"
[ "$(col file "$T/gf1")" = "$T/r3.pts" ] && ok "--group file, one file: the file column" ||
    nok "--group file, one file: $(cat "$T/gf1")"
# Several files are never merged into one row: --group n is per count
# and file, and the rows name their file.
mc-error -f disc --sets 256 "$T/rand.pts" "$T/r3.pts" >"$T/gn"
[ "$(wc -l <"$T/gn")" -eq 3 ] && [ "$(col sets "$T/gn") $(col sets "$T/gn" 2)" = "200 1" ] &&
    [ "$(col file "$T/gn") $(col file "$T/gn" 2)" = "$T/rand.pts $T/r3.pts" ] &&
    ok "--group n, two files: a row each, with the file" || nok "--group n: $(cat "$T/gn")"
mc-error -f disc --sets 256 --group n "$T/rand.pts" "$T/r3.pts" >"$T/gn2"
[ "$(wc -l <"$T/gn2")" -eq 2 ] && [ "$(col sets "$T/gn2")" = 201 ] &&
    [ "$(head -n 1 "$T/gn2" | cut -f 8)" = "" ] &&
    ok "--group n: sets of equal size together over the files" || nok "--group n: $(cat "$T/gn2")"
[ "$(head -n 1 "$T/d" | cut -f 8)" = "" ] && ok "one file: no file column" ||
    nok "one file: $(head -n 1 "$T/d")"
mc-error -f disc --group all "$T/grid.txt" "$T/r3.pts" >"$T/ga"
[ "$(wc -l <"$T/ga")" -eq 2 ] && [ "$(col n "$T/ga")" = 2176 ] &&
    [ "$(head -n 1 "$T/ga" | cut -f 8)" = "" ] &&
    [ "$(col sets "$T/ga")" = 2 ] && ok "--group all: one row, n the mean" ||
    nok "--group all: $(cat "$T/ga")"
mc-error -f gauss -f disc,step --sets 256 "$T/rand.pts" >"$T/x1"
mc-error --sets 256 "$T/rand.pts" >"$T/x2"
cmp -s "$T/x1" "$T/x2" && ok "-f repeated and comma lists; deterministic" ||
    nok "-f lists"
mc-error - <"$T/grid.txt" >"$T/x3"
cmp -s "$T/x3" "$T/all" && ok "standard input" || nok "standard input"

# Sets through a pipe: frs-sample --sets 4 --pdf's set column splits the
# stream as the four seeds' files do, and its pdf column (named) weights.
frs-sample -q -i blob -n 200 --sets 4 --pdf | mc-error --group all - >"$T/ps"
for s in 1 2 3 4; do frs-sample -q -i blob -n 200 -S $s --pdf -o "$T/p$s.pts"; done
mc-error --group all "$T/p1.pts" "$T/p2.pts" "$T/p3.pts" "$T/p4.pts" >"$T/ps1"
cmp -s "$T/ps" "$T/ps1" && [ "$(col sets "$T/ps")" = 4 ] &&
    ok "frs-sample --sets 4 --pdf | mc-error: the four seeds' rows" ||
    nok "frs-sample --sets 4 | mc-error: $(cat "$T/ps") / $(cat "$T/ps1")"
frs-sample -q -i blob -n 200 --sets 4 --pdf | mc-error --group file - >"$T/psf"
[ "$(cut -f 1-7 "$T/psf")" = "$(cat "$T/ps1")" ] && [ "$(col file "$T/psf")" = - ] &&
    ok "--group file of the stream: the same rows, file -" || nok "--group file of the stream"
# Named columns: the step and set columns of --progressive --sets are no
# pdf (in version 1 an unnamed first extra column was taken for one).
frs-sample -q -i blob --progressive 50,200 --sets 2 | mc-error -f step - >"$T/st"
frs-sample -q -i blob --progressive 50,200 --sets 2 | mc-error -f step --no-pdf - >"$T/st1"
cmp -s "$T/st" "$T/st1" && [ "$(wc -l <"$T/st")" = 3 ] &&
    ok "step and set columns are not a pdf" || nok "step column taken for a pdf"
frs-sample -q -i blob --progressive 50,200 | mc-error -f step - >"$T/st2"
frs-sample -q -i blob --progressive 50,200 | mc-error -f step --no-pdf - >"$T/st3"
cmp -s "$T/st2" "$T/st3" && [ "$(wc -l <"$T/st2")" = 2 ] &&
    ok "--progressive alone: the step column is not a pdf" || nok "step column taken for a pdf"
expect_fail "--weights without a pdf column" 1 "no pdf column" "$T/o9" \
    sh -c "frs-sample -q -i blob --progressive 50,200 --sets 2 | mc-error --weights -o '$T/o9' -"

# (4) Bad input: exit 1 naming the file, no output left.
O=$T/o/out.tsv
mkdir "$T/o"
printf '#pts dims=3\n0.1 0.2 0.3\n' >"$T/d3.txt"
printf '#pts dims=2\n0.1 1.5\n' >"$T/big.txt"
printf '#pts dims=2 extra=1\n0.1 0.2 0\n' >"$T/p0.txt"
printf '#pts dims=2 extra=1\n0.1 0.2 -1\n' >"$T/pneg.txt"
printf '#pts dims=2 extra=1\n0.1 0.2 inf\n' >"$T/pinf.txt"
printf '#pts dims=2 extra=1\n0.1 0.2 nan\n' >"$T/pnan.txt"
: >"$T/empty.txt"
expect_fail "missing file" 1 "$T/none.pts" "$O" mc-error -o "$O" "$T/none.pts"
expect_fail "3-D points" 1 "$T/d3.txt" "$O" mc-error -o "$O" "$T/d3.txt"
expect_fail "point outside [0,1)" 1 "$T/big.txt" "$O" mc-error -o "$O" "$T/big.txt"
expect_fail "pdf 0" 1 "$T/p0.txt" "$O" mc-error -o "$O" "$T/p0.txt"
# Points counted from 0, as every reader counts them.
printf '#pts dims=2 extra=1\n0.1 0.2 1\n0.3 0.4 0\n' >"$T/p1.txt"
expect_fail "pdf 0 at point 1 (the second)" 1 "p1.txt: point 1: pdf 0 is not positive" "$O" \
    mc-error -o "$O" "$T/p1.txt"
expect_fail "pdf 0 at point 1 of the second set" 1 "p1.txt: point 1: pdf 0 is not positive" "$O" \
    mc-error --sets 1 -o "$O" "$T/p1.txt"
expect_fail "pdf < 0" 1 "$T/pneg.txt" "$O" mc-error -o "$O" "$T/pneg.txt"
expect_fail "pdf inf" 1 "$T/pinf.txt" "$O" mc-error -o "$O" "$T/pinf.txt"
expect_fail "pdf nan" 1 "$T/pnan.txt" "$O" mc-error -o "$O" "$T/pnan.txt"
expect_fail "empty file" 1 "$T/empty.txt" "$O" mc-error -o "$O" "$T/empty.txt"
expect_fail "--sets not dividing" 1 "$T/r3.pts" "$O" \
    mc-error --sets 100 -o "$O" "$T/rand1.txt" "$T/r3.pts"
expect_fail "--weights without a pdf" 1 "$T/r3.pts" "$O" \
    mc-error --weights -o "$O" "$T/r3.pts"
expect_fail "bad file after good" 1 "$T/d3.txt" "$O" \
    mc-error -o "$O" "$T/r3.pts" "$T/d3.txt"

# Usage errors: exit 2.
expect_fail "unknown integrand" 2 "bogus" "$O" mc-error -f gauss,bogus -o "$O" "$T/r3.pts"
expect_fail "empty -f" 2 "-f" "$O" mc-error -f , -o "$O" "$T/r3.pts"
expect_fail "bad --group" 2 "--group" "$O" mc-error --group set -o "$O" "$T/r3.pts"
expect_fail "--sets 0" 2 "--sets" "$O" mc-error --sets 0 -o "$O" "$T/r3.pts"
expect_fail "--weights --no-pdf" 2 "exclude" "$O" \
    mc-error --weights --no-pdf -o "$O" "$T/r3.pts"
expect_fail "no files" 2 "no point files" "$O" mc-error -o "$O"
expect_fail "unknown option" 2 "usage" "$O" mc-error --bogus -o "$O" "$T/r3.pts"
check "-h" mc-error -h
check "--version" mc-error --version

# env: the irradiance from an equirectangular map, (u, v) = (phi / 2 pi,
# theta / pi), f = L cos+(theta) sin(theta) 2 pi^2.  Not in the default
# set unless --env is given.
# exact VAR FILE: I = rmse / rel_rmse of the first row.
exact() {
	awk -v a="$(col rmse "$1")" -v r="$(col rel_rmse "$1")" \
	    'BEGIN { printf "%.12g", a / r }'
}
PI=3.14159265358979324
mc-error --env const "$T/grid.txt" >"$T/e0"
[ "$(cut -f 1 "$T/e0" | tail -n +2 | tr '\n' ' ')" = "gauss disc step env " ] &&
    ok "--env adds env to the default set" || nok "--env rows: $(cut -f 1 "$T/e0")"
# (1) L = 1: I = 2 pi^2 int_0^1/2 cos(pi v) sin(pi v) dv = pi.
ref-sample -k regular -n 65536 -T -q -o "$T/g256.txt"
mc-error -f env --env const "$T/g256.txt" >"$T/e1"
near "$(exact "$T/e1")" "$PI" 1e-7 && ok "env const: exact pi" ||
    nok "env const: exact $(exact "$T/e1")"
near "$(col estimate_mean "$T/e1")" "$PI" 1e-3 &&
    ok "env const: 256x256 grid within 1e-3 of pi" ||
    nok "env const: estimate $(col estimate_mean "$T/e1")"
# The midpoint sum of the env integrand over the rows of ramp:angle=90
# (row j of ROWS holds (j + 1/2) / ROWS), STEPS steps a row:
# 2 pi^2 int_0^1/2 L(v) cos sin dv.
ramp_midsum() {
	awk -v pi="$PI" -v rows="$1" -v per="$2" 'BEGIN { n = rows * per
	h = 1 / n
	for (k = 0; k < n / 2; k++) { v = (k + 0.5) * h
		L = (int(v * rows) + 0.5) / rows
		s += L * cos(pi * v) * sin(pi * v) }
	printf "%.12g", s * h * 2 * pi * pi }'
}
# (2) ramp:angle=90 at 128x128: row j holds (j + 1/2) / 128.  The exact
# value against a fine midpoint sum over v (4096 steps a row, so that no
# step straddles a row) of the piecewise constant integrand, not the
# closed form; both are near pi/4 = 2 pi^2 int_0^1/2 v cos sin dv.
ref-sample -k regular -n 262144 -T -q -o "$T/g512.txt"
mc-error -f env --env ramp:angle=90 "$T/g512.txt" >"$T/e2"
orc=$(ramp_midsum 128 4096)
near "$(exact "$T/e2")" "$orc" 1e-8 && ok "env ramp: exact = midpoint sum $orc" ||
    nok "env ramp: exact $(exact "$T/e2"), midpoint sum $orc"
near "$(col estimate_mean "$T/e2")" "$orc" 1e-3 &&
    ok "env ramp: 512x512 grid within 1e-3" ||
    nok "env ramp: estimate $(col estimate_mean "$T/e2"), exact $orc"
# An odd height: row 2 of 5 straddles the horizon v = 1/2 and counts
# half; a constant map still gives pi, a ramp its midpoint sum.
imap gen -q -s 8x5 --format exr -o "$T/c5.exr" const
imap gen -q -s 8x5 --format exr -o "$T/r5.exr" ramp:angle=90
mc-error -f env --env "$T/c5.exr" "$T/grid.txt" >"$T/e5"
near "$(exact "$T/e5")" "$PI" 1e-7 && ok "env 8x5 const: exact pi" ||
    nok "env 8x5 const: exact $(exact "$T/e5")"
mc-error -f env --env "$T/r5.exr" "$T/grid.txt" >"$T/e6"
orc=$(ramp_midsum 5 40000)
near "$(exact "$T/e6")" "$orc" 1e-7 && ok "env 8x5 ramp: exact = midpoint sum $orc" ||
    nok "env 8x5 ramp: exact $(exact "$T/e6"), midpoint sum $orc"
# -f env alone uses data/sunset.exr; so does --env data/sunset.exr.
check "-f env: the default map" mc-error -f env -o "$T/e3" "$T/grid.txt"
mc-error -f env --env data/sunset.exr "$T/grid.txt" >"$T/e4"
cmp -s "$T/e3" "$T/e4" && ok "default map = data/sunset.exr" || nok "default map"
# (3) FRS importance sampling of the map with --equirect --pdf against
# uniform random points: within 2% of the exact value, and a far smaller
# rmse (10 sets of about 20000 against 20).
for i in 1 2 3 4 5 6 7 8 9 10; do
	frs-sample -q -i data/sunset.exr --equirect --pdf -n 20000 \
	    -S "$i" -o "$T/fe$i.pts"
done
ref-sample -k random --sets 20 -n 20000 -q -o "$T/re.pts"
mc-error -f env --group all "$T"/fe*.pts >"$T/ef"
mc-error -f env --sets 20000 "$T/re.pts" >"$T/er"
I=$(exact "$T/ef")
near "$(col estimate_mean "$T/ef")" "$I" 0.02 &&
    ok "env FRS: estimate $(col estimate_mean "$T/ef") ~ $I" ||
    nok "env FRS: estimate $(col estimate_mean "$T/ef"), exact $I"
awk -v f="$(col rmse "$T/ef")" -v r="$(col rmse "$T/er")" \
    'BEGIN { exit !(f > 0 && 3 * f < r) }' &&
    ok "env: FRS rmse $(col rmse "$T/ef") < random $(col rmse "$T/er") / 3" ||
    nok "env: FRS rmse $(col rmse "$T/ef"), random $(col rmse "$T/er")"
# (4) A bad map: exit 1 naming it, no output.
printf 'not an image\n' >"$T/bad.exr"
expect_fail "--env: not an image" 1 "$T/bad.exr" "$O" \
    mc-error --env "$T/bad.exr" -o "$O" "$T/r3.pts"
expect_fail "--env: missing file" 1 "$T/none.exr" "$O" \
    mc-error -f gauss --env "$T/none.exr" -o "$O" "$T/r3.pts"
expect_fail "--env: all zero" 1 "const:0" "$O" \
    mc-error --env const:0 -o "$O" "$T/r3.pts"
# --strict, as in frs-sample: negative radiance in env's map an error
# naming it; without it clamped with a warning.  No map: a usage error.
expect_fail "--strict refuses a negative env map" 1 "is negative" - \
    mc-error -f env --strict --env "$TD/interior.exr" "$T/grid.txt"
mc-error -f env --env "$TD/interior.exr" "$T/grid.txt" >/dev/null 2>"$T/err" &&
    grep -q "interior.exr: .*negative.*clamped" "$T/err" &&
    ok "a negative env map without --strict: clamped, a warning" ||
    nok "negative env map without --strict: $(cat "$T/err")"
expect_fail "--strict without env's map" 2 "--strict" - \
    mc-error -f disc --strict "$T/grid.txt"
# (5) --pdf-map: the density of a point from a map.  A 2 x 1 ramp holds
# 0.25 and 0.75 (imap info), mean 0.5: densities 0.5 and 1.5; the
# estimate of gauss at two points, one a pixel, against awk's.
imap gen -q -s 2x1 --format exr -o "$T/r21.exr" ramp
printf '#pts dims=2 extra=0 version=2\n0.25 0.5\n0.75 0.4\n' >"$T/two.txt"
orc=$(awk 'function g(x, y) { x -= 0.5; y -= 0.5
	return exp(-(x * x + y * y) / (2 * 0.15 * 0.15)) }
	BEGIN { printf "%.12g", (g(0.25, 0.5) / 0.5 + g(0.75, 0.4) / 1.5) / 2 }')
mc-error -f gauss --pdf-map "$T/r21.exr" "$T/two.txt" >"$T/pm"
near "$(col estimate_mean "$T/pm")" "$orc" 1e-8 &&
    ok "--pdf-map: 2x1 ramp, f / p by hand $orc" ||
    nok "--pdf-map: estimate $(col estimate_mean "$T/pm"), by hand $orc"
# Against frs-sample's own pdf column: its sets without the column and
# --pdf-map of the same map give --weights' table (the map's mean, as
# frs-sample computes it, may differ in the last digits).
frs-sample -q -i blob:floor=0.1 --pdf -n 512 --sets 4 -T -o "$T/bp.txt"
awk '/^#pts/ { sub(/extra=2/, "extra=1"); sub(/names=pdf,set/, "names=set") }
    !/^#/ && NF { $3 = $4; NF = 3 } { print }' "$T/bp.txt" >"$T/bn.txt"
mc-error --group all --weights "$T/bp.txt" >"$T/pw"
mc-error --group all --pdf-map blob:floor=0.1 "$T/bn.txt" >"$T/pn"
same=1
for f in rmse estimate_mean; do for r in 1 2 3; do
	near "$(col $f "$T/pn" $r)" "$(col $f "$T/pw" $r)" 1e-9 || same=0
done; done
[ "$(col sets "$T/pn")" = 4 ] && [ $same = 1 ] &&
    ok "--pdf-map blob = frs-sample's pdf column (--weights)" ||
    nok "--pdf-map: $(cat "$T/pn") against $(cat "$T/pw")"
# a point in a pixel of zero (blob:sigma=0.01's corners), exclusive
# options, and --strict goes with --pdf-map's map
printf '#pts dims=2 extra=0 version=2\n0.5 0.5\n0.001 0.001\n' >"$T/z.txt"
expect_fail "--pdf-map: a point in a pixel of zero" 1 "point 1: --pdf-map" "$O" \
    mc-error -f gauss --pdf-map blob:sigma=0.01 -o "$O" "$T/z.txt"
expect_fail "--pdf-map with --weights" 2 "exclude each other" - \
    mc-error --pdf-map blob --weights "$T/grid.txt"
expect_fail "--pdf-map with --no-pdf" 2 "exclude each other" - \
    mc-error --pdf-map blob --no-pdf "$T/grid.txt"
expect_fail "--pdf-map --strict: a negative map" 1 "is negative" - \
    mc-error -f gauss --strict --pdf-map "$TD/interior.exr" "$T/grid.txt"
done_testing
