#!/bin/sh
# Runs COMMAND and sends it SIGTERM once HISTORY has at least ROWS lines (the run flushes one row
# per accepted step), so the signal lands at a chosen point of the run whatever the machine's
# speed. Exits with COMMAND's exit code (128 + 15 if the signal ended it unhandled).
# Usage: signal_at_history_row.sh HISTORY ROWS COMMAND [ARGUMENTS...]
history=$1
rows=$2
shift 2
"$@" &
pid=$!
while kill -0 "$pid" 2>/dev/null; do
  if [ -f "$history" ] && [ "$(wc -l <"$history")" -ge "$rows" ]; then
    kill -TERM "$pid"
    break
  fi
  sleep 0.05
done
wait "$pid"
