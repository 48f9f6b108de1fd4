#!/usr/bin/env bash
# Runs every scenario of markov_localization_eval with the settings of the README's figures and
# writes each table to results/<name>.md. Needs `./spott build spott_system_tests` first.
# Each command is seeded (--seed 1 unless given) and takes minutes, not hours; run them one at a
# time on a shared machine (nice -n 10). Usage: spott_system_tests/markov_localization/run_figures.sh [NAME...] (default: the
# earlier issues' figures; `issue14`: issue 14's, about 15 minutes on an idle machine).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
EVAL="$HERE/../../.ws/devel/lib/spott_system_tests/markov_localization_eval"
OUT="$HERE/results"
mkdir -p "$OUT"
W="$HERE/../../spott_worlds/eval_worlds"
L="$HERE/../../spott_worlds/worlds"
declare -A CMD=(
  # issue 14 (the node's Localizer pipeline: motion gate, laser, refinement, distance filter)
  [i14_tracking_bonn_laser]="tracking --runs 3 --sensors laser --peer amcl"
  [i14_tracking_bonn_sonar]="tracking --runs 3 --sensors sonar --peer amcl"
  [i14_tracking_cim_laser]="tracking --runs 3 --sensors laser --world $L/cim_office.yaml --peer amcl"
  [i14_tracking_cim_sonar]="tracking --runs 3 --sensors sonar --world $L/cim_office.yaml --peer amcl"
  [i14_tracking_hilare_laser]="tracking --runs 3 --sensors laser --world $L/hilare_room.yaml --peer amcl"
  [i14_tracking_hilare_sonar]="tracking --runs 3 --sensors sonar --world $L/hilare_room.yaml --peer amcl"
  [i14_tracking_crossing_laser]="tracking --runs 3 --sensors laser --world $W/crossing_corridors.yaml --peer amcl"
  [i14_tracking_crossing_sonar]="tracking --runs 3 --sensors sonar --world $W/crossing_corridors.yaml --peer amcl"
  [i14_tracking_crossing_mapfile_laser]="tracking --runs 3 --clearance 0.1 --sensors laser --world $W/crossing_corridors.yaml --map-file $W/crossing_corridors_map.yaml --peer amcl"
  [i14_tracking_crossing_mapfile_sonar]="tracking --runs 3 --clearance 0.1 --sensors sonar --world $W/crossing_corridors.yaml --map-file $W/crossing_corridors_map.yaml --peer amcl"
  [i14_tracking_bonn_laser_10cm]="tracking --runs 3 --sensors laser --resolution 0.1"
  [i14_tracking_bonn_sonar_10cm]="tracking --runs 3 --sensors sonar --resolution 0.1"
  [i14_tracking_cim_laser_10cm]="tracking --runs 3 --sensors laser --world $L/cim_office.yaml --resolution 0.1"
  [i14_tracking_cim_sonar_10cm]="tracking --runs 3 --sensors sonar --world $L/cim_office.yaml --resolution 0.1"
  [i14_tracking_hilare_laser_10cm]="tracking --runs 3 --sensors laser --world $L/hilare_room.yaml --resolution 0.1"
  [i14_tracking_hilare_sonar_10cm]="tracking --runs 3 --sensors sonar --world $L/hilare_room.yaml --resolution 0.1"
  [i14_tracking_crossing_laser_10cm]="tracking --runs 3 --sensors laser --world $W/crossing_corridors.yaml --resolution 0.1"
  [i14_tracking_crossing_sonar_10cm]="tracking --runs 3 --sensors sonar --world $W/crossing_corridors.yaml --resolution 0.1"
  [i14_tracking_crossing_mapfile_laser_10cm]="tracking --runs 3 --sensors laser --world $W/crossing_corridors.yaml --map-file $W/crossing_corridors_map.yaml --resolution 0.1"
  [i14_tracking_crossing_mapfile_sonar_10cm]="tracking --runs 3 --sensors sonar --world $W/crossing_corridors.yaml --map-file $W/crossing_corridors_map.yaml --resolution 0.1"
  [i14_tracking_bonn_every_scan]="tracking --runs 3 --sensors laser --update-min-d 0 --update-min-a-deg 0"
  [i14_tracking_nomad_bonn]="tracking --runs 3 --robot nomad200 --sensors sonar"
  [i14_tracking_nomad_cim]="tracking --runs 3 --robot nomad200 --sensors sonar --world $L/cim_office.yaml"
  [i14_tracking_nomad_hilare]="tracking --runs 3 --robot nomad200 --sensors sonar --world $L/hilare_room.yaml"
  [i14_kidnap_20cm]="kidnap --runs 20 --resolution 0.2 --time-limit 480"
  [i14_kidnap_20cm_240s]="kidnap --runs 20 --resolution 0.2"
  [i14_global_20cm]="global --runs 20 --resolution 0.2"
  [i14_global_landmark_sonar]="global --runs 10 --resolution 0.2 --behaviours active --world $W/symmetric_landmark.yaml"
  [i14_global_landmark_laser]="global --runs 10 --resolution 0.2 --behaviours active --sensors laser --world $W/symmetric_landmark.yaml"
  [i14_symmetric_20cm]="symmetric --runs 10 --resolution 0.2"
  [global_20cm]="global --runs 20 --resolution 0.2"
  [tracking_15cm]="tracking --runs 3"
  [fig2_20cm]="fig2 --runs 5 --resolution 0.2 --picture $HERE/../../markov_localization/doc/belief_fig2_position2_20cm.png"
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
I14=(i14_tracking_bonn_laser i14_tracking_bonn_sonar i14_tracking_cim_laser i14_tracking_cim_sonar
     i14_tracking_hilare_laser i14_tracking_hilare_sonar i14_tracking_crossing_laser
     i14_tracking_crossing_sonar i14_tracking_crossing_mapfile_laser
     i14_tracking_crossing_mapfile_sonar i14_tracking_bonn_laser_10cm i14_tracking_bonn_sonar_10cm
     i14_tracking_cim_laser_10cm i14_tracking_cim_sonar_10cm i14_tracking_hilare_laser_10cm
     i14_tracking_hilare_sonar_10cm i14_tracking_crossing_laser_10cm i14_tracking_crossing_sonar_10cm
     i14_tracking_crossing_mapfile_laser_10cm i14_tracking_crossing_mapfile_sonar_10cm
     i14_tracking_bonn_every_scan i14_tracking_nomad_bonn i14_tracking_nomad_cim
     i14_tracking_nomad_hilare i14_kidnap_20cm i14_kidnap_20cm_240s i14_global_20cm
     i14_global_landmark_sonar i14_global_landmark_laser i14_symmetric_20cm)
ORDER=(global_20cm tracking_15cm fig2_20cm symmetric_20cm symmetric_25cm kidnap_20cm
       kidnap_20cm_keep global_20cm_calibrated global_active_full_update_25cm
       tracking_15cm_no_detector global_20cm_no_detector kidnap_full_update_25cm
       global_active_selective_25cm global_baselines_full_update_25cm
       global_baselines_selective_25cm global_25cm)
[[ $# -gt 0 ]] && ORDER=("$@")
[[ "${1:-}" == "issue14" ]] && ORDER=("${I14[@]}")
for name in "${ORDER[@]}"; do
  echo "== $name: markov_localization_eval ${CMD[$name]}" >&2
  { echo "command: markov_localization_eval ${CMD[$name]}  ($(date -u +%FT%TZ))"; echo;
    # shellcheck disable=SC2086
    nice -n 10 "$EVAL" ${CMD[$name]}; } > "$OUT/$name.md" 2> "$OUT/$name.log"
  [[ -s "$OUT/$name.log" ]] || rm -f "$OUT/$name.log"
done
