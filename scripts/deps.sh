#!/bin/sh
# Install the Debian packages frs needs, and only those that are missing.
# Idempotent: with everything present it installs nothing and says so.
#   scripts/deps.sh          install what is missing
#   scripts/deps.sh --check  only report; exit 1 if something is missing
set -eu

PKGS="gcc g++ make libc6-dev pkg-config libpng-dev libopenexr-dev libcmocka-dev
ocl-icd-opencl-dev opencl-headers pocl-opencl-icd clinfo mandoc gnuplot-nox
time parallel"

missing=""
for p in $PKGS; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null |
	    grep -q 'install ok installed'; then
		missing="$missing $p"
	fi
done

if [ -z "$missing" ]; then
	echo "deps: all $(echo $PKGS | wc -w) packages present"
	exit 0
fi
echo "deps: missing:$missing"
[ "${1:-}" = "--check" ] && exit 1

if [ "$(id -u)" -ne 0 ]; then
	if command -v sudo >/dev/null 2>&1; then
		SUDO=sudo
	else
		echo "deps: not root and no sudo; install them by hand" >&2
		exit 1
	fi
else
	SUDO=
fi
echo "deps: apt-get update"
$SUDO apt-get update -qq
echo "deps: apt-get install$missing"
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq \
    --no-install-recommends $missing >/dev/null
echo "deps: done"
