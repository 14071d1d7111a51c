#!/usr/bin/env bash
# 1,000 bad messages beside a good stream, sent with mosquitto_pub: 300 duplicates (other values),
# 300 late ones (for rows already written), 400 malformed ones. Each is counted in its kind, none
# crashes drytwin live, none enters the recording; the gap in the good stream stays missing.
# Also: the topic mapping (a renamed tag, a batch-id topic) and --duration.
# Usage: CountsBadMessages.sh DRYTWIN MOSQUITTO MOSQUITTO_PUB WORK
set -euo pipefail
EXE=$1 MOSQUITTO=$2 PUB=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK"
. "$(dirname "$0")/broker.sh"
start_broker

cat > "$WORK/topics.json" <<'JSON'
{"X_out_pct": "plant/NIR_OUT", "batch_id": "plant/BATCH", "prefix": "twin/lineA"}
JSON
"$EXE" -q live --broker "$BROKER_URL" --topics "$WORK/topics.json" --topic-prefix test/lineA \
  --record "$WORK/recording" --reorder-window 40 --duration 12 > "$WORK/live.out" 2> "$WORK/live.err" &
LIVE_PID=$!
wait_for_line "$WORK/live.err" "subscribed to 13 topics" 10

T0=$(( $(date +%s) - 1000 ))
pub() { # pub TOPIC < lines: one message per line, QoS 1
  "$PUB" -h 127.0.0.1 -p "$PORT" -q 1 -t "$1" -l
}
# The good stream: the batch's id, X_out_pct on its mapped topic without seconds 10-14 (a gap),
# T_out_C for the first 30 s on the default topic under the prefix, then X_out_pct to second 79.
# The 40 s reorder window takes the first two streams in either order; the third makes rows up to
# second 39 final. Values end in 5: their shortest text is as written.
echo "{\"t\": $T0, \"v\": \"Run7\"}" | pub plant/BATCH
for s in $(seq 0 29); do
  if [ "$s" -lt 10 ] || [ "$s" -gt 14 ]; then echo "{\"t\": $((T0 + s)), \"v\": 12.${s}5}"; fi
done | pub plant/NIR_OUT
for s in $(seq 0 29); do echo "{\"t\": $((T0 + s)), \"v\": 40.${s}5}"; done | pub test/lineA/T_out_C
for s in $(seq 30 79); do echo "{\"t\": $((T0 + s)), \"v\": 12.${s}5}"; done | pub plant/NIR_OUT
sleep 1 # the rows older than the reorder window are now written

# 300 duplicates with other values: the first sample of each second is kept.
for i in $(seq 1 300); do s=$(( 15 + i % 15 )); echo "{\"t\": $((T0 + s)), \"v\": 99}"; done | pub plant/NIR_OUT
# 300 late: 100 into the gap after its rows were written, 200 before the batch began.
for i in $(seq 1 100); do s=$(( 10 + i % 5 )); echo "{\"t\": $((T0 + s)), \"v\": 13}"; done | pub plant/NIR_OUT
for i in $(seq 1 200); do echo "{\"t\": $((T0 - i)), \"v\": 41}"; done | pub test/lineA/T_out_C
# 400 malformed: not JSON, text for a number, a time that is none, no value, a JSON array.
for i in $(seq 1 80); do
  echo 'wet'
  echo '{"t": 1, "v": "wet"}'
  echo '{"t": "yesterday", "v": 1}'
  echo '{"t": 1}'
  echo '[1, 2]'
done | pub plant/NIR_OUT

set +e
wait "$LIVE_PID"
rc=$?
set -e
LIVE_PID=
cat "$WORK/live.out"
[ "$rc" -eq 0 ] || fail "live ended with $rc (expected 0 after --duration): $(cat "$WORK/live.err")"
grep -qE "recorded 80 rows in 1 file\(s\).*: 105 samples, 300 late, 300 duplicate, 400 malformed, 55 missing cells" \
  "$WORK/live.out" || fail "the counts are not 300 late, 300 duplicate, 400 malformed, 55 missing"
grep -q "malformed message on plant/NIR_OUT: not a number or JSON (not recorded)" "$WORK/live.err" \
  || fail "the first malformed message is not named with its topic and cause: $(cat "$WORK/live.err")"

[ -f "$WORK/recording/Run7.csv" ] || fail "no Run7.csv (batch id from the mapped topic): $(ls "$WORK/recording")"
{
  echo "time_s,X_out_pct,T_out_C"
  for s in $(seq 0 79); do
    x="12.${s}5" t="40.${s}5"
    if [ "$s" -ge 10 ] && [ "$s" -le 14 ]; then x=""; fi
    if [ "$s" -ge 30 ]; then t=""; fi
    echo "$s,$x,$t"
  done
} > "$WORK/expected.csv"
grep -v '^#' "$WORK/recording/Run7.csv" > "$WORK/recorded.csv"
if ! cmp -s "$WORK/expected.csv" "$WORK/recorded.csv"; then
  diff "$WORK/expected.csv" "$WORK/recorded.csv" >&2 || true
  fail "the recording holds other rows than the good stream"
fi
grep -q "^# batch: Run7" "$WORK/recording/Run7.csv" || fail "no '# batch: Run7' line"
echo "PASS"
