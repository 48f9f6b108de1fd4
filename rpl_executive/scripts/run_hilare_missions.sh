#!/bin/bash
# Ten seeded runs of Noreils and Chatila's missions on HILARE (spott_launch's
# test/hilare_missions.test: Example 1 and the four branches of Example 2, in order on one stack
# per seed). Each branch of each run appends one line (outcome, monitors fired with their times,
# contacts) to the results file; a per-branch summary and the load average close it.
#
# Usage (from the repository root, after ./spott build):
#   tools/isolated.sh rpl_executive/scripts/run_hilare_missions.sh [RUNS] [FIRST_SEED]
# Environment: OUT (default .ws/eval/hilare_missions_runs.txt), RTF (default 4).
set -u
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
RUNS="${1:-10}"
FIRST="${2:-1}"
OUT="${OUT:-$ROOT/.ws/eval/hilare_missions_runs.txt}"
mkdir -p "$(dirname "$OUT")"
RTF="${RTF:-4.0}"
export PATH="/usr/bin:/bin:$PATH"
set +u  # the ROS setup scripts read unset variables
# shellcheck disable=SC1091
source "$ROOT/.ws/devel/setup.bash"
set -u
{
  echo "# hilare missions: $RUNS runs from seed $FIRST, real-time factor $RTF, $(date -u +%FT%TZ)"
  echo "# load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$OUT"
for ((seed = FIRST; seed < FIRST + RUNS; ++seed)); do
  echo "[run_hilare_missions] seed $seed" >&2
  rostest spott_launch hilare_missions.test seed:="$seed" real_time_factor:="$RTF" \
    report_file:="$OUT" filter:="*" > "/tmp/hilare_missions_seed$seed.log" 2>&1
done
{
  echo "# load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
  for b in example1 zone_first zone_first_obstacle obstacle_first avoidance_before_zone; do
    n=$(grep -c "^branch=$b " "$OUT")
    ok=$(grep "^branch=$b " "$OUT" | grep -c " as_paper=1 ")
    echo "# $b: $ok of $n runs as the paper says"
  done
} >> "$OUT"
cat "$OUT"
