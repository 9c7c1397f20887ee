#!/usr/bin/env bash
# Runs bench/adaptive_bench and plots, for each scene, the shape gap to the uniform fine mesh (for
# the flag, which no run follows instant by instant, the gap between the time-averaged shapes)
# against wall time per simulated second: the uniform meshes (coarse, one level finer, fine), the
# adaptive run, the two floors (the fine run with gravity nudged by 1e-11, and at half its time
# step) and issue 19's goal (1 % at 5 times the fine run's speed, 3 times on the curtain). Writes
# docs/adaptive.png and keeps the benchmark's CSV next to it as docs/adaptive.csv; `--plot-only`
# replots that CSV without running the benchmark. Extra arguments go to the benchmark. Needs a
# Release build (scripts/build.sh) and gnuplot (scripts/setup.sh installs it). Three repetitions,
# the medians plotted: about 13 minutes on one thread (OMP_NUM_THREADS=1, as docs/benchmarks.md
# quotes it).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${TISSU_BUILD_DIR:-build/release}
png=docs/adaptive.png
csv=docs/adaptive.csv
points=$(mktemp)
trap 'rm -f "$points"' EXIT

fail() { echo "plot_adaptive: $*" >&2; exit 1; }
command -v gnuplot >/dev/null || fail "gnuplot not found; install it with scripts/setup.sh"
if [[ ${1:-} == --plot-only ]]; then
  [[ $# -eq 1 ]] || fail "usage: $0 [--plot-only | benchmark arguments...]"
else
  bench=$build_dir/bench/adaptive_bench
  [[ -x $bench ]] || fail "$bench not found; build it with scripts/build.sh"
  "$bench" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_out="$csv" --benchmark_out_format=csv "$@"
fi
[[ -f $csv ]] || fail "$csv not found; run without --plot-only first"

# "BM_Adaptivity/<scene>/<run>/..." rows (the medians when repeated) -> "<scene> <run> <wall s per
# simulated s> <mean gap %> <time-averaged shape gap %>"
awk -F, '
  { gsub(/"/, "") }
  /^name,/ { for (c = 1; c <= NF; ++c) column[$c] = c; next }
  column["name"] && $1 ~ /^BM_Adaptivity\// && $1 ~ /(manual_time|_median)$/ {
    split($1, part, "/")
    print part[2], part[3], $column["wall_s_per_sim_s"], $column["mean_gap_pct"],
      $column["mean_shape_gap_pct"]
  }' "$csv" >"$points"
for scene in curtain drape flag; do
  for run in uniform_fine fine_nudged fine_half_step; do
    grep -q "^$scene $run " "$points" || fail "$csv has no $run run of the $scene"
  done
done

gnuplot <<EOF
set terminal pngcairo size 1500,600 font ",11"
set output "$png"
set multiplot layout 1,3 title "Adaptive against uniform meshes: shape gap to the uniform fine mesh against wall time; the goal is the green box (docs/benchmarks.md)"
set logscale x
set xlabel "wall time per simulated second (s)"
set yrange [0:*]
set grid
set key below horizontal font ",9" noenhanced
scenes = "curtain drape flag"
goals = "3 5 5"
# the gap each scene is judged by: column 4, the mean gap instant by instant; the flag, which no
# run follows instant by instant, column 5, the gap between the time-averaged shapes
gap_columns = "4 4 5"
# column 3 (wall time), 4 or 5 (gaps) of a scene's run
run_value(scene, run, column) = real(system(sprintf( \
  "awk '\$1 == \"%s\" && \$2 == \"%s\" { print \$%d }' $points", scene, run, column)))
do for [k = 1:3] {
  scene = word(scenes, k)
  goal = word(goals, k) + 0
  gap = word(gap_columns, k) + 0
  fine = run_value(scene, "uniform_fine", 3)
  floor = run_value(scene, "fine_nudged", gap)
  half_step = run_value(scene, "fine_half_step", gap)
  set title sprintf("%s: goal %g x faster than uniform fine at a gap <= 1 %%", scene, goal)
  set ylabel (gap == 4 ? "mean shape gap (% of the rest diagonal)" \
                       : "gap between time-averaged shapes (% of the rest diagonal)")
  set object 1 rectangle from graph 0, graph 0 to first fine / goal, first 1 \
    fillcolor rgb "#d8f0d8" fillstyle solid noborder behind
  plot sprintf("< awk '\$1 == \"%s\" && \$2 ~ /^uniform_/' $points | sort -g -k3", scene) \
         using 3:gap with linespoints pointtype 7 linecolor "gray30" title "uniform (coarse, mid, fine)", \
       "$points" using (strcol(1) eq scene && strcol(2) eq "adaptive" ? \$3 : 1/0):gap \
         with points pointtype 9 pointsize 2.5 linecolor "red" title "adaptive", \
       floor with lines dashtype 3 linewidth 2 linecolor "blue" title "noise floor (fine, g nudged 1e-11)", \
       half_step with lines dashtype 4 linewidth 2 linecolor "dark-orange" title "time-step floor (fine at h/2)"
  unset object 1
}
unset multiplot
EOF
echo "wrote $png and $csv"
