#!/usr/bin/env bash
# Soak test (issue 18; not in CI: it takes minutes, after a build of its own): one long run of
# tests/soak/flag_tearing.json, a flag in gusty wind with adaptive refinement and coarsening,
# tearing and knife cuts, until it has made at least MIN_EDITS topological edits (splits + merges
# + tears, summed over stats.csv). It passes when
#   - the build's assertions held: this build keeps them (no -DNDEBUG), and every split, merge and
#     tear asserts is_valid_cloth() on the whole complex right after it (topology/validity.hpp),
#     so the complex was valid after every edit, the last one included;
#   - the run ended normally (exit 0), and
#   - total_mass stayed equal to density x rest area (the first row's) to 1e-12, relative, on every
#     row of stats.csv.
#   usage: scripts/soak.sh [MIN_EDITS] [FRAMES]     (defaults: 100000 edits, 1000 frames: about
#   120,000 edits)
# The run's files are in build/soak/out; the summary line is its last output.
set -euo pipefail
cd "$(dirname "$0")/.."
min_edits=${1:-100000}
frames=${2:-1000}
build=build/soak
out=$build/out

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O2 \
  -DTISSU_BUILD_TESTS=OFF -DTISSU_BUILD_BENCH=OFF > "$build.configure.log"
cmake --build "$build" --parallel "$(nproc)" --target tissu
# the check below relies on the assertions: refuse a build that compiled them out
if grep -q -- "-DNDEBUG" "$build/build.ninja"; then
  echo "soak: $build compiles with -DNDEBUG, so edits would not be checked" >&2
  exit 1
fi

rm -rf "$out"
started=$(date +%s)
"$build/apps/tissu" run tests/soak/flag_tearing.json --frames "$frames" --out "$out"
seconds=$(($(date +%s) - started))

# edits and mass drift from stats.csv, its columns found by name
awk -F, -v min_edits="$min_edits" -v seconds="$seconds" '
  NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
  {
    mass = $column["total_mass"] + 0
    if (NR == 2) first_mass = mass
    drift = (mass - first_mass) / first_mass
    if (drift < 0) drift = -drift
    if (drift > max_drift) { max_drift = drift; worst_frame = $column["frame"] }
    splits += $column["splits"]; merges += $column["merges"]; tears += $column["tears"]
    rows += 1; particles = $column["particles"]; pieces = $column["pieces"]
  }
  END {
    edits = splits + merges + tears
    printf "soak: %d frames in %d s, %d edits (%d splits, %d merges, %d tears), %d particles and %d pieces at the end; total mass %.17g kg, largest relative drift %.3g (frame %d)\n",
      rows - 1, seconds, edits, splits, merges, tears, particles, pieces, first_mass, max_drift, worst_frame
    if (max_drift > 1e-12) { print "soak: FAILED: the total mass drifted by more than 1e-12"; exit 1 }
    if (edits < min_edits) { printf "soak: FAILED: %d edits, fewer than %d: give more frames\n", edits, min_edits; exit 1 }
    print "soak: passed"
  }' "$out/stats.csv"
