#!/bin/sh
# discrepancy: what accuracy costs.  (0) the exact L2 star D2 alone, 2-D
# and 3-D, against scipy in-process and against commit 034c211 built
# beside it (scripts/benchlib.sh: baseline_build); (a) the exact L2 star discrepancy
# against the brute-force reference (test/ref/ref_disc.c) and scipy's published
# timings, and the star grid against the reference's summed-area table,
# (b) per class D2 and Dinf against seconds per set, at the
# thesis parameters and cheaper ones, (c) the Fig. 6.3 sweep (star, 6
# distributions, n = 2^2..2^13, 1000 sets), (d) what the sweeps of
# Figs. 6.3-6.8 cost at the thesis parameters, (e) the 3-D star grid
# against the exact 3-D methods.
#   scripts/bench-discrepancy.sh [BUILD]
#   BENCH_QUICK=1: no 2^20 in (a); in (b) sets predicted to take over 3 s
#   are estimated from a cheaper setting; 50 sets in (c), scaled to 1000.
set -eu
BUILD=${1:-build/rel}
DISC=$BUILD/bin/discrepancy
GEN=$BUILD/bin/ref-sample
REF=$BUILD/test/ref_disc
. "$(dirname "$0")/benchlib.sh"
bench_setup bench-discrepancy "$DISC" "$GEN" "$REF"
if [ -n "${BENCH_QUICK:-}" ]; then
	AN="10 13 16" LIM=3 M=50
else
	AN="10 13 16 20" LIM=1000000 M=1000
fi
REFLIM=60	# (a): the reference only where it takes up to REFLIM s
DTOL=10		# (c): grid Dinf error allowed at n = 8192, per cent

# timerep OUT CMD...: as timed, repeated to fill about 0.5 s (at most
# 20 runs, timed together); SEC is the mean per run.
timerep() {
	timed "$@"
	reps=$(awk -v s="$SEC" 'BEGIN { r = int(0.5 / (s + 1e-6)); print (r > 20 ? 20 : r) }')
	if [ "$reps" -gt 1 ]; then
		out=$1
		shift
		i=0
		t0=$(now)
		while [ $i -lt "$reps" ]; do
			"$@" >"$out"
			i=$((i + 1))
		done
		t1=$(now)
		SEC=$(awk -v a="$t0" -v b="$t1" -v r="$reps" \
		    'BEGIN { printf "%.6f", (b - a) / r }')
	fi
}

# The last row's column C of a discrepancy table.
field() { tail -n 1 "$1" | cut -f "$2"; }
# Points in one of M sets of FILE (regular and jittered round n).
perset() { echo $(( $(od -A n -t u8 -j 24 -N 8 "$1" | tr -d ' ') / $2 )); }

# ---------------------------------------------------------------- (0)
# The exact L2 star D2 alone (issue 22): ours (--exact --d2-only) against
# scipy.stats.qmc.discrepancy(method='L2-star', workers=1) timed inside
# Python on the same points, and against the programs of BASE, the
# commit the issue starts from, built beside ours (baseline_build).
BASE=034c211
SCIPYLIM=60	# scipy only where predicted (n^2) to take up to SCIPYLIM s
BASELIM=60	# the baseline likewise (its D2 is O(n^2) in 3-D)
cat >"$T/sp.py" <<'PY'
import sys, time
try:
    import numpy as np
    from scipy.stats import qmc
except Exception:
    print("unavailable")
    sys.exit(0)
if sys.argv[1] == "probe":
    print("ok")
    sys.exit(0)
x = np.loadtxt(sys.argv[1], comments="#", ndmin=2)[:, :int(sys.argv[2])]
best = None
for _ in range(int(sys.argv[3])):
    t = time.perf_counter()
    v = qmc.discrepancy(x, method="L2-star", workers=1)
    t = time.perf_counter() - t
    best = t if best is None or t < best else best
print("%.6f %.17g" % (best, v))
PY
if BB=$(baseline_build $BASE); then BDISC=$BB/discrepancy; else BDISC=""; fi
SCIPY=$(python3 "$T/sp.py" probe 2>/dev/null || echo unavailable)
echo "discrepancy: exact L2 star D2 alone, halton points, one thread, whole process"
echo "(ours: --exact --d2-only -j 1; scipy: qmc.discrepancy L2-star workers=1,"
echo " in-process, the best of 2 (1 above 5 s); base: $BASE built beside ours,"
echo " which has no --d2-only: base_exact is its --exact (D2 and the exact Dinf),"
echo " base_d2 its --exact --grid 2 (D2 and a 2x2 grid's Dinf, its cheapest D2)"
[ "$SCIPY" = unavailable ] && echo " scipy not available: its columns are left out"
[ -z "$BDISC" ] && echo " the baseline did not build: its columns are left out"
printf '%-4s %-8s %9s %10s %9s %11s %10s %8s %-14s %-6s %9s\n' dims n ours_s \
    scipy_s vs_scipy base_exact_s base_d2_s vs_base target result D2_vs_sp
sprev="" snprev="" bprev="" bnprev=""
if [ -n "${BENCH_QUICK:-}" ]; then Z2="16" Z3="12 16"; else Z2="16 20" Z3="12 16 20"; fi
for dn in $(for e in $Z2; do echo 2:$e; done; for e in $Z3; do echo 3:$e; done); do
	d=${dn%:*} n=$((1 << ${dn#*:}))
	f=$T/z.pts
	"$GEN" -q -d $d -k halton -n $n -S 1 -o "$f"
	timerep "$T/o" "$DISC" -q -j 1 --exact --d2-only "$f"
	ours=$SEC d2=$(field "$T/o" 4)
	if [ "$d" != "${dprev:-}" ]; then sprev="" snprev="" dprev=$d; fi
	sp=- spv=""
	if [ "$SCIPY" != unavailable ]; then
		pred=$(awk -v r="$sprev" -v a="$snprev" -v n=$n \
		    'BEGIN { print r == "" ? 0 : r * (n / a) ^ 2 }')
		if awk -v p="$pred" -v l=$SCIPYLIM 'BEGIN { exit !(p <= l) }'; then
			"$GEN" -q -d $d -k halton -n $n -S 1 -T -o "$T/z.txt"
			reps=$(awk -v p="$pred" 'BEGIN { print (p > 5 ? 1 : 2) }')
			set -- $(python3 "$T/sp.py" "$T/z.txt" $d $reps)
			sp=$1 spv=$2 sprev=$1 snprev=$n
		else
			sp="~$(awk -v p="$pred" 'BEGIN { printf "%.0f", p }')"
		fi
	fi
	be=- bd=-
	if [ -n "$BDISC" ]; then
		pts_v1 "$f" "$T/zb.pts"	# the base reads version 1 only
		if { [ $d = 2 ] && [ $n -le 65536 ]; } || { [ $d = 3 ] && [ $n -le 4096 ]; }; then
			timerep "$T/b" "$BDISC" -q -j 1 --exact "$T/zb.pts"
			be=$SEC
		fi
		pred=$(awk -v r="$bprev" -v a="$bnprev" -v n=$n -v d=$d \
		    'BEGIN { print r == "" || d == 2 ? 0 : r * (n / a) ^ 2 }')
		if awk -v p="$pred" -v l=$BASELIM 'BEGIN { exit !(p <= l) }' &&
		    "$BDISC" -q -j 1 --exact --grid 2 "$T/zb.pts" >"$T/b" 2>/dev/null; then
			timerep "$T/b" "$BDISC" -q -j 1 --exact --grid 2 "$T/zb.pts"
			bd=$SEC
			[ $d = 3 ] && bprev=$SEC bnprev=$n
		else
			# refused at once (its limit), or too slow to run
			rc=0
			timeout 5 "$BDISC" -q -j 1 --exact --grid 2 "$T/zb.pts" \
			    >/dev/null 2>&1 || rc=$?
			if [ $rc = 1 ]; then bd=refused; else
				bd="~$(awk -v p="$pred" 'BEGIN { printf "%.0f", p }')"
			fi
		fi
	fi
	case $d:$n in
	2:65536) tg="<=0.2,>=30x" ;;
	2:1048576) tg="<5" ;;
	*) tg="-" ;;
	esac
	awk -v d=$d -v n=$n -v o="$ours" -v sp="$sp" -v spv="$spv" -v be="$be" \
	    -v bd="$bd" -v tg="$tg" -v d2="$d2" 'BEGIN {
		num = "^[0-9.]+$"
		vs = sp ~ num ? sprintf("%.0f", sp / o) : (sp ~ /^~/ ? "~" sprintf("%.0f", substr(sp, 2) / o) : "-")
		b = bd ~ num ? bd : (be ~ num ? be : "")
		vb = b == "" ? "-" : sprintf("%.0f", b / o)
		if (bd ~ /^~/) vb = "~" sprintf("%.0f", substr(bd, 2) / o)
		res = "-"
		if (tg == "<5") res = o < 5 ? "PASS" : "MISS"
		if (tg ~ /^<=0.2/) res = (o <= 0.2 && (sp !~ num || sp / o >= 30)) ? "PASS" : "MISS"
		rel = spv == "" ? "-" : sprintf("%.1e", (d2 - spv) / spv)
		printf "%-4d %-8d %9.4f %10s %9s %11s %10s %8s %-14s %-6s %9s\n", d, n, o, sp, vs, be, bd, vb, tg, res, rel
	}'
done
echo "(vs_scipy, vs_base: how many times faster than scipy and than base's"
echo " base_d2, or base_exact where base_d2 is missing; ~: predicted from the"
echo " last run, n^2, not run; refused: base's limit; D2_vs_sp: ours, 9 digits,"
echo " against scipy's value)"

echo
# ---------------------------------------------------------------- (a)
echo "discrepancy: exact L2 star discrepancy (Warnock), one thread, halton points"
echo "(ours: -c star --exact --d2-only -j 1, O(n log n); ref: ref_disc"
echo " warnock, the O(n^2) double loop; scipy: qmc.discrepancy L2-star, published)"
printf '%-8s %10s %10s %9s %9s %8s %9s %-6s %10s\n' n ours_s ref_s speedup \
    scipy_s target vs_scipy result D2_reldiff
rprev="" nprev=""
for e in $AN; do
	n=$((1 << e))
	f=$T/a.pts
	"$GEN" -q -k halton -n $n -S 1 -o "$f"
	timerep "$T/o" "$DISC" -q -j 1 -c star --exact --d2-only "$f"
	ours=$SEC
	d2=$(field "$T/o" 4)
	# The reference is O(n^2): predict it from the last size run.
	pred=$(awk -v r="$rprev" -v a="$nprev" -v n=$n \
	    'BEGIN { print r == "" ? 0 : r * (n / a) ^ 2 }')
	if awk -v p="$pred" -v l=$REFLIM 'BEGIN { exit !(p <= l) }'; then
		timerep "$T/r" "$REF" warnock "$f"
		ref=$SEC est=""
		rd2=$(awk '$1 == "D2" { print $2 }' "$T/r")
		rprev=$ref nprev=$n
	else
		ref=$pred est="~" rd2=""
	fi
	case $n in
	8192) sp=0.116 tg=0.05 ;;
	65536) sp=9.7 tg=1 ;;
	*) sp="" tg="" ;;
	esac
	awk -v n=$n -v o="$ours" -v r="$ref" -v est="$est" -v sp="$sp" \
	    -v tg="$tg" -v d="$d2" -v rd="$rd2" 'BEGIN {
		rs = sprintf("%s%.3f", est, r)
		sx = sprintf("%s%.0f", est, r / o)
		if (sp == "") { sps = "-"; tgs = "-"; vs = "-"; res = "-" }
		else {
			sps = sp; tgs = "<=" tg; vs = sprintf("%.1f", sp / o)
			res = o <= tg ? "PASS" : "MISS"
		}
		rel = rd == "" ? "-" : sprintf("%.1e", (d - rd) / rd)
		if (rel == "-0.0e+00") rel = "0"
		printf "%-8d %10.4f %10s %9s %9s %8s %9s %-6s %10s\n", n, o, rs, sx, sps, tgs, vs, res, rel
	}'
done
echo "(~: estimated from the last reference run, n^2; D2_reldiff: ours (9 digits)"
echo " against the reference; vs_scipy: how many times faster than scipy)"

echo
echo "discrepancy: star grid (D2 and Dinf over the s^2 corners), one thread, halton"
echo "(ours: -c star --grid S -j 1; ref: ref_disc stargrid, a full s x s"
echo " summed-area table; rel: largest relative difference of D2 and Dinf)"
printf '%-6s %6s %10s %10s %9s %10s\n' n S ours_s ref_s speedup rel
for n in 256 8192; do
	"$GEN" -q -k halton -n $n -S 1 -o "$T/a.pts"
	for s in 1000 3000; do
		timerep "$T/o" "$DISC" -q -j 1 -c star --grid $s "$T/a.pts"
		ours=$SEC
		timerep "$T/r" "$REF" stargrid $s "$T/a.pts"
		awk -v n=$n -v s=$s -v o="$ours" -v r="$SEC" \
		    -v d="$(field "$T/o" 4)" -v i="$(field "$T/o" 6)" '
			$1 == "D2" { rd = $2 } $1 == "Dinf" { ri = $2 }
			function rel(a, b) { a = (a - b) / b; return a < 0 ? -a : a }
			END {
				x = rel(d, rd); y = rel(i, ri); if (y > x) x = y
				printf "%-6d %6d %10.4f %10.4f %9.1f %10.1e\n", n, s, o, r, r / o, x
			}' "$T/r"
	done
done

# ---------------------------------------------------------------- (b)
# cost CLASS SETTING N: relative work of one set, to predict a setting's
# time from a cheaper one of the same class.
cost() {
	awk -v c=$1 -v s=$2 -v n=$3 'BEGIN {
		if (c == "star") print s * s + n
		else if (c == "rect") print s * s * (s < n ? s : n) + n
		else if (c == "half") print s * log(s) * n
		else print s * n
	}'
}
# args CLASS SETTING N: the discrepancy options of a setting (the exact
# rect Dinf is O(n^3): above 1024 points, Dinf from the 500 grid).
args() {
	case $1:$2 in
	star:exact) echo "--exact" ;;
	rect:exact) if [ "$3" -le 1024 ]; then echo "--exact"; else
		echo "--exact --grid 500"; fi ;;
	star:* | rect:* | half:*) echo "--grid $2" ;;
	*) echo "--shapes $2" ;;
	esac
}

echo
echo "discrepancy: accuracy against time per class, seconds per set on one thread"
echo "(* thesis parameters; err: against the exact value, per cent; ~: estimated"
echo " from the last timed setting, linear in the work, not run)"
printf '%-6s %5s %-7s %-10s %10s %12s %8s %12s %8s\n' class n points \
    setting s/set D2 D2_err% Dinf Dinf_err%
for n in 16 256 8192; do
	for k in halton random; do
		"$GEN" -q -k $k -n $n -S 1 -o "$T/b_${k}_$n.pts"
	done
done
: >"$T/thesis"
: >"$T/starinf"
for cls in star rect half quad circle; do
	case $cls in
	star) sets="exact 250 1000 3000" th=3000 ;;
	rect) sets="exact 100 250 500" th=500 ;;
	half) sets="100 300 1000 3000" th=3000 ;;
	*) sets="10000 100000 1000000 9000000" th=9000000 ;;
	esac
	for n in 16 256 8192; do
		for k in halton random; do
			f=$T/b_${k}_$n.pts
			ed2="" edinf="" last="" lastc=""
			for s in $sets; do
				c=$(cost $cls $s $n)
				pred=$(awk -v t="$last" -v a="$lastc" -v c="$c" \
				    'BEGIN { print t == "" ? 0 : t * c / a }')
				if awk -v p="$pred" -v l=$LIM 'BEGIN { exit !(p <= l) }'; then
					# shellcheck disable=SC2046
					timed "$T/o" "$DISC" -q -j 1 -c $cls $(args $cls $s $n) "$f"
					t=$SEC est="" last=$SEC lastc=$c
					d2=$(field "$T/o" 4) dinf=$(field "$T/o" 6)
				else
					t=$pred est="~" d2="" dinf=""
				fi
				if [ $s = exact ]; then
					# the grids' times are not predicted from it
					ed2=$d2 last="" lastc=""
					if [ $cls = star ] || [ $n -le 1024 ]; then
						edinf=$dinf
					fi
				fi
				if [ $s = $th ]; then
					echo "$cls $n $k $t $est" >>"$T/thesis"
					name="${s}*"
				else
					name=$s
				fi
				if [ $cls = star ] && [ $n = 8192 ] && [ -n "$dinf" ] &&
				    [ $s != exact ]; then
					echo "$s $k $dinf $edinf" >>"$T/starinf"
				fi
				if [ $s = exact ] && [ $cls = rect ] && [ $n -gt 1024 ]; then
					name="exact+500"
				fi
				awk -v c=$cls -v n=$n -v k=$k -v s="$name" -v t="$t" \
				    -v est="$est" -v d2="$d2" -v di="$dinf" -v e2="$ed2" \
				    -v ei="$edinf" 'BEGIN {
					ts = sprintf("%s%.3f", est, t)
					if (t >= 100) ts = sprintf("%s%.0f", est, t)
					d2s = d2 == "" ? "-" : d2; dis = di == "" ? "-" : di
					er2 = (d2 == "" || e2 == "") ? "-" : sprintf("%+.2f", 100 * (d2 - e2) / e2)
					eri = (di == "" || ei == "") ? "-" : sprintf("%+.2f", 100 * (di - ei) / ei)
					printf "%-6s %5d %-7s %-10s %10s %12s %8s %12s %8s\n", c, n, k, s, ts, d2s, er2, dis, eri
				}'
			done
		done
	done
done
echo "(star exact: Warnock D2 and Dinf over the critical boxes, O(n^1.5); rect"
echo " exact: closed-form D2 and Dinf over all boxes, O(n^3); rect exact+500:"
echo " Dinf on the 500 grid; half S: S border points per side; quad, circle K:"
echo " random shapes; grid Dinf is a lower bound)"

# ---------------------------------------------------------------- (c)
# The grid for the sweep: the cheapest star grid of (b) whose Dinf at
# n = 8192 is within DTOL per cent of the exact Dinf for both sets.
S=$(awk -v tol=$DTOL '
	{ e = 100 * ($4 - $3) / $4; if (!($1 in m) || e > m[$1]) m[$1] = e }
	END {
		best = ""
		for (s in m) if (m[s] <= tol && (best == "" || s + 0 < best + 0)) best = s
		print best == "" ? 3000 : best
	}' "$T/starinf")
echo
echo "discrepancy: the Fig. 6.3 sweep, star, 6 distributions x n = 2^2..2^13"
echo "x 1000 sets, $NCPU threads, load average $(cut -d ' ' -f 1 /proc/loadavg) at the start;"
echo "target <= 600 s"
awk -v s="$S" -v tol=$DTOL '
	{ e = 100 * ($4 - $3) / $4; if (!($1 in m) || e > m[$1]) m[$1] = e }
	END {
		printf "(S = %s: the cheapest star grid of (b) whose Dinf at n = 8192 is", s
		printf " within\n %s %% of the exact Dinf for halton and random (", tol
		split("250 1000 3000", gs, " ")
		for (i = 1; i <= 3; i++)
			if (gs[i] in m) printf "%s%s: %.1f %%", (i > 1 ? ", " : ""), gs[i], m[gs[i]]
		printf ");\n %s %% is %.2f decades on the log-log axes of Fig. 6.3", tol, log(1 + tol / 100) / log(10)
		if (s == 3000) printf "; the thesis grid"
		printf ")\n" }' "$T/starinf"
METHODS="exact+grid$S exact"
if [ "$S" != 1000 ]; then METHODS="exact+grid1000 $METHODS"; fi
gen=0
for meth in $METHODS; do echo 0 >"$T/sw_$meth"; done
for k in random regular jittered halton sobol dart; do
	for e in 2 3 4 5 6 7 8 9 10 11 12 13; do
		n=$((1 << e))
		f=$T/sw.pts
		timed /dev/null "$GEN" -q -k $k -n $n --sets $M -S 1 -o "$f"
		gen=$(awk -v a=$gen -v b=$SEC 'BEGIN { print a + b }')
		per=$(perset "$f" $M)
		for meth in $METHODS; do
			case $meth in
			exact) a="" ;;
			*) a="--grid ${meth#exact+grid}" ;;
			esac
			# shellcheck disable=SC2086
			timed "$T/o" "$DISC" -q -c star --exact $a --sets $per "$f"
			awk -v a="$(cat "$T/sw_$meth")" -v b=$SEC \
			    'BEGIN { print a + b }' >"$T/sw_$meth.new"
			mv "$T/sw_$meth.new" "$T/sw_$meth"
			if [ $e = 13 ]; then
				echo "$k $(field "$T/o" 7)" >>"$T/inf_$meth"
			fi
		done
		rm -f "$f"
	done
done
printf '%-15s %5s %10s %12s %7s %-6s %18s\n' method m seconds s_1000_sets \
    target result Dinf_err%@8192
for meth in $METHODS; do
	awk -v m=$M -v meth=$meth -v t="$(cat "$T/sw_$meth")" '
		FNR == NR { ex[$1] = $2; next }
		{ e = 100 * (ex[$1] - $2) / ex[$1]; s += e; if (e > mx) mx = e; c++ }
		END {
			full = t * 1000 / m
			fs = sprintf("%s%.1f", m == 1000 ? "" : "~", full)
			es = sprintf("%.1f / %.1f", s / c, mx)
			printf "%-15s %5d %10.1f %12s %7s %-6s %18s\n", meth, m, t, fs, "600", full <= 600 ? "PASS" : "MISS", es
		}' "$T/inf_exact" "$T/inf_$meth"
done
awk -v m=$M -v g=$gen 'BEGIN {
	printf "generation (ref-sample --sets %d): %.1f s", m, g
	if (m != 1000) printf ", ~%.1f s for 1000 sets", g * 1000 / m
	printf "\n" }'
echo "(~: measured with $M sets and scaled to 1000; Dinf_err: mean / worst over the"
echo " 6 distributions of the mean Dinf at n = 8192 against the exact method;"
echo " the sweep to use is exact: exact D2 and the exact Dinf over the critical"
echo " boxes, O(n^1.5), no grid error and no slower than the grid S)"

# ---------------------------------------------------------------- (d)
echo
echo "discrepancy: the sweeps of Figs. 6.3-6.8 at the thesis parameters, 6"
echo "distributions x n = 2^2..2^13 x 1000 sets, from the seconds per set of (b)"
echo "(mean of halton and random, linear in n between 16, 256 and 8192)"
printf '%-7s %-14s %9s %9s %9s %11s %11s\n' class parameters s@16 s@256 \
    s@8192 cpu_hours "wall_h($NCPU)"
awk -v ncpu=$NCPU '
	{ t[$1, $2] += $4 / 2; if ($5 == "~") est[$1] = 1 }
	function at(c, n) {
		if (n <= 16) return t[c, 16]
		if (n <= 256) return t[c, 16] + (t[c, 256] - t[c, 16]) * (n - 16) / 240
		return t[c, 256] + (t[c, 8192] - t[c, 256]) * (n - 256) / 7936
	}
	END {
		split("star rect half quad circle", cl, " ")
		split("grid 3000|grid 500|3000/side|9e6 shapes|9e6 shapes", pa, "|")
		for (i = 1; i <= 5; i++) {
			c = cl[i]; sum = 0
			for (e = 2; e <= 13; e++) sum += at(c, 2 ^ e)
			h = sum * 6 * 1000 / 3600
			mk = est[c] ? "~" : ""
			printf "%-7s %-14s %9.3f %9.3f %9.3f %11s %11s\n", c, pa[i], t[c, 16], t[c, 256], t[c, 8192], sprintf("%s%.2f", mk, h), sprintf("%s%.2f", mk, h / ncpu)
		}
	}' "$T/thesis"
echo "(~: some sets estimated in (b); wall hours assume the sets spread evenly"
echo " over $NCPU cores, as discrepancy --sets does)"

# ---------------------------------------------------------------- (e)
echo
echo "discrepancy: 3-D star (ref-sample -d 3), one thread: the grid of s^3"
echo "anchored boxes against the exact method (Warnock D2, Dinf over the"
echo "critical boxes); err: relative to exact"
printf '%-7s %6s %-10s %9s %12s %12s %8s %8s\n' kind n method seconds D2 Dinf \
    D2_err Dinf_err
if [ -n "${BENCH_QUICK:-}" ]; then N3="1024"; else N3="1024 4096"; fi
for k in random halton; do
	for n in $N3; do
		f=$T/e.pts
		"$GEN" -q -d 3 -k $k -n "$n" -S 1 -o "$f"
		timerep "$T/ex" "$DISC" -q -j 1 -c star --exact "$f"
		ed2=$(field "$T/ex" 4) einf=$(field "$T/ex" 6)
		printf '%-7s %6d %-10s %9.4f %12.6g %12.6g %8s %8s\n' $k "$n" exact \
		    "$SEC" "$ed2" "$einf" - -
		for s in 25 50 100 200 400; do
			timerep "$T/gr" "$DISC" -q -j 1 -c star --grid $s "$f"
			awk -v k=$k -v n="$n" -v s=$s -v t="$SEC" -v d2="$(field "$T/gr" 4)" \
			    -v di="$(field "$T/gr" 6)" -v e2="$ed2" -v ei="$einf" 'BEGIN {
				printf "%-7s %6d %-10s %9.4f %12.6g %12.6g %7.1f%% %7.1f%%\n",
				    k, n, "grid " s, t, d2, di, 100 * (d2 - e2) / e2, 100 * (di - ei) / ei }'
		done
	done
done
