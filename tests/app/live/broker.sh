# Sourced by the live tests: starts a Mosquitto broker of the test's own on a free loopback port
# and stops it when the test's shell exits. Sets PORT, BROKER_URL and BROKER_PID.
# Usage: MOSQUITTO=/usr/sbin/mosquitto WORK=dir; . broker.sh; start_broker
start_broker() {
  local conf="$WORK/mosquitto.conf" attempt
  for attempt in 1 2 3 4 5 6 7 8 9 10; do
    # A random port in the dynamic range; taken ones make the broker exit, and another is tried.
    PORT=$(( 20000 + (RANDOM * 32768 + RANDOM) % 40000 ))
    # Mosquitto 2 listens on loopback only and refuses anonymous clients unless told otherwise
    # (PLATFORM-NOTES.md). No queue limit: a subscriber behind a 200x publisher must lose nothing.
    cat > "$conf" <<CONF
listener $PORT 127.0.0.1
allow_anonymous true
persistence false
max_queued_messages 0
log_dest stderr
CONF
    # Its log to stderr, into the work folder: run as root it drops to the mosquitto user, which
    # could not open a log file there.
    "$MOSQUITTO" -c "$conf" 2>> "$WORK/mosquitto.log" &
    BROKER_PID=$!
    local i
    for i in $(seq 1 50); do
      if ! kill -0 "$BROKER_PID" 2>/dev/null; then
        break # port taken (or bad config): try another
      fi
      if (exec 3<>"/dev/tcp/127.0.0.1/$PORT") 2>/dev/null; then
        BROKER_URL="mqtt://127.0.0.1:$PORT"
        trap stop_broker EXIT
        return 0
      fi
      sleep 0.1
    done
    kill "$BROKER_PID" 2>/dev/null
    wait "$BROKER_PID" 2>/dev/null
  done
  echo "FAIL: could not start mosquitto on a free port (see $WORK/mosquitto.log)" >&2
  exit 1
}

stop_broker() {
  if [ -n "${LIVE_PID:-}" ]; then kill "$LIVE_PID" 2>/dev/null; fi
  if [ -n "${BROKER_PID:-}" ]; then kill "$BROKER_PID" 2>/dev/null; wait "$BROKER_PID" 2>/dev/null; fi
}

# wait_for_line FILE REGEX SECONDS: until FILE holds a line matching REGEX.
wait_for_line() {
  local i
  for i in $(seq 1 $(( $3 * 10 ))); do
    if grep -qE "$2" "$1" 2>/dev/null; then return 0; fi
    sleep 0.1
  done
  echo "FAIL: '$2' did not appear in $1 within $3 s:" >&2
  cat "$1" >&2
  exit 1
}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}
