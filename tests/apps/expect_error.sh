#!/usr/bin/env bash
# Runs a command that must fail: exit status EXPECTED_STATUS, and stderr exactly one line that
# contains EXPECTED_TEXT.  usage: expect_error.sh EXPECTED_STATUS EXPECTED_TEXT COMMAND...
set -u
expected_status=$1 expected_text=$2
shift 2
. "$(dirname "$0")/one_line_error.sh"
stderr=$("$@" 2>&1 >/dev/null)
status=$?
check_one_line_error "$status" "$stderr" "$expected_status" "$expected_text" || exit 1
echo "ok"
