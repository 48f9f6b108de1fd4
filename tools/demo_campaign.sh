#!/usr/bin/env bash
# Runs ./spott demo on a world several times with different seeds (optionally while other jobs
# keep every core busy) and prints one line per run plus the totals: legs reached on ground
# truth, bumper contacts, the localization's largest error, lost alarms and the real-time
# factor achieved. The numbers behind the README's "demo legs reached over 10 runs" table.
#   tools/demo_campaign.sh --world cim_office --runs 10 [--busy] [--first-seed 1]
#                          [--controller tr_plus|none]   (the demo's default: tr_plus)
set -o pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
world=cim_office runs=10 busy=0 first=1 controller=tr_plus
while [[ $# -gt 0 ]]; do
  case "$1" in
    --world) world=$2; shift 2;;
    --runs) runs=$2; shift 2;;
    --first-seed) first=$2; shift 2;;
    --busy) busy=1; shift;;
    --controller) controller=$2; shift 2;;
    -h|--help) sed -n 2,8p "$0"; exit 0;;
    *) echo "demo_campaign: unknown option $1" >&2; exit 2;;
  esac
done
out="$ROOT/.ws/campaign"
mkdir -p "$out"
hogs=()
if [[ $busy -eq 1 ]]; then  # one spinning process per core, for the whole campaign
  for _ in $(seq "$(nproc)"); do (while :; do :; done) & hogs+=($!); done
  trap 'kill "${hogs[@]}" 2>/dev/null' EXIT
fi
total_legs=0 total_reached=0 total_contacts=0 total_alarms=0 worst=0
printf '%-16s %4s %8s %8s %9s %7s %6s %6s\n' world seed reached contacts max_err_m alarms rtf load
for ((seed = first; seed < first + runs; ++seed)); do
  report="$out/$world-$controller-$seed.report"
  SPOTT_SKIP_SETUP=1 "$ROOT/spott" demo --world "$world" --seed "$seed" --controller "$controller" \
    >"$report" 2>"$out/$world-$controller-$seed.err"
  # A leg is a place ("   to NAME (x, y): ...") or, with --controller tr_plus, a task ("   task '...': ...").
  legs=$(grep -cE "^   (to [a-z_0-9]+ \(|task ')" "$report")
  reached=$(grep -cE "^   (to [a-z_0-9]+ \(.*\)|task '.*'): reached$" "$report")
  contacts=$(grep -oE 'bumper contacts: [0-9]+' "$report" | awk '{s += $3} END {print s + 0}')
  alarms=$(grep -oE 'said lost [0-9]+' "$report" | awk '{s += $3} END {print s + 0}')
  max_err=$(grep -oE 'max [0-9.]+ m /' "$report" | awk '{if ($2 > m) m = $2} END {print m + 0}')
  rtf=$(grep -oE 'real-time factor [0-9.]+' "$report" | awk '{print $3}')
  load=$(cut -d' ' -f1 /proc/loadavg)
  printf '%-16s %4d %5d/%-2d %8d %9.2f %7d %6s %6s\n' "$world" "$seed" "$reached" "$legs" \
    "$contacts" "$max_err" "$alarms" "${rtf:--}" "$load"
  total_legs=$((total_legs + legs)); total_reached=$((total_reached + reached))
  total_contacts=$((total_contacts + contacts)); total_alarms=$((total_alarms + alarms))
  worst=$(awk -v a="$worst" -v b="$max_err" 'BEGIN {print (b > a) ? b : a}')
done
echo "$world: $total_reached of $total_legs legs reached over $runs runs$([[ $busy -eq 1 ]] && echo ' (busy: every core loaded)'), $total_contacts bumper contacts, $total_alarms lost alarms, largest localization error ${worst} m; reports in $out"
