#!/usr/bin/env bash
# Configures and builds tissu in Release into build/release (or $TISSU_BUILD_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${TISSU_BUILD_DIR:-build/release}
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build "$build_dir" --parallel "$(nproc)"
