#!/usr/bin/env bash
# live --reference: the monitor fitted on a healthy reference period judges a healthy line
# published at 200x: one window a minute published under the twin's prefix with its statistics and
# limits, and no alarm (the seeds are fixed, so this is one draw at the 1 % false-alarm rate).
# Usage: MonitorPublishesWindows.sh DRYTWIN MOSQUITTO MOSQUITTO_SUB WORK
set -euo pipefail
EXE=$1 MOSQUITTO=$2 SUB=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK"
. "$(dirname "$0")/broker.sh"
start_broker

"$EXE" -q generate --out "$WORK/reference" --batches 3 --samples 1200 --seed 21 > /dev/null
"$SUB" -h 127.0.0.1 -p "$PORT" -q 1 -t 'drytwin/line1/twin/#' -v > "$WORK/twin.out" &
SUB_PID=$!
trap 'kill $SUB_PID 2>/dev/null; stop_broker' EXIT
"$EXE" -q live --broker "$BROKER_URL" --reference "$WORK/reference" --duration 60 \
  > "$WORK/live.out" 2> "$WORK/live.err" &
LIVE_PID=$!
wait_for_line "$WORK/live.err" "subscribed to 13 topics" 20
grep -q "monitor fitted on the reference" "$WORK/live.err" || fail "no word of the monitor: $(cat "$WORK/live.err")"

"$EXE" -q generate --publish "$BROKER_URL" --speed 200 --batches 1 --samples 1200 --seed 33 > "$WORK/publish.out"
sleep 1
kill -INT "$LIVE_PID"
set +e
wait "$LIVE_PID"
rc=$?
set -e
LIVE_PID=
cat "$WORK/live.out"
[ "$rc" -eq 130 ] || fail "live ended with $rc, expected 130 after Ctrl+C: $(cat "$WORK/live.err")"
grep -q "monitor: 20 windows published under drytwin/line1/twin/monitor; no alarm" "$WORK/live.out" \
  || fail "expected 20 windows (1200 s, one a minute) and no alarm on a healthy line"
sleep 0.5
n=$(grep -c '^drytwin/line1/twin/monitor {' "$WORK/twin.out" || true)
[ "$n" -eq 20 ] || fail "$n window messages reached the broker, expected 20"
for key in '"t":' '"batch":"B01"' '"t2":' '"spe":' '"cusum_t2_limit":' '"alarm":false'; do
  grep -q "$key" "$WORK/twin.out" || fail "the window messages lack $key: $(head -2 "$WORK/twin.out")"
done
! grep -q '^drytwin/line1/twin/alarm' "$WORK/twin.out" || fail "an alarm was published on a healthy line"
echo "PASS"
