#!/usr/bin/env bash
# Runs a command that must fail: exit status EXPECTED_STATUS, and stderr exactly one line that
# contains EXPECTED_TEXT.  usage: expect_error.sh EXPECTED_STATUS EXPECTED_TEXT COMMAND...
set -u
expected_status=$1 expected_text=$2
shift 2
stderr=$("$@" 2>&1 >/dev/null)
status=$?
lines=$(printf '%s\n' "$stderr" | grep -c .)
echo "exit status $status, stderr: $stderr"
[ "$status" -eq "$expected_status" ] || { echo "FAIL: expected exit status $expected_status"; exit 1; }
[ "$lines" -eq 1 ] || { echo "FAIL: expected one line on stderr, got $lines"; exit 1; }
case "$stderr" in
  *"$expected_text"*) echo "ok" ;;
  *) echo "FAIL: stderr does not contain: $expected_text"; exit 1 ;;
esac
