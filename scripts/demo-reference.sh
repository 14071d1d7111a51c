#!/usr/bin/env bash
# The story of issue #41 on the virtual plant: six healthy batches (the reference period, the
# weeks after commissioning), then four batches in which the outlet NIR meter's window fogs up 20
# minutes into each batch (its air purge failed) and reads 0.8 % wb high until it is wiped at the
# batch change. Six, not four: against four the monitors' normal run-to-run spread (taken at its
# upper 75 % bound, docs/reference-period.md) left this change at p 0.008, under the alarm. Opens the GUI on it with the reference set, or runs `discover --reference`
# headless. Run scripts/run.sh (or scripts/test.sh) once first: it builds build/app/drytwin.
set -euo pipefail
cd "$(dirname "$0")/.."
DRYTWIN="${DRYTWIN:-build/app/drytwin}" # the program, and where the story goes (ctest sets both)
OUT="${OUT:-build/demo-reference}"
"$DRYTWIN" generate --out "$OUT/reference" --seed 2030 --batches 6 --samples 3000
"$DRYTWIN" generate --out "$OUT/after" --seed 2031 --batches 4 --samples 3000 \
  --effect moisture_meter_offset=0.8 --onset moisture_meter_offset=1200 --truth "$OUT/truth.json"
if [ -n "${DISPLAY:-}" ] && [ "${DRYTWIN_HEADLESS:-0}" != "1" ]; then
  exec "$DRYTWIN" --data "$OUT/after" --reference "$OUT/reference" --run discover
fi
exec "$DRYTWIN" discover --reference "$OUT/reference" --data "$OUT/after" --json "$OUT/discover.json"
