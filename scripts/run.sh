#!/usr/bin/env bash
# Set-up and the main job: install packages, configure, build, then open the GUI on the
# bundled demo data set, or run `drytwin pipeline` on it when there is no display.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
source scripts/lib/configure-build.sh
configure_build build
# Only what the main job needs (the program and its translations): the tests and benchmarks are
# built by scripts/test.sh, which reuses this build directory.
cmake --build build -j"$(nproc)" --target drytwin drytwin_translations
DRYTWIN=build/app/drytwin
DEMO=build/demo-data
if [ ! -f "$DEMO/.complete" ]; then
  if "$DRYTWIN" generate --demo --out "$DEMO" --seed 2025 --truth build/demo-truth.json; then
    touch "$DEMO/.complete"
  else
    rc=$?
    echo "run.sh: generating the demo data set failed (exit $rc); showing the command-line help instead" >&2
    "$DRYTWIN" --help
    exit 0
  fi
fi
if [ -n "${DISPLAY:-}" ] && [ "${DRYTWIN_HEADLESS:-0}" != "1" ]; then
  exec "$DRYTWIN" --data "$DEMO"
fi
exec "$DRYTWIN" pipeline --data "$DEMO" --out build/demo-report
