#!/usr/bin/env bash
# Installs tissu's build and test dependencies from Debian bookworm's packages (run as root).
# Does nothing when they are already installed. With --fuzz, also clang and its libFuzzer runtime
# (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(
  cmake ninja-build g++ pkg-config
  libcgal-dev libeigen3-dev libmetis-dev libassimp-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libosmesa6-dev libstb-dev ffmpeg
  gnuplot-nox # plots in docs/ (scripts/plot_pd_accuracy.sh)
  libhdf5-dev # frames.h5, the run's arrays (lib/frame_arrays.hpp)
  python3-h5py python3-numpy python3-matplotlib # the Python example that reads them (examples/)
  chromium # the viewer's test in a real browser (tests/apps/viewer_in_chromium.sh)
  blender # the point cache and glTF frames played in Blender (tests/apps/caches_in_blender.sh)
  libbullet-dev # the peer in bench/bullet_sheet_bench.cpp (issue 16)
  pybind11-dev python3-dev # the tissu Python module (python/), for Debian's /usr/bin/python3
  python3-distributed # sweeps on a Dask cluster (python/tissu/sweep.py)
)
if [[ "${1:-}" == "--fuzz" ]]; then
  packages+=(clang libclang-rt-14-dev)
fi
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
command -v npm > /dev/null || missing+=(nodejs npm) # the browser viewer's packages (viewer/)
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# three.js and esbuild for the viewer, at the versions viewer/package-lock.json pins
if [[ ! -x viewer/node_modules/.bin/esbuild ||
  viewer/package-lock.json -nt viewer/node_modules/.package-lock.json ]]; then
  npm ci --prefix viewer --no-audit --no-fund --loglevel=error
fi
