# Sourced by the CLI test scripts. check_one_line_error STATUS STDERR EXPECTED_STATUS TEXT: prints
# what the command gave, and returns 1 (saying why) unless it exited with EXPECTED_STATUS and wrote
# exactly one line on stderr, containing TEXT.
check_one_line_error() {
  local status=$1 stderr=$2 expected_status=$3 text=$4
  local lines
  lines=$(printf '%s\n' "$stderr" | grep -c .)
  echo "exit status $status, stderr: $stderr"
  [ "$status" -eq "$expected_status" ] || { echo "FAIL: expected exit status $expected_status"; return 1; }
  [ "$lines" -eq 1 ] || { echo "FAIL: expected one line on stderr, got $lines"; return 1; }
  case "$stderr" in
    *"$text"*) ;;
    *) echo "FAIL: stderr does not contain: $text"; return 1 ;;
  esac
}
