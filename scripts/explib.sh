# Helpers for the experiment scripts (scripts/exp-*.sh); source it.
#
# Environment (scripts/experiments.sh sets it; each script also runs
# alone: sh scripts/exp-fig6.9.sh):
#   MODE     tiny (make check: seconds), quick (default: <= 50 s each) or
#            full (the thesis parameters)
#   BIN      the programs (default bin/)
#   RES      results root (default results/); the experiment writes
#            RES/ID/, intermediate files go to RES/cache/
#   JOBS     parallel jobs (default: all cores)
#   SSHLOGIN hosts for GNU parallel --sshlogin (e.g. "8/host1,8/host2,:");
#            the tree must be at the same path on every host (NFS)
#   ENVMAP   the environment map of Fig. 6.1d (default data/sunset.exr)
set -eu
TOP=$(cd "$(dirname "$0")/.." && pwd)
MODE=${MODE:-quick}
BIN=${BIN:-$TOP/bin}
RES=${RES:-$TOP/results}
JOBS=${JOBS:-$(nproc)}
ENVMAP=${ENVMAP:-$TOP/data/sunset.exr}
CACHE=$RES/cache
PATH=$BIN:$PATH
export PATH BIN RES MODE JOBS CACHE ENVMAP TOP

case $MODE in
tiny | quick | full) ;;
*) echo "explib: MODE must be tiny, quick or full" >&2; exit 2 ;;
esac

# pick TINY QUICK FULL: the value for the mode.
pick() {
	case $MODE in
	tiny) echo "$1" ;;
	quick) echo "$2" ;;
	*) echo "$3" ;;
	esac
}

# exp_begin ID "title" "thesis section and parameters" "full-mode estimate"
exp_begin() {
	ID=$1
	OUT=$RES/$ID
	mkdir -p "$OUT" "$CACHE"
	: >"$OUT/summary.md"
	EXP_T0=$(date +%s.%N)
	{
		echo "## $ID: $2"
		echo
		echo "Thesis: $3.  Mode: $MODE."
		echo
	} >"$OUT/head.md"
	if [ "$MODE" = full ]; then
		echo "$ID: full mode, expected to take $4" >&2
	fi
	export ID OUT
}

# newest program: a cached file older than it is stale.
exp_stamp() {
	ls -t "$BIN"/* 2>/dev/null | head -n 1
}

# cached FILE CMD...: FILE is CMD's standard output, made only when it is
# missing or older than the programs; written atomically.
cached() {
	f=$1
	shift
	s=$(exp_stamp)
	if [ -s "$f" ] && { [ -z "$s" ] || [ "$f" -nt "$s" ]; }; then
		return 0
	fi
	mkdir -p "$(dirname "$f")"
	"$@" >"$f.tmp.$$"
	mv -f "$f.tmp.$$" "$f"
}

# par_run: run the shell commands on standard input, one a line, with GNU
# parallel on JOBS cores (or the SSHLOGIN hosts); stops at the first
# failure.
par_run() {
	if [ -n "${SSHLOGIN:-}" ]; then
		parallel --will-cite --halt now,fail=1 --sshlogin "$SSHLOGIN" \
		    --workdir "$TOP" --env PATH --env MODE --env RES
	else
		parallel --will-cite --halt now,fail=1 -j "$JOBS"
	fi
}

# timing_inputs MAPS: the inputs of the timing experiments.  FRP is the
# default matrix prepared with frd-prep -a all (tiny mode: the .frd
# itself; only the untimed setup differs), ENV128 the environment map at
# 128x128 with the sin(theta) weight when MAPS holds env; mapin NAME gives
# the map argument for a name of MAPS.
timing_inputs() {
	if [ "$MODE" = tiny ]; then
		FRP=$TOP/data/default.frd
	else
		FRP=$CACHE/default-all.frp
		cached "$FRP" frd-prep -q -a all "$TOP/data/default.frd"
	fi
	envb=$(basename "$ENVMAP")
	ENV128=$CACHE/${envb%.*}-128-equirect.exr
	case " $1 " in
	*" env "*) cached "$ENV128" imap convert -q -s 128x128 --equirect \
	    --format exr "$ENVMAP" - ;;
	esac
}

mapin() {
	if [ "$1" = env ]; then echo "$ENV128"; else echo "$1"; fi
}

# mean_points FILE...: the mean point count of binary .pts files, from
# their headers (the count is the 8 bytes at offset 24).
mean_points() {
	for f in "$@"; do
		od -A n -t u8 -j 24 -N 8 "$f"
	done | awk '{ t += $1; c++ } END { printf "%.1f", t / c }'
}

# split_frs DIR ARGS...: the sets of "frs-sample ARGS" (with --sets) as
# per-set text files DIR/s00001.txt, ... (each with its header line, so
# extra columns keep their meaning), listed.  FRS sets vary in size with
# the seed: a --count-only run of the same ARGS gives the sizes.
split_frs() {
	sdir=$1
	shift
	mkdir -p "$sdir"
	frs-sample -q "$@" --count-only >"$sdir/counts"
	frs-sample -q "$@" -T |
	    awk -v dir="$sdir" 'NR == FNR { c[++k] = $1; next }
		/^#pts / { h = $1 " " $2 " " $3; next }	# dims, extra
		/^#/ { next }
		{ while (left == 0) { s++; left = c[s]
		      f = sprintf("%s/s%05d.txt", dir, s)
		      if (h != "") print h " count=" left > f }
		  print > f; left--
		  if (left == 0) close(f) }' "$sdir/counts" -
	ls "$sdir"/s*.txt
}

# set_points A B: the mean point count of the SETS sets that the
# experiment's own function "pts A B SEED" names.
set_points() {
	mean_points $(for seed in $(seq 1 $SETS); do pts $1 $2 $seed; done)
}

# The radial statistics of the DDA experiments (fig4.4, fig4.5-4.6): awk
# rules over rows "sampler param distance power anisotropy" (header
# first) that keep, per sampler and param (key, in order[1..no], names
# nm[] and pm[]): the peak beyond 0.3 spacings (pk, at pd), the summed
# anisotropy from 0.5 to 6 spacings (an over na), every value val[key,d],
# and dart's distances up to 6 spacings (ds[1..nd]); np[] from -v
# pts_list "sampler:param:points ...".  The experiment adds its END.
RADIAL_AWK='
	BEGIN { k = split(pts_list, a, " "); for (i = 1; i <= k; i++) { split(a[i], b, ":"); np[b[1] SUBSEP b[2]] = b[3] } }
	NR == 1 { next }
	{
		key = $1 SUBSEP $2
		if (!(key in seen)) { seen[key] = 1; order[++no] = key; nm[key] = $1; pm[key] = $2 }
		d = $3 + 0; p = $4 + 0
		val[key, d] = p
		if (d >= 0.3 && p > pk[key]) { pk[key] = p; pd[key] = d }
		if (d >= 0.5 && d <= 6) { an[key] += $5; na[key]++ }
		if (d <= 6 && $1 == "dart") ds[++nd] = d
	}'

# awk function best(lo, hi) over the annuli f[1..n] with powers p[]: the
# annulus of the highest power in [lo, hi), that power left in bp (the
# radial peaks of fig6.9 and fig6.10-6.11).
BEST_AWK='
	function best(lo, hi,   i, bf) {
		bp = -1; bf = -1
		for (i = 1; i <= n; i++)
			if (f[i] >= lo && f[i] < hi && p[i] > bp) { bp = p[i]; bf = f[i] }
		return bf
	}'

# dda_grid PNG COLS TITLE: the preamble of a gnuplot page of DDA pictures
# (2 rows of COLS, +-6 spacings); then dda_img FILE TITLE for each.
dda_grid() {
	gp_png "$1"
	echo "set terminal png size $((170 * $2)),380 font ',9'"
	echo "set multiplot layout 2,$2 title '$3'"
	echo "unset key; unset tics; unset border; set size ratio -1"
	echo "h = 12./128; set xrange [-6:6]; set yrange [-6:6]"
}
dda_img() {
	echo "set title '$2'; plot '$1' binary filetype=png dx=h dy=h origin=(-12,-12) with rgbimage notitle"
}

# gp_png FILE: the preamble of a gnuplot script writing a PNG.
gp_png() {
	echo "set terminal png size 900,600 font ',10'"
	echo "set output '$1'"
	echo "set datafile separator '\t'"
	echo "set key autotitle columnhead"
}

# row "what" "ours" "thesis": a line of the summary table.
row() {
	[ -s "$OUT/rows.md" ] || {
		echo "| what | ours | thesis |"
		echo "| --- | --- | --- |"
	} >"$OUT/rows.md"
	echo "| $1 | $2 | $3 |" >>"$OUT/rows.md"
}

# exp_end VERDICT "why": reproduced, differs or not reproducible here.
exp_end() {
	t1=$(date +%s.%N)
	secs=$(awk -v a="$EXP_T0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
	{
		cat "$OUT/head.md"
		for f in "$OUT"/*.png; do
			[ -e "$f" ] && echo "![$ID]($ID/$(basename "$f"))" && echo
		done
		[ -s "$OUT/rows.md" ] && cat "$OUT/rows.md" && echo
		echo "**Verdict: $1.** $2"
		echo
		echo "Time: $secs s ($MODE mode)."
		echo
	} >"$OUT/summary.md"
	rm -f "$OUT/head.md" "$OUT/rows.md"
	echo "$ID: $1 ($secs s)" >&2
}
