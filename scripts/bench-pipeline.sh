#!/usr/bin/env bash
# The pipeline benchmark of issue #44: `drytwin pipeline` on the bundled demo (seed 2025),
# three runs one after the other, each one's wall clock, CPU and peak memory and its stage
# table, then the median wall clock. Run it on an idle machine: the figure is the machine's
# as much as the program's. Usage: bash scripts/bench-pipeline.sh [build-dir] [runs]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
RUNS="${2:-3}"
DRYTWIN="$BUILD/app/drytwin"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
"$DRYTWIN" -q generate --demo --seed 2025 --out "$WORK/demo" > /dev/null
echo "$(date -u +%Y-%m-%dT%H:%MZ) $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(nproc) cores"
walls=()
for run in $(seq 1 "$RUNS"); do
  /usr/bin/time -f "%e %U %S %M" -o "$WORK/time" "$DRYTWIN" pipeline --data "$WORK/demo" \
    --out "$WORK/report-$run" > "$WORK/log-$run" 2> /dev/null
  read -r wall user sys peak < "$WORK/time"
  walls+=("$wall")
  printf 'run %d: %6.1f s wall clock, %6.1f s CPU, %5.0f MB peak; stages:' "$run" "$wall" \
    "$(echo "$user + $sys" | bc)" "$(echo "$peak / 1024" | bc)"
  sed -n '/^== stages ==$/,/^$/p' "$WORK/log-$run" | awk 'NF >= 3 && $2 ~ /^[0-9.]+$/ {printf " %s %s", $1, $2}'
  echo
done
median=$(printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}')
echo "median wall clock over $RUNS runs: $median s (issue #44: <= 120 s)"
