#!/usr/bin/env bash
# README command 2: install, build in Release, run the whole test suite through ctest, then fuzz
# each loader briefly (issue 18: 500 inputs per target from a fixed seed; about 2 minutes after
# the fuzz targets' clang build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build/release --output-on-failure --parallel "$(nproc)"
bash scripts/fuzz.sh --runs 500
