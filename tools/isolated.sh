#!/usr/bin/env bash
# Runs a command in a network namespace of its own (loopback only), so that its rostest or
# roslaunch master on the fixed port 11311 does not meet another one: two rostests, or a
# rostest beside a running stack, can then share the machine. Needs root (unshare -n).
# Usage: tools/isolated.sh COMMAND [ARGS...]     e.g. tools/isolated.sh rostest spott_launch task.test
set -euo pipefail
[[ $# -gt 0 ]] || { echo "usage: $0 COMMAND [ARGS...]" >&2; exit 2; }
[[ $(id -u) -eq 0 ]] || { echo "$0: unshare -n needs root" >&2; exit 1; }
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
exec unshare -n bash -c 'ip link set lo up && exec "$@"' isolated "$@"
