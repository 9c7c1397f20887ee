#!/usr/bin/env bash
# Runs bench/integrator_bench's hanging sheets (one thread) and plots each method's wall time per
# frame against the particle count, log-log, into docs/integrators.png; the benchmark's CSV is
# kept next to it as docs/integrators.csv, and `--plot-only` replots that CSV. Needs a Release
# build (scripts/build.sh) and gnuplot (scripts/setup.sh installs it). About 30 minutes, much of
# it the converged reference trajectories (TISSU_SHEET_REFERENCES=0 skips them).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${TISSU_BUILD_DIR:-build/release}
png=docs/integrators.png
csv=docs/integrators.csv
points=$(mktemp)
trap 'rm -f "$points"' EXIT

fail() { echo "plot_integrators: $*" >&2; exit 1; }
[[ $# -eq 0 || ( $# -eq 1 && $1 == --plot-only ) ]] || fail "usage: $0 [--plot-only]"
command -v gnuplot >/dev/null || fail "gnuplot not found; install it with scripts/setup.sh"
if [[ ${1:-} != --plot-only ]]; then
  bench=$build_dir/bench/integrator_bench
  [[ -x $bench ]] || fail "$bench not found; build it with scripts/build.sh"
  OMP_NUM_THREADS=1 "$bench" --benchmark_filter=HangingSheet \
    --benchmark_out="$csv" --benchmark_out_format=csv
fi
[[ -f $csv ]] || fail "$csv not found; run without --plot-only first"

# "BM_HangingSheet/<method>/<N>/..." rows -> "<method> <particles> <ms per frame> <unconverged>"
awk -F, '
  /^name,/ { for (c = 1; c <= NF; ++c) column[$c] = c; next }
  column["name"] && $1 ~ /^"BM_HangingSheet\// {
    gsub(/"/, "", $1); split($1, part, "/")
    print part[2], $column["\"particles\""], $column["\"ms_per_frame\""], $column["\"unconverged\""]
  }' "$csv" >"$points"

gnuplot <<PLOT
set terminal pngcairo size 1000,750 font ",11"
set output "$png"
set title "Stiff hanging sheet, one step of h = 1/30 s per frame, one thread: wall time per frame" noenhanced
set logscale xy
set xlabel "particles"
set ylabel "ms per frame"
set grid
set key top left noenhanced
methods = "implicit_euler pd_direct pd_colored_gauss_seidel newton quasi_newton"
plot for [m in methods] "$points" using (strcol(1) eq m ? \$2 : 1/0):3 with linespoints \
       pointsize 1 title m, \
     x * 19.0 / 6561 with lines dashtype 2 linecolor "black" title "linear in the particle count"
PLOT
echo "wrote $png and $csv"
