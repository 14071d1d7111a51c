#!/usr/bin/env bash
# PGRL-CC's forecasts with and without one of its forecast-time switches (issue #42,
# docs/hybrid-study.md): the ten data sets of `study_hybrid --part unseen` on seeds BASE+1 …
# BASE+10, each generated, calibrated and trained once with the command line (the LSTM for one
# epoch only: it is not what is compared), then evaluated twice from the same model file, with
# the switch off and on. SWITCH:
#   realised-weights  the three realised-weight switches of 2026-11-27 (off: the trained s_H and
#                     held error alone)
#   learnt-bound      the bound on the learnt correction of 2026-11-27, late (off: taken out of
#                     the model file, the learnt part unbounded)
#   held-error-decay  the third realised weight alone (off: the error held at the origin is never
#                     let go; the reference blend and the learnt part's weight as on)
# Usage: scripts/study-forecast-switch.sh SWITCH [BASE (default 960)] [WORK (default /tmp/drytwin-SWITCH)]
# Prints, per data set and switch setting, PGRL-CC's moisture skill at each horizon 1-180.
set -euo pipefail
cd "$(dirname "$0")/.."
SWITCH="${1:?usage: $0 realised-weights|learnt-bound|held-error-decay [BASE] [WORK]}"
case "$SWITCH" in realised-weights|learnt-bound|held-error-decay) ;; *) echo "$0: unknown switch '$SWITCH'" >&2; exit 2;; esac
BASE="${2:-960}"
WORK="${3:-/tmp/drytwin-$SWITCH}"
DRYTWIN="${DRYTWIN:-build/app/drytwin}" # a copy lets a study run beside a rebuild
mkdir -p "$WORK"
sets=()
while read -r kind offset batches samples plant mix faults; do
  seed=$((BASE + offset))
  name="$kind$seed"
  sets+=("$name")
  args=(--seed "$seed" --batches "$batches" --samples "$samples" --plant "$plant" --sensors realistic)
  [ "$mix" = demo ] && args+=(--demo)
  [ "$mix" = drift ] && args+=(--drift)
  # The faults set: five times the transmitters' spike, stuck-value and dropout rates.
  [ "$faults" = 5 ] && args+=(--sensor-spikes 2.5 --sensor-stuck 0.25 --sensor-dropouts 2.5)
  if [ ! -f "$WORK/$name.model.json" ]; then
    rm -rf "${WORK:?}/$name"
    "$DRYTWIN" generate --out "$WORK/$name" "${args[@]}" > /dev/null 2>&1
    "$DRYTWIN" calibrate --data "$WORK/$name" --out "$WORK/$name.cal.json" > /dev/null 2>&1
    "$DRYTWIN" train --data "$WORK/$name" --model "$WORK/$name.cal.json" --out "$WORK/$name.model.json" \
      --lstm-epochs 1 > "$WORK/$name.train.log" 2>&1
  fi
done <<LIST
d 1 3 2000 distributed demo 1
d 2 5 4000 distributed demo 1
d 3 4 3000 distributed null 1
d 4 3 2000 distributed drift 1
d 5 6 4000 distributed null 1
d 6 10 6300 distributed demo 1
d 7 6 4000 distributed demo 5
l 8 5 4000 lumped demo 1
l 9 4 3000 lumped null 1
l 10 10 6300 lumped demo 1
LIST
for setting in off on; do
  echo "$SWITCH $setting"
  for name in "${sets[@]}"; do
    python3 - "$WORK/$name.model.json" "$WORK/$name.$setting.model.json" "$setting" "$SWITCH" <<'PY'
import json, sys
model = json.load(open(sys.argv[1]))
on = sys.argv[3] == "on"
for m in model["residual_models"].values():
    if sys.argv[4] == "learnt-bound":
        if not on:
            m.pop("learnt_bound_by_horizon", None)
    elif sys.argv[4] == "held-error-decay":
        if "options" in m:
            m["options"]["realised_held_error_decay"] = on
    elif "options" in m:
        for key in ("realised_reference_blend", "realised_weight_by_absolute_error", "realised_held_error_decay"):
            m["options"][key] = on
json.dump(model, open(sys.argv[2], "w"))
PY
    "$DRYTWIN" evaluate --data "$WORK/$name" --model "$WORK/$name.$setting.model.json" \
      --json "$WORK/$name.$setting.eval.json" > /dev/null 2>&1
    python3 - "$WORK/$name.$setting.eval.json" "$name" <<'PY'
import json, sys
curve = json.load(open(sys.argv[1]))["horizons"]
k = curve["models"]["pgrl_cc"]["moisture_skill"]
t = curve["models"]["pgrl_cc"]["temperature_skill"]
worst = max(range(len(k)), key=lambda i: k[i])
print("%-5s X worst %.3f (H %d) mean %.3f, H 1 %.3f | T worst %.3f mean %.3f | X by H: %s" % (
    sys.argv[2], k[worst], curve["steps"][worst], sum(k) / len(k), k[0], max(t), sum(t) / len(t),
    " ".join("%.3f" % x for x in k)))
PY
  done
done
