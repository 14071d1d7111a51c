#!/usr/bin/env bash
# The virtual line published at 200x and recorded by drytwin live: the recording equals the
# batch files generate writes for the same options, sample for sample (no loss, no duplicate,
# the sensors' dropouts as missing cells), and drytwin can open it as a data set.
# Usage: RecordsPublishedLine.sh DRYTWIN MOSQUITTO WORK
set -euo pipefail
EXE=$1 MOSQUITTO=$2 WORK=$3
rm -rf "$WORK" && mkdir -p "$WORK"
. "$(dirname "$0")/broker.sh"
start_broker

# 2 batches of 600 s: 20 minutes of line time, with realistic sensors and dropouts (null values).
PLANT=(--batches 2 --samples 600 --seed 11 --sensor-dropouts 30)
"$EXE" -q generate --out "$WORK/files" "${PLANT[@]}" > "$WORK/generate-files.out"

"$EXE" -q live --broker "$BROKER_URL" --record "$WORK/recording" --duration 50 \
  > "$WORK/live.out" 2> "$WORK/live.err" &
LIVE_PID=$!
wait_for_line "$WORK/live.err" "subscribed to 13 topics" 10

start=$(date +%s%N)
"$EXE" -q generate --publish "$BROKER_URL" --speed 200 "${PLANT[@]}" > "$WORK/publish.out" \
  || fail "generate --publish failed: $(cat "$WORK/publish.out")"
grep -q "published 2 batch(es), 1200 samples (14402 messages" "$WORK/publish.out" \
  || fail "unexpected publish summary: $(cat "$WORK/publish.out")"
echo "published in $(( ($(date +%s%N) - start) / 1000000 )) ms: $(cat "$WORK/publish.out")"

# Ctrl+C once the stream is in (the reorder window waits for nothing at the end): exit 130,
# the recording written.
sleep 1
kill -INT "$LIVE_PID"
set +e
wait "$LIVE_PID"
rc=$?
set -e
LIVE_PID=
[ "$rc" -eq 130 ] || fail "live ended with $rc, expected 130 after Ctrl+C: $(cat "$WORK/live.out" "$WORK/live.err")"
cat "$WORK/live.out"
grep -qE "recorded 1200 rows in 2 file\(s\).*: 14400 samples, 0 late, 0 duplicate, 0 malformed" "$WORK/live.out" \
  || fail "counts differ from what was published"

for b in B01 B02; do
  [ -f "$WORK/recording/$b.csv" ] || fail "no recording of batch $b: $(ls "$WORK/recording")"
  # Metadata lines differ (source, start); header and every row must be the same text, which
  # (shortest exact decimals on both sides) means the same doubles and the same missing cells.
  grep -v '^#' "$WORK/files/$b.csv" > "$WORK/$b.expected"
  grep -v '^#' "$WORK/recording/$b.csv" > "$WORK/$b.recorded"
  if ! cmp -s "$WORK/$b.expected" "$WORK/$b.recorded"; then
    diff "$WORK/$b.expected" "$WORK/$b.recorded" | head -20 >&2
    fail "recording of $b differs from the published samples"
  fi
  empty=$(grep -cE '(^|,)(,|$)' "$WORK/$b.recorded" || true)
  echo "$b: $(($(wc -l < "$WORK/$b.recorded") - 1)) rows identical, $empty with missing cells"
done
[ "$(ls "$WORK/recording" | wc -l)" -eq 2 ] || fail "extra files in the recording: $(ls "$WORK/recording")"

"$EXE" -q inspect --data "$WORK/recording" > "$WORK/inspect.out" || fail "inspect cannot open the recording"
grep -q "B02" "$WORK/inspect.out" || fail "inspect does not list B02"
echo "PASS"
