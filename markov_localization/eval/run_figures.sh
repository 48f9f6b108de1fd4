#!/usr/bin/env bash
# Runs every scenario of markov_localization_eval with the settings of the README's figures and
# writes each table to eval/results/<name>.md. Needs `./spott build markov_localization` first.
# Each command is seeded (--seed 1 unless given) and takes minutes, not hours; run them one at a
# time on a shared machine (nice -n 10). Usage: eval/run_figures.sh [NAME...] (default: all).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
EVAL="$HERE/../../.ws/devel/lib/markov_localization/markov_localization_eval"
OUT="$HERE/results"
mkdir -p "$OUT"
declare -A CMD=(
  [global_20cm]="global --runs 20 --resolution 0.2"
  [tracking_15cm]="tracking --runs 3"
  [fig2_20cm]="fig2 --runs 5 --resolution 0.2 --picture $HERE/../doc/belief_fig2_position2_20cm.png"
  [symmetric_20cm]="symmetric --runs 10 --resolution 0.2"
  [symmetric_25cm]="symmetric --runs 10 --resolution 0.25"
  [kidnap_20cm]="kidnap --runs 10 --resolution 0.2"
  [kidnap_20cm_keep]="kidnap --runs 10 --resolution 0.2 --on-lost keep"
  [global_20cm_calibrated]="global --runs 20 --resolution 0.2 --calibrate"
  [global_active_full_update_25cm]="global --runs 10 --resolution 0.25 --full-update --behaviours active"
  [tracking_15cm_no_detector]="tracking --runs 3 --lost-detector off"
  [global_20cm_no_detector]="global --runs 20 --resolution 0.2 --lost-detector off"
  [kidnap_full_update_25cm]="kidnap --runs 10 --resolution 0.25 --full-update"
  [global_active_selective_25cm]="global --runs 10 --resolution 0.25 --behaviours active"
  [global_baselines_full_update_25cm]="global --runs 5 --resolution 0.25 --full-update --behaviours wander,wall --time-limit 300"
  [global_baselines_selective_25cm]="global --runs 5 --resolution 0.25 --behaviours wander,wall --time-limit 300"
  [global_25cm]="global --runs 20 --resolution 0.25"
)
ORDER=(global_20cm tracking_15cm fig2_20cm symmetric_20cm symmetric_25cm kidnap_20cm
       kidnap_20cm_keep global_20cm_calibrated global_active_full_update_25cm
       tracking_15cm_no_detector global_20cm_no_detector kidnap_full_update_25cm
       global_active_selective_25cm global_baselines_full_update_25cm
       global_baselines_selective_25cm global_25cm)
[[ $# -gt 0 ]] && ORDER=("$@")
for name in "${ORDER[@]}"; do
  echo "== $name: markov_localization_eval ${CMD[$name]}" >&2
  { echo "command: markov_localization_eval ${CMD[$name]}  ($(date -u +%FT%TZ))"; echo;
    # shellcheck disable=SC2086
    nice -n 10 "$EVAL" ${CMD[$name]}; } > "$OUT/$name.md" 2> "$OUT/$name.log"
  [[ -s "$OUT/$name.log" ]] || rm -f "$OUT/$name.log"
done
