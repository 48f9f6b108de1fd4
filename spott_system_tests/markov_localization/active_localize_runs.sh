#!/usr/bin/env bash
# The ActiveLocalize action end to end on the simulator, N seeded runs (issue 14: >= 19 of 20):
# spott_system_tests/test/active_localize_success.test (B21 in bonn_department, sonars only, uniform belief at
# the corridor's east end, world_server + global planner + harmonic planner + the node at its
# YAML defaults, 20 cm / 5 deg) once per seed, each in its own network namespace
# (tools/isolated.sh, as root). Needs the workspace built with tests
# (./spott test spott_system_tests builds them). Writes results/active_localize_runs.md.
# Usage: spott_system_tests/markov_localization/active_localize_runs.sh [RUNS (20)] [FIRST_SEED (1)] [extra roslaunch args...]
set -uo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$HERE/../.."
RUNS="${1:-20}"
FIRST="${2:-1}"
shift $(( $# > 2 ? 2 : $# ))
OUT="$HERE/results/active_localize_runs.md"
ISOLATE=""
[[ $(id -u) -eq 0 ]] && ISOLATE="$ROOT/tools/isolated.sh"
RUNNER="$(mktemp)"
cat > "$RUNNER" <<EOS
#!/usr/bin/env bash
export PATH=/usr/bin:\$PATH
source "$ROOT/.ws/devel/setup.bash"
rostest spott_system_tests active_localize_success.test "\$@"
EOS
chmod +x "$RUNNER"
{
  echo "# ActiveLocalize end to end: $RUNS seeded runs ($(date -u +%FT%TZ))"
  echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg); extra args: ${*:-none}"
  echo
  echo "| seed | result | reason / final error | targets | wall (s) |"
  echo "|---|---|---|---|---|"
} > "$OUT"
ok=0
for ((i = 0; i < RUNS; ++i)); do
  seed=$((FIRST + i))
  log="$(mktemp)"
  start=$SECONDS
  $ISOLATE "$RUNNER" seed:="$seed" "$@" > "$log" 2>&1
  wall=$((SECONDS - start))
  line=$(grep -h "ActiveLocalize succeeded\|ActiveLocalize gave up" "$log" | tail -1 | sed 's/.*ActiveLocalize //; s/\x1b\[[0-9;]*m//g')
  targets=$(grep -o "[0-9]* targets" <<<"$line" | head -1)
  if grep -q "RESULT: SUCCESS" "$log"; then result=success; ok=$((ok + 1)); else result=failed; fi
  failure=$(grep -h -A3 "Failure" "$log" | grep -v "^--" | tr '\n' ' ' | sed 's/\x1b\[[0-9;]*m//g' | cut -c1-200)
  echo "| $seed | $result | ${line:-none} ${failure} | ${targets:-?} | $wall |" >> "$OUT"
  echo "seed $seed: $result ($wall s)" >&2
  mkdir -p /tmp/active_localize_runs && mv "$log" "/tmp/active_localize_runs/seed_$seed.log"
done
{
  echo
  echo "**$ok of $RUNS** ended certain and within 0.5 m / 10 degrees; load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
} >> "$OUT"
rm -f "$RUNNER"
echo "$ok of $RUNS" >&2
