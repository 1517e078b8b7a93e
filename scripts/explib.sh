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
#   FRS_MATRIX, FRS_MATRIX3
#            the matrices frs-sample uses (default data/default.frd and
#            data/default3.frd)
#   SSH      the ssh command GNU parallel runs for SSHLOGIN (default ssh)
set -eu
TOP=$(cd "$(dirname "$0")/.." && pwd)
MODE=${MODE:-quick}
BIN=${BIN:-$TOP/bin}
RES=${RES:-$TOP/results}
JOBS=${JOBS:-$(nproc)}
ENVMAP=${ENVMAP:-$TOP/data/sunset.exr}
FRS_MATRIX=${FRS_MATRIX:-$TOP/data/default.frd}
FRS_MATRIX3=${FRS_MATRIX3:-$TOP/data/default3.frd}
CACHE=$RES/cache
PATH=$BIN:$PATH
export PATH BIN RES MODE JOBS CACHE ENVMAP TOP FRS_MATRIX FRS_MATRIX3
mkdir -p "$CACHE"
# ID: the experiment, for the cache's miss log before exp_begin sets it
# (and in the child shells of par_run, which inherit it).
if [ -z "${ID:-}" ]; then
	ID=$(basename "$0" .sh)
	ID=${ID#exp-}
fi
export ID

case $MODE in
tiny | quick | full) ;;
*) echo "explib: MODE must be tiny, quick or full" >&2; exit 2 ;;
esac

# The environment map of Table 6.1 and Figs. 6.10-6.11, one setup for
# both: ENVMAP resampled to ENV_SIZE for every tool (env_map: the words
# after -i).  Square, as the thesis's light probe (an angular map) is: FRS
# spaces its points evenly in pixels, so on a 2:1 map they would be
# anisotropic in the unit square that the DDA measures.  env_setup, in an
# experiment that uses it, states it once for the report (report.sh) and
# points there from the experiment's setup notes.
ENV_SIZE=256x256
env_map() { echo "$ENVMAP -s $ENV_SIZE"; }
env_setup() {
	mkdir -p "$RES/.setup"
	printf '%s\n' "Environment map (Table 6.1, Figs. 6.10-6.11): $(basename "$ENVMAP") resampled to $ENV_SIZE for every tool (-i $(basename "$ENVMAP") -s $ENV_SIZE), square as the thesis's light probe (an angular map) is, so that FRS's evenly spaced pixels are not stretched 2:1 in the unit square the DDA measures; not the thesis's Grace Cathedral probe." \
	    >"$RES/.setup/env.txt"
	exp_note "Environment map: the report's environment setup ($(basename "$ENVMAP") at $ENV_SIZE; see the top of the report)."
}

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
	printf 'claim\tours\tresult\tcause\tcondition\n' >"$OUT/checks.tsv"
	rm -f "$OUT/observed.txt" "$OUT/hw.txt" "$OUT/notes.txt"
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

# ---- the cache: results keyed by content ------------------------------
#
# A cached file FILE keeps FILE.key, a checksum of everything that made
# it: the mode, the command's words, the content of every word that is a
# file (inputs, and outputs of earlier cached steps), of every program
# the command runs, and of the matrix frs-sample reads; for a
# shell function, also its text and that of the functions it calls, so
# that editing a script's prose recomputes nothing.  A function must
# therefore take what it reads as words (or name its output after its
# parameters, as the scripts do).  A rerun
# with the same key reuses FILE; touch or cp -p change nothing; any
# changed content recomputes exactly what depends on it.  Every miss is
# a line "ID FILE" in $CACHE/misses (t_experiments counts them).

# file_sum FILE: the checksum of FILE's content, memoised in
# $CACHE/sums by path, size, inode and time (so it is read once).
file_sum() {
	_st="$1|$(stat -L -c '%s %i %y' "$1")"
	_h=$(awk -F '\t' -v k="$_st" '$1 == k { print $2; exit }' \
	    "$CACHE/sums" 2>/dev/null) || :
	if [ -z "$_h" ]; then
		_h=$(sha1sum <"$1" | cut -c 1-40)
		printf '%s\t%s\n' "$_st" "$_h" >>"$CACHE/sums"
	fi
	echo "$_h"
}

# fn_body CMD...: the text of shell function CMD's first word and of
# every function of the script and explib.sh that it calls, in turn
# (each function from "NAME() {" to the first "}" alone on a line, the
# script's before explib's; a name joined to a "-" is an option or part
# of a program's name, awk -v or pts-render, not a call); the command
# itself when it is no function (sh -c "...").
fn_body() {
	awk -v start="$1" '
	FNR == 1 { on = "" }
	on == "" && match($0, /^[A-Za-z_][A-Za-z0-9_]*\(\) *\{/) {
		on = substr($0, 1, index($0, "(") - 1)
		if (on in text) { on = ""; next }	# the script wins
		text[on] = ""
	}
	on != "" { text[on] = text[on] $0 "\n"; if ($0 ~ /^}/) on = "" }
	END {
		if (!(start in text)) exit 1
		todo[1] = start; nt = 1; seen[start] = 1
		for (i = 1; i <= nt; i++) {
			t = text[todo[i]]
			printf "%s", t
			for (f in text)
				if (!(f in seen) && t ~ ("(^|[^A-Za-z0-9_-])" f "([^A-Za-z0-9_-]|$)")) {
					seen[f] = 1; todo[++nt] = f
				}
		}
	}' "$0" "$TOP/scripts/explib.sh" || printf '%s\n' "$@"
}

# cache_key FILE CMD...: the key of CMD making FILE (see above).  Words
# named like FILE (its path up to the extension, then another one) are
# the step's own further outputs (a --png beside the table), not inputs.
# The programs a command runs: those of BIN it names or, for a shell
# function, those its text and the functions it calls name (fn_body).
cache_key() {
	_s=${1%.*}
	shift
	if [ -x "$BIN/$1" ]; then
		_progs=$(for _w in "$@"; do [ -x "$BIN/$_w" ] && echo "$_w"; done; :)
		_code=
	else
		fn_body "$@" >"$CACHE/.body.$$"
		_code=$(sha1sum <"$CACHE/.body.$$" | cut -c 1-40)
		_progs=$(for _p in "$BIN"/*; do
			grep -q -w -F -e "${_p##*/}" "$CACHE/.body.$$" && echo "${_p##*/}"
		done; :)
		rm -f "$CACHE/.body.$$"
	fi
	{
		echo "mode $MODE"
		printf 'word %s\n' "$@"
		for _w in "$@"; do
			case $_w in "$_s".*) continue ;; esac
			[ -f "$_w" ] && echo "file $(file_sum "$_w")"
		done
		[ -n "$_code" ] && echo "code $_code"
		for _p in $_progs; do
			echo "prog $_p $(file_sum "$BIN/$_p")"
			case $_p in
			frs-sample | frd-prep)
				for _m in ${EXP_MATRIX:-$FRS_MATRIX}; do
					echo "matrix $(file_sum "$_m")"
				done ;;
			esac
		done
	} | sha1sum | cut -c 1-40
}

# cached FILE CMD...: FILE is CMD's standard output, made only when its
# key changed; written atomically, the key last.
cached() {
	_f=$1
	_k=$(cache_key "$@")
	shift
	if [ -s "$_f" ] && [ "$(cat "$_f.key" 2>/dev/null)" = "$_k" ]; then
		return 0
	fi
	mkdir -p "$(dirname "$_f")"
	echo "$ID $_f" >>"$CACHE/misses"
	"$@" >"$_f.tmp.$$"
	mv -f "$_f.tmp.$$" "$_f"
	echo "$_k" >"$_f.key.tmp.$$"
	mv -f "$_f.key.tmp.$$" "$_f.key"
}

# J FILE CMD...: a par_run line running explib's cached in a child shell
J="sh -c '. \"\$0\"; cached \"\$@\"' $TOP/scripts/explib.sh"

# par_run: run the shell commands on standard input, one a line, with GNU
# parallel on JOBS cores (or the SSHLOGIN hosts); stops at the first
# failure.
par_run() {
	if [ -n "${SSHLOGIN:-}" ]; then
		parallel --will-cite --halt now,fail=1 --sshlogin "$SSHLOGIN" \
		    --ssh "${SSH:-ssh}" --workdir "$TOP" --env PATH --env MODE \
		    --env RES --env BIN --env ENVMAP --env FRS_MATRIX \
		    --env FRS_MATRIX3 --env ID
	else
		parallel --will-cite --halt now,fail=1 -j "$JOBS"
	fi
}

# job_lock, alone, together: a par_run job of a timing experiment calls
# job_lock first (a shared lock of the experiment's jobs), alone before
# what it times and together after it, so that a timed part never runs
# beside another job of the experiment (make runs the experiment itself
# beside no other; mk/experiments.mk).
job_lock() {
	exec 9>"$CACHE/.$ID.lock"
	flock -s 9
}
alone() {
	flock -x 9
}
together() {
	flock -s 9
}

# timing_inputs MAPS: the inputs of the timing experiments.  FRP is the
# default matrix prepared with frd-prep -a all (tiny mode: the .frd
# itself; only the untimed setup differs), ENV128 the environment map at
# 128x128 with the sin(theta) weight when MAPS holds env; mapin NAME gives
# the map argument for a name of MAPS.
timing_inputs() {
	if [ "$MODE" = tiny ]; then
		FRP=$FRS_MATRIX
	else
		FRP=$CACHE/default-all.frp
		cached "$FRP" frd-prep -q -a all "$FRS_MATRIX"
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

# mkey MAP: the map's name in the cache files (env: $ENVMAP's base name).
mkey() {
	if [ "$1" = env ]; then
		mk_=$(basename "$ENVMAP")
		echo "${mk_%.*}"
	else
		echo "$1"
	fi
}

# window_over FILE LIM: the window that frs-sample -v reported in FILE
# has more than 2^LIM elements (the slow algorithms are not timed there).
window_over() {
	_w=$(sed -n 's/.* window \([0-9]*\)x\([0-9]*\) .*/\1 \2/p' "$1" | head -n 1)
	awk -v w="$_w" -v l="$2" 'BEGIN { split(w, a, " "); exit !(a[1] * a[2] > 2^l) }'
}

# compare_thesis ALGOS FMT HEADER: ours beside the thesis wherever both
# $OUT/thesis.tsv and $OUT/avg.tsv have a value, sorted by algorithm and
# n, under HEADER: "log2n algo ours ours' thesis thesis/ours", ALGOS the
# columns of both from the third on, ours' the column |ALGOS| further in
# avg.tsv, the ratio in printf format FMT ("-" where one is 0).
compare_thesis() {
	awk -F'\t' -v algos="$1" -v fmt="$2" '
	BEGIN { na = split(algos, A, " ") }
	FNR == 1 { next }
	NR == FNR { for (i = 3; i <= na + 2; i++) th[$1, i] = $i; next }
	{
		for (i = 3; i <= na + 2; i++) {
			if (!(($1, i) in th) || th[$1, i] == "-" || $i == "-") continue
			r = ($i > 0 && th[$1, i] > 0) ? sprintf(fmt, th[$1, i] / $i) : "-"
			printf "%d\t%s\t%s\t%s\t%s\t%s\n", $1, A[i - 2], $i, $(i + na), th[$1, i], r
		}
	}' "$OUT/thesis.tsv" "$OUT/avg.tsv" |
	    { printf '%s\n' "$3"; sort -k2,2 -k1,1n; }
}

# get LOG2N COLUMN, thv LOG2N COLUMN: a value of $OUT/avg.tsv, of
# $OUT/thesis.tsv; pretty ALGO: the algorithm's name in the thesis;
# ratio A B: A / B, "-" where either is missing or B is 0.
get() { awk -F'\t' -v e="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i } NR > 1 && $1 == e { print $k }' "$OUT/avg.tsv"; }
thv() { awk -F'\t' -v e="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i } NR > 1 && $1 == e { print $k }' "$OUT/thesis.tsv"; }
pretty() {
	case $1 in
	naive) echo Naive ;; level1) echo "Level 1" ;; flat1) echo "Flat 1" ;;
	stack) echo Stack ;; sorted) echo Sorted ;; hsw) echo HSW ;; *) echo "$1" ;;
	esac
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b == "" || a == "-" || b == "-" || b + 0 == 0) print "-"; else printf "%.3g", a / b }'; }

# mean_points FILE...: the mean point count of binary .pts files, from
# their headers (the count is the 8 bytes at offset 24).
mean_points() {
	for f in "$@"; do
		od -A n -t u8 -j 24 -N 8 "$f"
	done | awk '{ t += $1; c++ } END { printf "%.1f", t / c }'
}

# split_frs DIR ARGS...: the sets of "frs-sample ARGS" (with --sets) as
# per-set text files DIR/s00001.txt, ... (set i in s<i+1>, each with its
# header line, so extra columns keep their names), listed.  FRS sets vary
# in size with the seed: the set column of the output (pts(5)) tells
# them apart; it is left out of the files.
split_frs() {
	sdir=$1
	shift
	mkdir -p "$sdir"
	frs-sample -q "$@" -T |
	    awk -v dir="$sdir" '
		/^#pts / {	# dims and names; the set column is sc (0: none)
			for (i = 2; i <= NF; i++) {
				split($i, kv, "=")
				if (kv[1] == "dims") d = kv[2]
				if (kv[1] == "names") nn = split(kv[2], nm, ",")
			}
			sc = 0
			keep = ""
			for (i = 1; i <= nn; i++)
				if (nm[i] == "set") sc = d + i
				else keep = keep (keep == "" ? "" : ",") nm[i]
			h = "#pts dims=" d " extra=" (nn - (sc > 0)) " version=2"
			if (keep != "") h = h " names=" keep
			next }
		/^#/ { next }
		{ s = sc ? $sc + 1 : 1
		  if (s != cur) {
			if (f != "") close(f)
			cur = s
			f = sprintf("%s/s%05d.txt", dir, s)
			print h > f
		  }
		  if (sc) {
			l = ""
			for (i = 1; i <= NF; i++)
				if (i != sc) l = l (l == "" ? "" : " ") $i
			print l > f
		  } else
			print > f }'
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
# pts_list "sampler:param:points ..."; beyond(key) gives the strongest
# value past 2 spacings.  The experiment adds its END.
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
	}
	# beyond(key): over dart'"'"'s annuli from 2.2 spacings on, the strongest
	# value of key (left in sp, at sq) and its RMS deviation from the
	# Poisson level 1 (sdv): a ring there that dart lacks is the matrix'"'"'s
	function beyond(key,   j, d, u2, nu) {
		sp = -1; u2 = 0; nu = 0
		for (j = 1; j <= nd; j++) {
			d = ds[j]
			if (d < 2.2) continue
			if (val[key, d] > sp) { sp = val[key, d]; sq = d }
			u2 += (val[key, d] - 1) ^ 2; nu++
		}
		sdv = sqrt(u2 / nu)
	}'

# dda_line NAME SETOPT FILES...: the par_run line of the DDA of the sets
# of the fig4 experiments (dda --dda, one image of all FILES): radial
# statistics cached in $C/NAME.tsv, the image $C/NAME.png (made again
# when it is missing).
dda_line() {
	name=$1 so=$2
	shift 2
	[ -s "$C/$name.png" ] || rm -f "$C/$name.tsv"
	printf '%s %s sh -c '\''dda --dda -q -j 1 %s --radial "$0.r" --png %s -o /dev/null "$@" && cat "$0.r" && rm -f "$0.r"'\'' %s %s\n' \
	    "$J" "$C/$name.tsv" "$so" "$C/$name.png" "$C/$name" "$*"
}

# jit_name JITTER: the sampler's name in the fig4 tables (none: frs).
jit_name() { [ "$1" = none ] && echo frs || echo frs-jitter; }

# The uniform FRS sets of Sec. 4.7, shared by Figs. 4.4 to 4.6: N points
# at sparsity SIG on a constant map of 32 SIG pixels a side.
# fig4_pts SM SIG JIT SEED: the file of a set with the S_M matrix.
fig4_pts() { echo "$CACHE/fig4/frs-m$1-sig$2-map$((32 * $2))-n$N-$3-S$4.pts"; }
# fig4_jobs SM SIG MATRIX: par_run's lines for SETS sets, FRS and
# jittered FRS, from the S_M matrix in the file MATRIX.
fig4_jobs() {
	for _jit in none random; do
		for _seed in $(seq 1 $SETS); do
			echo "$J $(fig4_pts $1 $2 $_jit $_seed) frs-sample -q -j 1 -m $3 -i const -s $((32 * $2))x$((32 * $2)) --sigma $2 --jitter $_jit -n $N -S $_seed"
		done
	done
}

# rad SAMPLER PARAM FILE: the rows of radial.tsv (sampler param dist
# power aniso_db) from a DDA's radial statistics.
rad() {
	awk -F '\t' -v n="$1" -v s="$2" 'NR > 1 { printf "%s\t%s\t%s\t%s\t%s\n", n, s, $1, $2, $3 }' "$3"
}

# radial_pts PARAMS: the pts_list of RADIAL_AWK for FRS and jittered FRS
# at each PARAM, from the experiment's set_points.
radial_pts() {
	for jit in none random; do for p in $1; do
		printf '%s:%s:%s ' "$(jit_name $jit)" $p "$(set_points $p $jit)"
	done; done
}

# radial_stats HEADER PARAMS RULES: $OUT/stats.tsv, the line HEADER
# (printf %b) over what RADIAL_AWK followed by the experiment's RULES
# (its END) makes of $OUT/radial.tsv, FRS and jittered FRS at PARAMS.
radial_stats() {
	{
		printf '%b\n' "$1"
		awk -F '\t' -v sets=$SETS -v n=$N -v pts_list="$(radial_pts "$2")" "$RADIAL_AWK$3" "$OUT/radial.tsv"
	} >"$OUT/stats.tsv"
}

# st SAMPLER PARAM COLUMN: a value of the experiment's stats.tsv.
st() { awk -F '\t' -v n="$1" -v s="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next } $1 == n && $2 == s { print $col[c] }' "$OUT/stats.tsv"; }

# dart_limit: the height of a ring beyond 2 spacings that dart throwing
# lacks, dart's strongest value there plus 2 of its deviations from 1.
dart_limit() {
	awk -v a="$(st dart 0 spike)" -v b="$(st dart 0 sd_beyond2)" 'BEGIN { printf "%.4f", a + 2 * b }'
}

# dda_sets BASE DIST MAP: the par_run line of the DDA (dda --dda, images
# of 2K+1 pixels a side) on MAP of the M sets of N points of DIST, in
# BASE-DIST-nN-S<seed>.pts (ref: all in BASE-ref-nN-mM.pts); it writes
# BASE-DIST-nN-mM-KK.tsv, .png and .rad.
dda_sets() {
	if [ "$2" = ref ]; then
		_files="--sets $N $1-ref-n$N-m$M.pts"
	else
		_files=$(for s in $(seq 1 "$M"); do printf ' %s' "$1-$2-n$N-S$s.pts"; done)
	fi
	_b=$1-$2-n$N-m$M-K$K
	echo "$J $_b.tsv dda -q -j 1 --dda -i $3 --size $K --png $_b.png --radial $_b.rad $_files"
}

# dda_copy BASE DIST NAME: dda_sets' radial statistics and image as
# $OUT/radial-NAME.tsv and $OUT/dda/NAME.png.
dda_copy() {
	cp "$1-$2-n$N-m$M-K$K.rad" "$OUT/radial-$3.tsv"
	cp "$1-$2-n$N-m$M-K$K.png" "$OUT/dda/$3.png"
}

# gp_page FILE SIZE FONT LAYOUT TITLE: the preamble of a gnuplot page of
# pictures: SIZE "width,height", LAYOUT "rows,columns".
gp_page() {
	gp_png "$1"
	echo "set terminal png size $2 font ',$3'"
	echo "set output '$1'"
	echo "set multiplot layout $4 title '$5'"
}

# gp_pictures: images at their aspect, without key, tics or border.
gp_pictures() {
	echo "unset key; set size ratio -1; unset xtics; unset ytics; unset border"
}

# gp_centre K: the centre of a DDA image of 2K+1 pixels a side, +-3 of
# its +-12 spacings.
gp_centre() {
	echo "set xrange [$(($1 - $1 / 4)):$(($1 + $1 / 4))]; set yrange [$(($1 - $1 / 4)):$(($1 + $1 / 4))]"
}

# frd_param KEY: the value of KEY in the parameters of FRS_MATRIX's
# header (empty when it has none).
frd_param() {
	LC_ALL=C head -c 4096 "$FRS_MATRIX" | tr '\000' '\n' | sed -n "s/^$1=//p" | head -n 1
}

# cut_radius SPACING: where the force of FRS_MATRIX was cut off for points
# SPACING cells apart, R = min(cap S, max(reach SPACING, R_eps)) cells
# (frd-gen(1)), from its header: "R R/SPACING", or 0 when the header does
# not give it.
cut_radius() {
	awk -v f="$(frd_param force)" -v s="$(frd_param s)" -v q="$(frd_param q)" -v t="$(frd_param tol)" \
	    -v r="$(frd_param reach)" -v c="$(frd_param cap)" -v sz="$(frd_param size)" -v sp="$1" '
	BEGIN {
		split(sz, d, "x"); S = (d[2] + 0 < d[1] + 0) ? d[2] : d[1]
		if (f == "power") re = s * (t ^ (-1 / q) - 1)
		else if (f == "exp") re = s * (log(1 / t)) ^ (1 / q)
		else { print 0; exit }
		R = r * sp; if (re > R) R = re
		if (c > 0 && c * S < R) R = c * S
		printf "%.1f %.2f\n", R, R / sp
	}'
}

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

# gp_loglog: axes for times against n ("-" missing), powers of 2 and 10.
gp_loglog() {
	echo "set datafile missing '-'"
	echo "set logscale x 2"
	echo "set logscale y 10"
	echo "set format x '2^{%L}'"
	echo "set format y '10^{%L}'"
}

# row "what" "ours" "thesis": a line of the summary table.
row() {
	[ -s "$OUT/rows.md" ] || {
		echo "| what | ours | thesis |"
		echo "| --- | --- | --- |"
	} >"$OUT/rows.md"
	echo "| $1 | $2 | $3 |" >>"$OUT/rows.md"
}

# ---- verdicts computed from the run ----------------------------------
#
# Every claim of the thesis that an experiment tests is a check on this
# run's numbers; the verdict is computed from the checks alone:
# "reproduced" when every check holds, "differs" when one fails, and
# "not comparable" when the claim is about hardware we lack (exp_hw).
# A failed check of an order (check_order: A beats B) is a reversal of
# the thesis, named in the verdict's first sentence.  The experiments of
# OWN_CLAIMS test claims of ours that the thesis does not make: their
# verdict is "confirmed" or "not confirmed", and the report gives them a
# section of their own.
OWN_CLAIMS="3d mc vac"
own_claim() {
	case " $OWN_CLAIMS " in *" $1 "*) return 0 ;; esac
	return 1
}

# holds EXPR: the awk condition EXPR (numbers already in it) is true.
holds() {
	awk "BEGIN { exit !($1) }" </dev/null
}

# check "claim" "ours" EXPR ["cause"]: a claim of the thesis, our value
# and the condition on it; the cause, if known, is said when it fails.
check() {
	_check fails "$@"
}

# check_order "claim" "ours" EXPR ["cause"]: a claim that one method
# beats another; when it fails, the thesis is reversed here.
check_order() {
	_check reversed "$@"
}

# checks.tsv: claim, ours, result, the cause (when it fails) and the
# condition as tested, its numbers in it: the tolerance the report prints
# beside the check.
_check() {
	if holds "$4"; then _st=holds; else _st=$1; fi
	printf '%s\t%s\t%s\t%s\t%s\n' "$2" "$3" "$_st" "${5:-}" "$4" >>"$OUT/checks.tsv"
}

# observe EXPR "sentence": a sentence of the verdict that holds only
# when EXPR does (a cause or a finding measured in this run).
observe() {
	if holds "$1"; then
		printf '%s\n' "$2" >>"$OUT/observed.txt"
	fi
}

# exp_hw "what we measured instead": the thesis measured hardware we
# lack (its GPU); the verdict is "not comparable".
exp_hw() {
	printf '%s\n' "$1" >"$OUT/hw.txt"
}

# exp_note "sentence": a fact of the setup (not a verdict), said before
# the verdict.
exp_note() {
	printf '%s\n' "$1" >>"$OUT/notes.txt"
}

# verdict: the verdict word and text from checks.tsv, observed.txt and
# hw.txt; sets VERDICT and WHY.
verdict() {
	_c=$OUT/checks.tsv
	_nc=$(awk 'END { print NR - 1 }' "$_c")
	_nf=$(awk -F '\t' 'NR > 1 && $3 != "holds"' "$_c" | awk 'END { print NR }')
	_rev=$(awk -F '\t' '$3 == "reversed" { printf "%s%s (ours: %s)", s, $1, $2; s = "; " }' "$_c")
	_bad=$(awk -F '\t' '$3 == "fails" { printf "%s%s (ours: %s%s)", s, $1, $2, ($4 == "" ? "" : "; " $4); s = "; " }' "$_c")
	WHY=
	[ -n "$_rev" ] && WHY="Reversed here: $_rev."
	if [ -s "$OUT/hw.txt" ]; then
		VERDICT="not comparable"
		WHY="${WHY:+$WHY  }Measured on hardware other than the thesis': $(cat "$OUT/hw.txt")."
	elif [ "$_nc" -gt 0 ] && [ "$_nf" = 0 ]; then
		VERDICT=reproduced
	elif [ "$_nc" = 0 ]; then
		VERDICT=differs
		WHY="No claim of the thesis was checked."
	else
		VERDICT=differs
	fi
	if own_claim "$ID"; then
		case $VERDICT in
		reproduced) VERDICT=confirmed ;;
		differs) VERDICT="not confirmed"
		    [ "$_nc" = 0 ] && WHY="No claim was checked." ;;
		esac
	fi
	if [ "$_nc" -gt 0 ]; then
		if [ "$_nf" = 0 ]; then
			WHY="${WHY:+$WHY  }All $_nc checks hold."
		else
			WHY="${WHY:+$WHY  }$_nf of $_nc checks fail${_bad:+: $_bad}."
		fi
	fi
	if [ -s "$OUT/observed.txt" ]; then
		WHY="$WHY  $(tr '\n' ' ' <"$OUT/observed.txt" | sed 's/ *$//')"
	fi
	if [ "$MODE" = tiny ]; then
		WHY="$WHY  (Tiny mode: a smoke test with too few points for the numbers to mean much.)"
	fi
}

# exp_end: the summary: head, pictures, the table of numbers, the
# checks, setup notes and the verdict computed from the checks.
exp_end() {
	_t1=$(date +%s.%N)
	_secs=$(awk -v a="$EXP_T0" -v b="$_t1" 'BEGIN { printf "%.1f", b - a }')
	verdict
	{
		cat "$OUT/head.md"
		for f in "$OUT"/*.png; do
			[ -e "$f" ] && echo "![$ID]($ID/$(basename "$f"))" && echo
		done
		[ -s "$OUT/rows.md" ] && cat "$OUT/rows.md" && echo
		if [ "$_nc" -gt 0 ]; then
			if own_claim "$ID"; then
				echo "| check (our claim) | ours | condition | result |"
			else
				echo "| check (thesis) | ours | condition | result |"
			fi
			echo "| --- | --- | --- | --- |"
			awk -F '\t' 'NR > 1 { c = $5; gsub(/\|/, "\\|", c)
			    printf "| %s | %s | `%s` | %s |\n", $1, $2, c, $3 }' "$OUT/checks.tsv"
			echo
		fi
		if [ -s "$OUT/notes.txt" ]; then
			printf 'Setup: %s\n\n' "$(tr '\n' ' ' <"$OUT/notes.txt" | sed 's/ *$//')"
		fi
		echo "**Verdict: $VERDICT.** $WHY"
		echo
		echo "Time: $_secs s ($MODE mode)."
		echo
	} >"$OUT/summary.md"
	rm -f "$OUT/head.md" "$OUT/rows.md" "$OUT/observed.txt" "$OUT/hw.txt" \
	    "$OUT/notes.txt"
	# the time of this mode's last run, for the report's table
	mkdir -p "$RES/.times"
	echo "$_secs" >"$RES/.times/$ID.$MODE"
	echo "$ID: $VERDICT ($_secs s)" >&2
}
