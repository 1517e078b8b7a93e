#!/bin/sh
# fakessh.sh [ssh options] HOST [--] COMMAND...: run COMMAND on this
# machine, as ssh would on HOST: a stand-in host for GNU parallel
# --sshlogin (--ssh test/fakessh.sh) in t_experiments.  Each call appends
# HOST to $FAKESSH_LOG.  Like sshd it sets SHELL to the login shell:
# GNU parallel's remote worker runs each job with $SHELL, and with none
# set (CI's bare environment) it runs nothing and still exits 0.
while [ $# -gt 0 ]; do
	case $1 in
	-[bcDEeFIiJLlmOopQRSWw]) shift 2 ;;
	-*) shift ;;
	*) break ;;
	esac
done
host=$1
shift
[ "${1:-}" = -- ] && shift
SHELL=$(getent passwd "$(id -u)" | cut -d: -f7)
export SHELL="${SHELL:-/bin/sh}"
echo "$host" >>"${FAKESSH_LOG:-/dev/null}"
exec sh -c "$*"
