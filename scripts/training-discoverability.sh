#!/usr/bin/env bash
# Which faults can a trainee find with the Discover tab on a training recording? For every
# mechanism of CONTRACT.md §4 at the Training tab's default strength (twice the plant's default),
# switched on 5 min into the bundled training_shift scenario under the PI loop, on three seeds and
# two recording lengths: `drytwin training` writes the recording, `drytwin discover` reads it.
# Prints one line per run and a summary (docs/training.md quotes it).
#   bash scripts/training-discoverability.sh [BUILD_DIR]      (JOBS=2 runs in parallel)
# ORACLE=1: Discover is asked about the fault alone (`discover --causes CAUSE`): the bound on what
# any choice among the candidates can reach with discovery's judgement rules.
# REFERENCE=1: each recording is judged against the line's healthy commissioning data
# (`discover --reference`): six fault-free runs of the same scenario, the seeds the Training tab's
# monitor commissions on (seed + 90001 … 90006, engine/training/LineMonitor.h), whole length;
# COMMISSIONING_RUNS=N: N of them (seed + 90001 … 90000 + N) instead of the tab's 6.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
drytwin="$build/app/drytwin"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
scenario="$(cat "$here/resources/scenarios/training_shift.json")"
declare -A strength=([tube_wall_heat_loss]=0.2 [gas_phase_coupling]=1.0 [heat_transfer_fouling]=0.4
                     [moisture_meter_lag]=60 [moisture_meter_offset]=0.4 [transport_delay_error]=30
                     [falling_rate_drying]=1.0 [ambient_reabsorption]=6)
run() {
  local cause=$1 strength=$2 seed=$3 minutes=$4
  local dir="$work/$cause-$seed-$minutes"
  mkdir -p "$dir"
  local s="${scenario/\"seed\": 7/\"seed\": $seed}"
  cat > "$dir/script.json" <<JSON
{"scenario": $s, "end_s": $((minutes * 60)),
 "events": [{"at_s": 0, "type": "fault", "cause": "$cause", "strength": $strength, "onset_s": 300}]}
JSON
  "$drytwin" -q training --script "$dir/script.json" --out "$dir/out" >/dev/null
  local named
  local only=()
  if [ -n "${ORACLE:-}" ]; then only=(--causes "$cause"); fi
  if [ -n "${REFERENCE:-}" ]; then only+=(--reference "$work/commissioning-$seed"); fi
  # Each finding as its cause and the look-alikes not ruled out ("a|b"), as study_discovery prints it.
  named=$("$drytwin" -q discover --data "$dir/out/recording" "${only[@]}" --json "$dir/d.json" >/dev/null 2>&1;
          python3 -c "import json,sys; d=json.load(open('$dir/d.json')); print(','.join('|'.join([f['cause']] + [l['cause'] for l in f.get('look_alikes', []) if not l.get('ruled_out')]) for f in d.get('findings',[])) or '-')")
  local first=${named%%,*}
  local verdict=no
  if [ "${first%%|*}" = "$cause" ]; then verdict=yes; elif [[ "|$first|" == *"|$cause|"* ]]; then verdict=group; fi
  echo "$cause seed=$seed ${minutes}min named=$named first_right=$verdict"
}
# The commissioning runs of the line of each seed: fault-free, the scenario's whole length.
commission() {
  local seed=$1 run=$2
  local dir="$work/commissioning-run-$seed-$run"
  mkdir -p "$dir" "$work/commissioning-$seed"
  local s="${scenario/\"seed\": 7/\"seed\": $((seed + 90000 + run))}"
  echo "{\"scenario\": $s, \"events\": []}" > "$dir/script.json"
  "$drytwin" -q training --script "$dir/script.json" --out "$dir/out" >/dev/null
  # Each run its own batch id (a recording is named after its scenario, and ids must be unique).
  for f in "$dir"/out/recording/*.csv; do
    sed "s/^# batch: .*/# batch: C$run/" "$f" > "$work/commissioning-$seed/C$run.csv"
  done
}
export -f run commission
export drytwin work scenario
if [ -n "${REFERENCE:-}" ]; then
  for seed in 7 8 9; do for r in $(seq 1 "${COMMISSIONING_RUNS:-6}"); do echo "$seed $r"; done; done |
    xargs -P "${JOBS:-2}" -L 1 bash -c 'commission "$@"' _
fi
results="$work/results.txt"
for minutes in 30 60; do
  for seed in 7 8 9; do
    for cause in "${!strength[@]}"; do
      echo "$cause ${strength[$cause]} $seed $minutes"
    done
  done
done | xargs -P "${JOBS:-2}" -L 1 bash -c 'run "$@"' _ | tee "$results"
for minutes in 30 60; do
  total=$(grep -c " ${minutes}min" "$results")
  right=$(grep " ${minutes}min" "$results" | grep -c "first_right=yes" || true) # grep -c exits 1 on 0
  group=$(grep " ${minutes}min" "$results" | grep -c "first_right=group" || true)
  echo "recording ${minutes} min: right cause first in $right of $total, $((right + group)) counting its look-alike group (as study_discovery does)"
done
