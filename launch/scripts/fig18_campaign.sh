#!/usr/bin/env bash
# SPOTT Fig. 18, GO with the CAD map: N seeded runs on cim_office (default 20), each a fresh
# stack with its own start pose and goal (launch/src/fig18_campaign.h), one after the other,
# then a table of the results (times, path lengths, speeds). Every run is in its own network
# namespace when unshare is at hand (as tools/isolated.sh does) (rostest's and roslaunch's fixed
# ports). Usage: launch/scripts/fig18_campaign.sh [N] [FIRST_SEED]    (from the repository)
# FIG18_LOCALIZATION=truth runs the stack on the simulator's pose (no localization error), to
# tell the controller's failures from the localization's. FIG18_BAG=1 records each run's ground
# truth, estimate, map updates, bumper and steering in $OUT/run-SEED.bag (rosbag; about 10 MB);
# launch/scripts/fig18_bag_summary.py summarizes them on the ground truth.
# Do not rebuild or edit config/*.yaml while it runs: every run starts the nodes afresh.
set -u
N=${1:-20}
FIRST=${2:-1}
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
export PATH="/usr/bin:$PATH"
# shellcheck disable=SC1091
set +u  # catkin's setup scripts read unset variables
source "$ROOT/.ws/devel/setup.bash"
set -u
WORLD="$ROOT/spott_worlds/worlds/cim_office.yaml"
OUT=${FIG18_OUT:-"$ROOT/.ws/fig18"}
mkdir -p "$OUT"
RESULTS="$OUT/results.txt"
: > "$RESULTS"
run_one() {  # seed start_pose
  export ROS_MASTER_URI=http://127.0.0.1:11311 ROS_HOSTNAME=127.0.0.1
  export ROS_LOG_DIR="$OUT/log-$1"
  timeout 600 roslaunch -p 11311 spott_launch fig18.launch seed:="$1" start_pose:="$2" \
    result_file:="$RESULTS" localization:="${FIG18_LOCALIZATION:-markov}" > "$OUT/run-$1.log" 2>&1 &
  local launch=$!
  local bag=""
  if [[ -n "${FIG18_BAG:-}" ]]; then  # what the run's diagnosis needs, without tf
    sleep 3
    rosbag record -q -O "$OUT/run-$1.bag" /sim/ground_truth /amcl_pose /localization_status \
      /belief_modes /map_updates /bumper /harmonic_planner/steering /harmonic_planner/status \
      /tr_plus_controller/state /projected_goal /global_path /cmd_vel /infrared \
      /cmd_vel/reflex __name:=fig18_bag \
      > /dev/null 2>&1 &
    bag=$!
  fi
  wait "$launch"
  if [[ -n "$bag" ]]; then
    kill -INT "$bag" 2> /dev/null
    wait "$bag" 2> /dev/null
    # The recorder closes the bag shortly after its wrapper exits; only a bag left open is
    # reindexed.
    for _ in 1 2 3 4 5 6 7 8 9 10; do [[ -f "$OUT/run-$1.bag.active" ]] || break; sleep 1; done
    if [[ -f "$OUT/run-$1.bag.active" ]]; then
      rosbag reindex "$OUT/run-$1.bag.active" > /dev/null 2>&1 &&
        mv "$OUT/run-$1.bag.active" "$OUT/run-$1.bag"
    fi
  fi
  return 0
}
export -f run_one
export OUT RESULTS FIG18_LOCALIZATION FIG18_BAG
for ((seed = FIRST; seed < FIRST + N; ++seed)); do
  start=$("$ROOT/.ws/devel/lib/spott_launch/fig18_run" --case "$seed" "$WORLD") || {
    echo "seed $seed: no case"; continue; }
  echo "seed $seed: start $start ($(uptime | sed 's/.*load average: //'))"
  if command -v unshare > /dev/null && [[ $(id -u) -eq 0 ]]; then
    unshare -n bash -c "ip link set lo up; run_one $seed '$start'"
  else
    run_one "$seed" "$start"
  fi
  grep "^$seed " "$RESULTS" || echo "$seed - - FAILED (no result: see $OUT/run-$seed.log)" >> "$RESULTS"
  tail -n 1 "$RESULTS"
done
echo
echo "seed start_room goal_room result time_s path_m straight_m speed_mps error_m contacts"
cat "$RESULTS"
awk '$4 == "arrived" {n++; t += $5; l += $6; s += $8} END {
  printf "\n%d of %d arrived", n, NR;
  if (n) printf "; mean time %.1f s, mean path %.1f m, mean speed %.3f m/s", t / n, l / n, s / n;
  printf "\n" }' "$RESULTS"
