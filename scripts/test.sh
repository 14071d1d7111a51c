#!/usr/bin/env bash
# Set-up and the whole test suite: install packages, configure, build, run CTest.
# DRYTWIN_SANITIZE=ON bash scripts/test.sh builds with ASan+UBSan in build-asan/ instead.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
SANITIZE="${DRYTWIN_SANITIZE:-OFF}"
BUILD_DIR=build
[ "$SANITIZE" = "ON" ] && BUILD_DIR=build-asan
source scripts/lib/configure-build.sh
configure_build "$BUILD_DIR" -DDRYTWIN_SANITIZE="$SANITIZE"
cmake --build "$BUILD_DIR" -j"$(nproc)"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)"
