#!/usr/bin/env bash
# The GUI's two budgets on the demo (issue #13), measured on the real program under Xvfb:
#  1. open the 10-batch demo and simulate it: time until the full plot is drawn (goal < 3 s);
#  2. demo loaded, simulated, trained, every tab opened: peak resident memory (goal < 1.5 GB).
#   bash scripts/measure-gui.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
drytwin="$build/app/drytwin"
demo="$build/demo-data"
[ -d "$demo" ] || "$drytwin" -q generate --demo --seed 2025 --out "$demo"
out="$(mktemp -d)"
xvfb-run -a -s "-screen 0 1280x800x24" "$drytwin" --data "$demo" --screenshot "$out/plot.png" 2>&1 |
  grep "drawn"
/usr/bin/time -f "peak resident memory after load, simulate, train and every tab: %M KB" \
  xvfb-run -a -s "-screen 0 1280x800x24" "$drytwin" --data "$demo" --run train --screenshot "$out/tabs" 2>&1 |
  grep -E "peak resident|drawn"
rm -rf "$out"
