#!/usr/bin/env bash
# README command 1: install, build in Release, run the curtain demo into out/curtain/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
./build/release/apps/curtain --out out/curtain "$@"
