#!/usr/bin/env bash
# Screenshots of every tab of the real program under Xvfb, with the bundled demo loaded and the
# main actions run (calibrate from the paper's parameters, train, discover, the paper-like MPC
# scenario), in English and Simplified Chinese: docs/screenshots/<lang>/NN-<tab>.png. The project
# is saved after that run and reopened in a new window, whose tabs go to
# docs/screenshots/<lang>/reopened/ (what a reopened project shows without re-running anything).
# A historian export of the demo's first four batches (tag names, time stamps, decimal commas, line
# stops between the runs; scripts/lib/historian_export.py) is opened with the column mapping the
# dialog proposes and run the same way: docs/screenshots/<lang>/historian/.
# The Training tab shows the example session of docs/training-example.json (replayed headless
# first), in the trainee's and the instructor's view.
#   bash scripts/screenshots.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
out="${2:-$here/docs/screenshots}"
drytwin="$build/app/drytwin"
demo="$build/demo-data"
if [ ! -d "$demo" ]; then
  "$drytwin" -q generate --demo --seed 2025 --out "$demo"
fi
session="$build/training-example"
"$drytwin" -q training --script "$here/docs/training-example.json" --out "$session" >/dev/null
projects="$build/screenshot-projects"
for lang in en zh_CN; do
  # The tabs' pictures only: others beside them (discover-reference.png, scripts/demo-reference.sh) stay.
  rm -rf "$out/$lang/reopened" "$projects/$lang"
  rm -f "$out/$lang"/[0-9][0-9]-*.png
  xvfb-run -a -s "-screen 0 1280x800x24" "$drytwin" --lang "$lang" --data "$demo" \
    --training "$session/session.json" --run calibrate,train,discover,mpc \
    --save-project "$projects/$lang/demo.drytwin" --screenshot "$out/$lang"
  xvfb-run -a -s "-screen 0 1280x800x24" "$drytwin" --lang "$lang" --project "$projects/$lang/demo.drytwin" \
    --training "$session/session.json" --screenshot "$out/$lang/reopened"
done
historian="$build/screenshot-historian"
mkdir -p "$historian"
python3 "$here/scripts/lib/historian_export.py" "$demo" "$historian/historian-export.csv" "$historian/historian-export-mapping.json" 4
for lang in en zh_CN; do
  rm -rf "$out/$lang/historian"
  xvfb-run -a -s "-screen 0 1280x800x24" "$drytwin" --lang "$lang" --data "$historian/historian-export.csv" \
    --mapping "$historian/historian-export-mapping.json" --run calibrate,train,discover,mpc --screenshot "$out/$lang/historian"
done
ls "$out"/*/
# The column-mapping dialog on a historian export with tag names, and the Data tab with the runs
# it gives (taken by test_mainwindow when DRYTWIN_SCREENSHOT_DIR is set).
mkdir -p "$out/en"
DRYTWIN_NO_MODAL=1 DRYTWIN_SCREENSHOT_DIR="$out/en" xvfb-run -a -s "-screen 0 1280x800x24" \
  "$build/tests/widgets/test_mainwindow" historianExportIsGuessedPreviewedAndLoaded >/dev/null
# The same dialog in Chinese (its units worded, issue #72 item 6).
mkdir -p "$out/zh_CN"
DRYTWIN_SCREENSHOT_DIR="$out/zh_CN" xvfb-run -a -s "-screen 0 1280x800x24" \
  "$build/tests/widgets/test_column_mapping" theDialogsUnitsAreInTheWindowsLanguage >/dev/null
