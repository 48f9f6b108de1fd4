#!/usr/bin/env bash
# Instructions per plan, ours and the navfn peer on the same grids (callgrind), for the README's
# figures table: counts do not depend on the machine's load, CPU times do. Needs valgrind and
# the benchmarks built (./spott bench, or SPOTT_BUILD_BENCHMARKS=ON).
#   spott_harmonic_planner/bench/count_instructions.sh [WORKSPACE]   (default: .ws)
# Prints one line per grid: instructions per plan, ours, peer, ratio, and what ours reported.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
WS="${1:-$ROOT/.ws}"
EXE="$WS/devel/lib/spott_harmonic_planner/spott_harmonic_planner_plan_count"
command -v valgrind >/dev/null || { echo "needs valgrind (apt-get install valgrind)" >&2; exit 1; }
[[ -x "$EXE" ]] || { echo "no $EXE: build the benchmarks first (./spott bench)" >&2; exit 1; }
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT

# count GRID N WHO MODE REPS -> "instructions per plan|program output"
count() {
  local file="$OUT/cg.$$.$RANDOM" text ir
  text=$(valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$file" \
           "$EXE" "$@" 2>/dev/null)
  ir=$(grep -E '^(summary|totals):' "$file" | head -1 | awk '{print $2}')
  rm -f "$file"
  echo "$((ir / $5))|$text"
}

row() {  # GRID N MODE REPS
  local o p oi pi
  o=$(count "$1" "$2" ours "$3" "$4")
  p=$(count "$1" "$2" peer cold "$4")
  oi=${o%%|*}
  pi=${p%%|*}
  printf "%-11s %5s %-6s ours %12d  peer %12d  ratio %6.3f  (%s)\n" "$1" "$2" "$3" "$oi" "$pi" \
    "$(echo "$oi / $pi" | bc -l)" "${o#*|}"
}

for grid in open rect; do
  for n in 35 64 128 256 512 1024; do
    reps=3
    [[ $n -ge 512 ]] && reps=1
    row $grid $n cold $reps
  done
done
row corridor20 128 cold 3
row corridor20 256 cold 3
row corridor20 512 cold 1
row corridor20 1024 cold 1
row corridor50 256 cold 3
row corridor50 512 cold 1
row corridor50 1024 cold 1
row corridor100 512 cold 1
row corridor100 1024 cold 1
for n in 70 256; do
  row rect $n cold 2
  row rect $n change 2
  row rect $n shift 2
done
row office 70 cold 3
row office 70 change 3
