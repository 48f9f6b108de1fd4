#!/bin/bash
# Ten seeded runs of the office delivery of Beetz et al. section 4 on the simulator
# (spott_launch's test/office_delivery.test: bonn_department, the B21, the 70 degree turn), one
# after the other. Each run appends one line (outcome, times, final error on ground truth) to the
# results file; the summary and the load average at start and end close it.
#
# Usage (from the repository root, after ./spott build; rostest needs its own network namespace
# on a shared machine):
#   tools/isolated.sh rpl_executive/scripts/run_office_delivery.sh [RUNS] [FIRST_SEED]
# Environment: OUT (results file, default .ws/eval/office_delivery_runs.txt),
# RTF (real-time factor, default 4).
set -u
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
RUNS="${1:-10}"
FIRST="${2:-1}"
OUT="${OUT:-$ROOT/.ws/eval/office_delivery_runs.txt}"
mkdir -p "$(dirname "$OUT")"
RTF="${RTF:-4.0}"
export PATH="/usr/bin:/bin:$PATH"
set +u  # the ROS setup scripts read unset variables
# shellcheck disable=SC1091
source "$ROOT/.ws/devel/setup.bash"
set -u
{
  echo "# office delivery: $RUNS runs from seed $FIRST, real-time factor $RTF, $(date -u +%FT%TZ)"
  echo "# load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$OUT"
for ((seed = FIRST; seed < FIRST + RUNS; ++seed)); do
  echo "[run_office_delivery] seed $seed" >&2
  rostest spott_launch office_delivery.test seed:="$seed" real_time_factor:="$RTF" \
    report_file:="$OUT" > "/tmp/office_delivery_seed$seed.log" 2>&1
  grep -q "seed=$seed " "$OUT" || echo "seed=$seed outcome=no-report (see /tmp/office_delivery_seed$seed.log)" >> "$OUT"
done
ok=$(grep -c ' success=1 ' "$OUT")
{
  echo "# load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# $ok of $RUNS runs succeeded"
} >> "$OUT"
cat "$OUT"
