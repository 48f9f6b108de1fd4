#!/usr/bin/env bash
# The scenario suite (issue 20): every scenario of launch/scenarios/ (or those named) run with
# seeds 1..SEEDS through ./spott run (no bags), and a table per scenario from the runs'
# report.json: runs that succeeded (every leg reached on the ground truth without contact, every
# fault applied), mean simulated and wall time, mean path length, contacts (bumper, and the body on
# the ground truth), the largest
# localization error. Writes the table to OUT/suite.md (OUT: runs/suite-<UTC time>).
# --jobs N runs N scenarios at once, each on its own private master: one run at the scenarios'
# real-time factor 4 keeps about one of this machine's 2 cores busy (the robot_sim pacer holds
# the clock for a stack that lags, so a busy machine slows a run without changing it).
# Usage: launch/scripts/scenario_suite.sh [--jobs N (1)] [SEEDS (10)] [SCENARIO.yaml...]
# ./spott bench scenarios [--jobs N] [SEEDS] runs it.
set -uo pipefail
export PATH="/usr/bin:$PATH"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
JOBS=1
if [[ "${1:-}" == --jobs ]]; then
  JOBS="${2:-}"
  [[ "$JOBS" =~ ^[1-9][0-9]*$ ]] || { echo "scenario_suite: --jobs must be a positive integer" >&2; exit 2; }
  shift 2
fi
SEEDS="${1:-10}"
[[ "$SEEDS" =~ ^[1-9][0-9]*$ ]] || { echo "scenario_suite: SEEDS must be a positive integer" >&2; exit 2; }
shift $(( $# > 0 ? 1 : 0 ))
scenarios=("$@")
[[ ${#scenarios[@]} -gt 0 ]] || scenarios=("$ROOT"/launch/scenarios/*.yaml)
OUT="${SUITE_OUT:-$ROOT/runs/suite-$(date -u +%Y%m%dT%H%M%SZ)}"
mkdir -p "$OUT"
echo "scenario suite: ${#scenarios[@]} scenarios x $SEEDS seeds, $JOBS at once, into $OUT; load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
# Built once here; each run skips the build check (about 20 s a run).
"$ROOT/spott" build > "$OUT/build.log" 2>&1 || { echo "scenario_suite: the build failed ($OUT/build.log)" >&2; exit 1; }
run_one() {  # scenario file, seed
  local name start=$SECONDS
  name=$(basename "$1" .yaml)
  "$ROOT/spott" run "$1" --seed "$2" --no-bag --no-build --out "$OUT/$name/seed-$2" \
    > "$OUT/$name-seed-$2.log" 2>&1
  echo "$name seed $2: $(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['outcome'])" \
    "$OUT/$name/seed-$2/report.json" 2>/dev/null || echo 'no report') ($((SECONDS - start)) s)" >&2
}
suite_start=$SECONDS
for scenario in "${scenarios[@]}"; do
  for ((seed = 1; seed <= SEEDS; ++seed)); do
    while (( $(jobs -rp | wc -l) >= JOBS )); do wait -n; done
    run_one "$scenario" "$seed" &
  done
done
wait
python3 - "$OUT" "$SEEDS" "$(cut -d' ' -f1-3 /proc/loadavg)" "$((SECONDS - suite_start))" "$JOBS" > "$OUT/suite.md" <<'PY'
import glob, json, os, sys
out, seeds, load, suite_wall, jobs = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
print('| scenario | succeeded | mean simulated time (s) | mean wall time (s) | mean path (m) | contacts (bumper / body, ground truth) | max localization error (m) | failures |')
print('|---|---|---|---|---|---|---|---|')
for d in sorted(glob.glob(os.path.join(out, '*/'))):
    name = os.path.basename(d.rstrip('/'))
    reports = []
    for s in range(1, seeds + 1):
        try:
            with open(os.path.join(d, 'seed-%d' % s, 'report.json')) as f:
                reports.append((s, json.load(f)))
        except (OSError, ValueError):
            reports.append((s, None))
    ok = [r for _, r in reports if r and r['outcome'] == 'succeeded']
    done = [r for _, r in reports if r and r.get('totals')]
    mean = lambda key: sum(r['totals'][key] for r in done) / len(done) if done else float('nan')
    wall = sum(r['elapsed_wall_s'] for r in done) / len(done) if done else float('nan')
    contacts = '%d / %d' % (sum(r['totals']['bumper_hits'] for r in done),
                            sum(r['totals'].get('body_contacts', 0) for r in done))
    err = max((r['totals']['max_position_error_m'] for r in done), default=float('nan'))
    failed = ', '.join('seed %d (%s)' % (s, r['outcome'] if r else 'no report')
                       for s, r in reports if not r or r['outcome'] != 'succeeded')
    print('| %s | %d of %d | %.1f | %.1f | %.1f | %s | %.2f | %s |' % (
        name, len(ok), len(reports), mean('sim_time_s'), wall, mean('path_length_m'), contacts,
        err, failed or '-'))
print()
print('suite wall time: %s s (%s runs at once); load average at the end: %s' % (suite_wall, jobs, load))
PY
cat "$OUT/suite.md"
