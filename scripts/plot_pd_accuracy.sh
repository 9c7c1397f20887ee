#!/usr/bin/env bash
# Runs bench/pd_accuracy_bench (medians of 3) and plots each solver's error against its wall time
# per step, one panel per scene, into docs/pd_accuracy.png. The benchmark's CSV is kept next to the
# picture as docs/pd_accuracy.csv; `--plot-only` replots that CSV without running the benchmark.
# Needs a Release build (scripts/build.sh) and gnuplot (scripts/setup.sh installs it). The
# benchmark takes about 25 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${TISSU_BUILD_DIR:-build/release}
png=docs/pd_accuracy.png
csv=docs/pd_accuracy.csv
points=$(mktemp)
trap 'rm -f "$points"' EXIT

fail() { echo "plot_pd_accuracy: $*" >&2; exit 1; }
[[ $# -eq 0 || ( $# -eq 1 && $1 == --plot-only ) ]] || fail "usage: $0 [--plot-only]"
command -v gnuplot >/dev/null || fail "gnuplot not found; install it with scripts/setup.sh"
if [[ ${1:-} != --plot-only ]]; then
  bench=$build_dir/bench/pd_accuracy_bench
  [[ -x $bench ]] || fail "$bench not found; build it with scripts/build.sh"
  "$bench" --benchmark_repetitions=3 --benchmark_min_time=0.1 \
    --benchmark_report_aggregates_only=true --benchmark_out="$csv" --benchmark_out_format=csv
fi
[[ -f $csv ]] || fail "$csv not found; run without --plot-only first"

# "curve/<scene>/<solver>/<knob>/real_time_median" rows -> "<scene> <solver> <ms per step> <error>"
awk -F, '
  /^name,/ { for (c = 1; c <= NF; ++c) column[$c] = c; next }
  column["name"] && $1 ~ /^"curve\// && $1 ~ /_median"$/ {
    gsub(/"/, "", $1); split($1, part, "/")
    print part[2], part[3], $column["real_time"], $column["\"error\""]
  }' "$csv" >"$points"

gnuplot <<EOF
set terminal pngcairo size 1400,1000 font ",11"
set output "$png"
set multiplot layout 2,2 title "One backward Euler step from rest: error against the converged step vs wall time (2 threads)"
set logscale xy
set format y "10^{%L}"
set xlabel "wall time per step (ms)"
set ylabel "relative error |x - x*| / |x* - x_0|"
set yrange [1e-5:3]
set grid
set key bottom left font ",9" noenhanced
solvers = "pd_direct pd_jacobi pd_chebyshev pd_gauss_seidel pd_colored_gauss_seidel implicit_euler"
scenes = "sheet81 sheet81_h300 sheet128 adaptive"
titles = "'81 x 81, h = 1/30 s' '81 x 81, h = 1/300 s' '128 x 128, h = 1/30 s' 'adaptive and torn, 1729 particles, h = 1/30 s'"
do for [k = 1:4] {
  scene = word(scenes, k)
  set title word(titles, k) noenhanced
  plot for [s in solvers] "$points" using (strcol(1) eq scene && strcol(2) eq s ? \$3 : 1/0):4 \
         with linespoints pointsize 0.6 title s, \
       1e-3 with lines dashtype 2 linecolor "black" title "target 1e-3"
}
unset multiplot
EOF
echo "wrote $png and $csv"
