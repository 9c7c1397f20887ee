#!/usr/bin/env bash
# README command 2: install, build in Release, run the whole test suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build/release --output-on-failure --parallel "$(nproc)"
