#!/usr/bin/env bash
# A README screenshot of one stack: launch/launch/STACK.launch with rviz under Xvfb (a private
# master, 4x real time), its example task or mission sent after the start, the screen saved as
# PNG after SECONDS of wall time. Usage (from the repository, after ./spott build):
#   launch/scripts/stack_screenshot.sh STACK OUT.png [SECONDS]
# STACK: spott_nomad200 | spott_b12 | rhino_b21 | noreils_chatila_hilare
set -euo pipefail
STACK=${1:?usage: stack_screenshot.sh STACK OUT.png [SECONDS]}
OUT=${2:?usage: stack_screenshot.sh STACK OUT.png [SECONDS]}
SECONDS_TO_RUN=${3:-40}
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
export PATH="/usr/bin:$PATH"
[[ -f "$ROOT/launch/launch/$STACK.launch" ]] || { echo "no stack '$STACK'" >&2; exit 2; }
OUT=$(realpath -m "$OUT")
FB=$(mktemp -d)
trap 'rm -rf "$FB"' EXIT
export ROS_MASTER_URI=http://127.0.0.1:11411 ROS_HOSTNAME=127.0.0.1
# What the stack is given to do (the examples in each launch file's header).
case "$STACK" in
  spott_nomad200 | spott_b12)
    send=(rostopic pub -1 /task/goal spott_msgs/TaskActionGoal "{goal: {command: 'go in room(lab)'}}");;
  rhino_b21)
    send=(rostopic pub -1 /mission/goal spott_msgs/MissionActionGoal "{goal: {language: 0, name: office_delivery}}");;
  noreils_chatila_hilare)
    send=(rostopic pub -1 /mission/goal spott_msgs/MissionActionGoal "{goal: {language: 1, name: example1_wall_following}}");;
esac
# env.sh: the workspace sourced, then the command.
"$ROOT/launch/scripts/env.sh" xvfb-run -a -s "-screen 0 1280x800x24 -fbdir $FB" bash -c '
  roslaunch -p 11411 spott_launch "$0.launch" real_time_factor:=4.0 > "$1/launch.log" 2>&1 &
  launch=$!
  sleep 15
  "${@:3}" > /dev/null 2>&1 || echo "sending the task failed" >&2
  sleep "$2"
  cp "$1/Xvfb_screen0" "$1/screen.xwd"
  kill -INT "$launch"; wait "$launch" || true
' "$STACK" "$FB" "$SECONDS_TO_RUN" "${send[@]}"
"$ROOT/launch/scripts/xwd_to_png.py" "$FB/screen.xwd" "$OUT"
echo "wrote $OUT"
