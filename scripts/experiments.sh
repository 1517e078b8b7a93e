#!/bin/sh
# make experiments: run every experiment script (scripts/exp-*.sh), or
# those named in ONLY (ids such as fig6.3 or tab6.1, comma-separated),
# then write results/REPORT.md, through the rules of mk/experiments.mk
# (what runs is what changed).  QUICK=1 (default) or QUICK=0 (the thesis
# parameters); MODE=tiny is what make check uses.
#   sh scripts/experiments.sh            as make experiments (MAKEFLAGS
#                                        such as -j2 pass through)
#   sh scripts/experiments.sh --select ONLY
#                                        the experiment ids ONLY names
#   sh scripts/experiments.sh --stamp ID the checksums of what ID reads
set -eu
cd "$(dirname "$0")/.."

# select ONLY: the ids of the scripts whose id or "# ids:" alias is in
# ONLY; none is an error (exit 2).
select_ids() {
	out=
	for s in scripts/exp-*.sh; do
		id=${s#scripts/exp-}
		id=${id%.sh}
		for w in $(echo "$1" | tr ',' ' '); do
			case " $(sed -n 's/^# ids: //p' "$s") $id " in
			*" $w "*) out="$out $id"; break ;;
			esac
		done
	done
	if [ -z "$out" ]; then
		echo "experiments: no experiment matches ONLY=$1" >&2
		exit 2
	fi
	echo $out
}

# stamp ID: a line per input of the experiment, with its checksum: the
# script, explib.sh, the programs it names, the matrices and the map
# (when it names them), every file of data/ it names, and the mode.
stamp() {
	s=scripts/exp-$1.sh
	[ -f "$s" ] || { echo "experiments: no experiment $1" >&2; exit 2; }
	BIN=${BIN:-$PWD/bin}
	echo "mode ${MODE:-quick}"
	for f in "$s" scripts/explib.sh; do
		echo "script $f $(sha1sum <"$f" | cut -c 1-40)"
	done
	for p in "$BIN"/*; do
		b=$(basename "$p")
		grep -q -w -F -e "$b" "$s" scripts/explib.sh &&
		    echo "prog $b $(sha1sum <"$p" | cut -c 1-40)"
	done
	if grep -q -w -e frs-sample -e frd-prep -e split_frs -e timing_inputs "$s"; then
		m=${FRS_MATRIX:-data/default.frd}
		echo "matrix $m $(sha1sum <"$m" | cut -c 1-40)"
	fi
	if grep -q 'FRS_MATRIX3' "$s"; then
		echo "matrix3 ${FRS_MATRIX3:-data/default3.frd} $(sha1sum <"${FRS_MATRIX3:-data/default3.frd}" | cut -c 1-40)"
	fi
	if grep -q 'ENVMAP' "$s"; then
		e=${ENVMAP:-data/sunset.exr}
		echo "envmap $e $(sha1sum <"$e" | cut -c 1-40)"
	fi
	for f in $(grep -o 'data/[A-Za-z0-9_.-]*\.[a-z]*' "$s" | sort -u); do
		[ -f "$f" ] && echo "data $f $(sha1sum <"$f" | cut -c 1-40)"
	done
	:
}

case ${1:-} in
--select) select_ids "$2" ;;
--stamp) stamp "$2" ;;
"") exec ${MAKE:-make} --no-print-directory -f mk/experiments.mk \
    ${ONLY:+ONLY="$ONLY"} experiments ;;
*) echo "usage: sh scripts/experiments.sh [--select ONLY | --stamp ID]" >&2
   exit 2 ;;
esac
