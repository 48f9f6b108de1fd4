#!/usr/bin/env bash
# roslaunch env-loader for remote machines: sources the catkin workspace that holds this script
# (or $SPOTT_SETUP, a setup.bash), then runs the node command it is given.
if [[ -z "${SPOTT_SETUP:-}" ]]; then
  dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)
  while [[ "$dir" != / ]]; do
    for candidate in "$dir/devel/setup.bash" "$dir/install/setup.bash" "$dir/.ws/devel/setup.bash"; do
      [[ -f "$candidate" ]] && SPOTT_SETUP=$candidate && break 2
    done
    dir=$(dirname "$dir")
  done
fi
[[ -n "${SPOTT_SETUP:-}" ]] || { echo "env.sh: no catkin setup.bash found; set SPOTT_SETUP" >&2; exit 1; }
export PATH="/usr/bin:$PATH"
# shellcheck disable=SC1090
source "$SPOTT_SETUP"
exec "$@"
