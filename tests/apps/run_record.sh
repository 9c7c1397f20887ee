#!/usr/bin/env bash
# The run folder records itself (issue 20): run.json says which tissu ran what and how it ended,
# scenario.json is the scenario as run and passes `tissu check`; a failed run is recorded too.
# usage: run_record.sh TISSU SCENARIOS_DIR OUT_DIR
set -u
tissu=$1 scenarios=$2 out=$3
rm -rf "$out"
fail() { echo "FAIL: $*"; exit 1; }
# field NAME FILE: the value of "NAME": ... on its own line of a JSON file written with indent 2
field() { sed -n "s/^  \"$1\": \(.*\),\{0,1\}\$/\1/p" "$2" | sed 's/,$//'; }

"$tissu" run "$scenarios/tiny.json" --out "$out/tiny" --quiet --set cloth.density=0.3 ||
  fail "the run failed"
record=$out/tiny/run.json
[ "$(field status "$record")" = '"completed"' ] || fail "status: $(field status "$record")"
[ "$(field exit_status "$record")" = 0 ] || fail "exit_status: $(field exit_status "$record")"
[ "$(field frames_done "$record")" = 3 ] || fail "frames_done: $(field frames_done "$record")"
grep -q '"cloth.density=0.3"' "$record" || fail "the override is not recorded"
grep -Eq '"commit": "([0-9a-f]{40}(-dirty)?|unknown)"' "$record" || fail "no commit"
version=$("$tissu" --version) || fail "--version failed"
[ "$(field tissu_version "$record")" = "\"$(echo "$version" | cut -d' ' -f2)\"" ] ||
  fail "run.json's version is not --version's ($version)"

# scenario.json: the override in it, and it checks as a valid scenario
grep -q '"density": 0.3' "$out/tiny/scenario.json" || fail "scenario.json lacks the override"
"$tissu" check "$out/tiny/scenario.json" > "$out/resolved_again.json" 2>/dev/null ||
  fail "tissu check refuses the scenario.json a run wrote"
cmp -s "$out/resolved_again.json" <(cat "$out/tiny/scenario.json") ||
  fail "scenario.json does not check as itself"

# a diverging run: exit 2, recorded as failed with its message
"$tissu" run "$scenarios/exploding.json" --out "$out/exploding" --quiet 2>/dev/null
[ $? = 2 ] || fail "the exploding run did not exit with 2"
record=$out/exploding/run.json
[ "$(field status "$record")" = '"failed"' ] || fail "exploding status: $(field status "$record")"
[ "$(field exit_status "$record")" = 2 ] || fail "exploding exit_status"
grep -q '"message": "simulation failed at frame' "$record" || fail "no failure message"

# a scenario refused for its mesh leaves an earlier run's folder as it was
before=$(ls -l --time-style=full-iso "$out/tiny")
"$tissu" run "$scenarios/missing_mesh.json" --out "$out/tiny" --quiet 2>/dev/null
[ $? = 1 ] || fail "the missing mesh was not refused with exit status 1"
[ "$(ls -l --time-style=full-iso "$out/tiny")" = "$before" ] ||
  fail "a refused scenario changed the earlier run's folder"
echo ok
