#!/usr/bin/env bash
# Hostile inputs too large, too odd or too special to keep as files in the repository, made here
# and run through expect_error.sh (exit status 1, one line on stderr holding the expected text),
# each under a timeout so that a hang fails the test instead of stalling the suite.
# usage: hostile_generated.sh CASE TISSU WORK_DIR
set -eu
case_name=$1 tissu=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
tiny=$here/scenarios/tiny.json
mkdir -p "$work"
expect() {  # expect TEXT ARGS...: tissu run ARGS must fail with TEXT
  local text=$1
  shift
  exec "$here/expect_error.sh" 1 "$text" timeout 60 "$tissu" run "$@" --out "$work/out" --quiet
}
# N nested arrays: [[[...]]]
nested() { printf "%${1}s" | tr ' ' '['; printf "%${1}s" | tr ' ' ']'; }

case $case_name in
  deep_nesting_file)  # 100,000 nested arrays as a value (a stack overflow once)
    { printf '{"cloth": '; nested 100000; printf ', "simulation": {"frames": 1}}\n'; } >"$work/deep.json"
    expect "deep.json: cloth[0][0]" "$work/deep.json" ;;
  deep_nesting_file_message)
    { printf '{"cloth": '; nested 100000; printf ', "simulation": {"frames": 1}}\n'; } >"$work/deep.json"
    expect "nested more than 64 levels deep" "$work/deep.json" ;;
  deep_nesting_set_value)  # 60,000 levels through --set
    expect "tiny.json: cloth[0][0][0]" "$tiny" --set "cloth=$(nested 60000)" ;;
  deep_nesting_set_path)
    path=$(printf 'a.%.0s' $(seq 60000))
    expect "a key path of more than 64 keys" "$tiny" --set "${path}a=1" ;;
  set_path_at_the_limit)  # 64 keys put a value inside 64 objects, the limit: an array there is a 65th level
    path=$(printf 'a.%.0s' $(seq 63))
    expect "nested more than 64 levels deep" "$tiny" --set "${path}a=[1]" ;;
  set_invalid_utf8_value)
    expect "tiny.json: --set name=\\xFF: byte 5 is not UTF-8 text" "$tiny" --set "name=$(printf '\377')" ;;
  set_invalid_utf8_key)
    expect "byte 1 is not UTF-8 text" "$tiny" --set "c$(printf '\300\257')=1" ;;
  set_newline_value)
    expect 'tiny.json: simulation.frames: expected an integer from 1 to 10000000, got "1\n2"' \
      "$tiny" --set "simulation.frames=1
2" ;;
  set_newline_key)
    expect 'tiny.json: out\nput: unknown key' "$tiny" --set "out
put=1" ;;
  fifo)  # would block forever in open()
    rm -f "$work/fifo.json"
    mkfifo "$work/fifo.json"
    expect "fifo.json: cannot read the scenario: it is a FIFO (named pipe); expected a regular file" \
      "$work/fifo.json" ;;
  too_large)  # 17 MB of spaces around a scenario
    { head -c 17000000 /dev/zero | tr '\0' ' '; cat "$tiny"; } >"$work/large.json"
    expect "large.json: cannot read the scenario: it has 17000" "$work/large.json" ;;
  too_large_message)
    { head -c 17000000 /dev/zero | tr '\0' ' '; cat "$tiny"; } >"$work/large.json"
    expect "more than the 16777216 (16 MiB) a scenario file may have" "$work/large.json" ;;
  *) echo "unknown case $case_name"; exit 2 ;;
esac
