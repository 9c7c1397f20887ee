#!/usr/bin/env bash
# Sends SIGNAL to a running `tissu run` (or `tissu render`) once it has written a few frames (or
# images): it must stop with EXPECTED_STATUS (128 + the signal) and one line on stderr saying it
# was stopped, every file whole and, for a run, as many stats.csv rows as meshes. Waits are
# generous and nothing is timed: the test only needs the run to be longer than its first frames.
# usage: stop_signal.sh TISSU SCENARIO OUT_DIR SIGNAL EXPECTED_STATUS run|render
set -u
tissu=$1 scenario=$2 out=$3 signal=$4 expected_status=$5 command=$6
. "$(dirname "$0")/complete_outputs.sh"
. "$(dirname "$0")/one_line_error.sh"
dir=$out/$command-$signal
rm -rf "$dir"
mkdir -p "$dir"

# waits (up to 300 s) until `$1` prints a number >= $2, while the process $pid lives
wait_for() {
  local i
  for i in $(seq 1 3000); do
    [ "$(eval "$1")" -ge "$2" ] 2>/dev/null && return 0
    kill -0 "$pid" 2>/dev/null || { echo "FAIL: tissu ended before it was signalled"; cat "$dir.err"; exit 1; }
    sleep 0.1
  done
  echo "FAIL: nothing written after 300 s"
  kill -KILL "$pid"
  exit 1
}

if [ "$command" = run ]; then
  # far more frames than are ever reached: the signal ends it
  "$tissu" run "$scenario" --out "$dir" --quiet --frames 1000000 \
    --set "cloth.grid.resolution=[30,30]" 2>"$dir.err" &
  pid=$!
  wait_for "grep -c . '$dir/stats.csv' 2>/dev/null" 4  # the header and 3 frames
else
  "$tissu" run "$scenario" --out "$dir" --quiet --frames 300 || exit 1
  rm -f "$dir/stats.csv"
  # large images take the renderer long enough that the signal comes before the last one
  "$tissu" render "$dir" --quiet --width 1280 --height 960 2>"$dir.err" &
  pid=$!
  wait_for "ls '$dir' | grep -c '^frame_.*\.png$'" 1
fi
kill -s "$signal" "$pid"
wait "$pid"
status=$?
check_one_line_error "$status" "$(cat "$dir.err")" "$expected_status" "stopped by SIG$signal" ||
  exit 1
check_complete_outputs "$dir" || { echo "FAIL: an output is not whole"; exit 1; }
if [ "$command" = run ]; then
  meshes=$(ls "$dir" | grep -c '^frame_.*\.obj$')
  rows=$(($(wc -l < "$dir/stats.csv") - 1))
  echo "$meshes meshes, $rows stats rows"
  [ "$meshes" -eq "$rows" ] || { echo "FAIL: $meshes meshes but $rows stats rows"; exit 1; }
else
  images=$(ls "$dir" | grep -c '^frame_.*\.png$')
  echo "$images images"
  [ "$images" -lt 301 ] || { echo "FAIL: every image was rendered: not stopped"; exit 1; }
  [ ! -e "$dir/$(basename "$dir").mp4" ] || { echo "FAIL: a video was made"; exit 1; }
fi
echo ok
