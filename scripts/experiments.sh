#!/bin/sh
# make experiments: run every experiment script (scripts/exp-*.sh), or
# those named in ONLY (ids such as fig6.3 or tab6.1, comma-separated),
# then write results/REPORT.md.  QUICK=1 (default) or QUICK=0 (the thesis
# parameters); MODE=tiny is what make check uses.
set -eu
cd "$(dirname "$0")/.."
if [ -z "${MODE:-}" ]; then
	if [ "${QUICK:-1}" = 0 ]; then MODE=full; else MODE=quick; fi
fi
export MODE
ONLY=${ONLY:-}
t0=$(date +%s)
ran=0
for s in scripts/exp-*.sh; do
	id=${s#scripts/exp-}
	id=${id%.sh}
	if [ -n "$ONLY" ]; then
		hit=0
		for w in $(echo "$ONLY" | tr ',' ' '); do
			case " $(sed -n 's/^# ids: //p' "$s") $id " in
			*" $w "*) hit=1 ;;
			esac
		done
		[ $hit = 1 ] || continue
	fi
	sh "$s"
	ran=$((ran + 1))
done
if [ $ran = 0 ]; then
	echo "experiments: no experiment matches ONLY=$ONLY" >&2
	exit 2
fi
sh scripts/report.sh
echo "experiments: $ran run in $(( $(date +%s) - t0 )) s ($MODE mode); see ${RES:-results}/REPORT.md" >&2
