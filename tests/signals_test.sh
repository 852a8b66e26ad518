#!/usr/bin/env bash
# A run ended by a signal keeps what it computed. SIGTERM (a scheduler's end of the job) and
# SIGHUP (the terminal or its ssh session closed) stop it after the current step with a final
# checkpoint and summary.json, exit 130, and `netsph run --restart` continues it. SIGPIPE (its
# output piped into a reader that stopped reading, `netsph run ... | head -1`) does not end it
# at all: the run finishes, its outputs whole, and exits 0. Likewise a standalone net run,
# which prints its progress on stdout.
set -euo pipefail
netsph="$1"
dambreak="$2"   # cases/dambreak2d.toml
net_case="$3"   # cases/net_bi2014_standalone.toml
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"

# $1: the signal; $2: the run folder. A long run, signalled once it has written a few rows.
stopped_by() {
  local signal="$1" dir="$2"
  "$netsph" run --threads 1 --no-plots "$dambreak" -o "$dir" --set simulation.end_time=100 \
    2>"$dir.err" &
  local pid=$!
  for _ in $(seq 600); do
    [ -f "$dir/series.csv" ] && [ "$(wc -l <"$dir/series.csv")" -ge 3 ] && break
    sleep 0.1
  done
  kill -"$signal" "$pid"
  local status=0
  wait "$pid" || status=$?
  [ "$status" = 130 ] || { echo "SIG$signal: exit status $status, not 130"; cat "$dir.err"; exit 1; }
  grep -q '"status": "interrupted"' "$dir/summary.json" ||
    { echo "SIG$signal: no summary of an interrupted run"; cat "$dir.err"; exit 1; }
  [ -f "$dir/checkpoint.h5" ] || { echo "SIG$signal: no checkpoint"; exit 1; }
  grep -q "SIG$signal" "$dir.err" || { echo "SIG$signal: not named"; cat "$dir.err"; exit 1; }
  local steps
  steps="$(tail -1 "$dir/series.csv" | cut -d, -f3)"
  "$netsph" -q run --threads 1 --no-plots --restart "$dir" --max-steps $((steps + 5))
  [ "$(tail -1 "$dir/series.csv" | cut -d, -f3)" = $((steps + 5)) ] ||
    { echo "SIG$signal: the restart did not continue"; exit 1; }
}
stopped_by TERM term
stopped_by HUP hup

# Every line of the log goes to a pipe whose reader is gone after the first.
set +o pipefail
"$netsph" run --threads 1 --no-plots "$dambreak" -o piped --max-steps 300 2>&1 | head -1 >/dev/null
status="${PIPESTATUS[0]}"
set -o pipefail
[ "$status" = 0 ] || { echo "a run into a closed pipe: exit status $status"; exit 1; }
grep -q '"status": "step limit"' piped/summary.json || { echo "a run into a closed pipe: no summary"; exit 1; }

set +o pipefail
"$netsph" run --no-plots "$net_case" -o net --set simulation.end_time=1 \
  --set 'output.force_window=[0.5, 1.0]' 2>&1 | head -1 >/dev/null
status="${PIPESTATUS[0]}"
set -o pipefail
[ "$status" = 0 ] || { echo "a net run into a closed pipe: exit status $status"; exit 1; }
grep -q '"status": "completed"' net/summary.json || { echo "a net run into a closed pipe: no summary"; exit 1; }
echo "ok: SIGTERM and SIGHUP stop with a checkpoint and a summary; SIGPIPE stops nothing"
