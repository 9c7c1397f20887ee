#!/usr/bin/env bash
# Runs bench/integrator_bench's hanging sheets (one thread) for the methods in `methods` below,
# and the scenario default on two threads as tissu runs it on this 2-core machine, and plots each
# one's wall time per frame against the particle count, log-log, into
# docs/integrators.png, with Bullet's soft body on the same sheet (bench/bullet_sheet_bench) and
# dotted lines for the methods that missed their tolerance; the benchmarks' CSV is kept next to it as docs/integrators.csv, and `--plot-only`
# replots that CSV. Needs a Release build (scripts/build.sh) and gnuplot (scripts/setup.sh
# installs it). About half an hour, most of it the converged reference trajectories and the 512 x
# 512 sheets; TISSU_SHEET_REFERENCES=0 skips the references; TISSU_BUILD_DIR picks the build.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${TISSU_BUILD_DIR:-build/release}
png=docs/integrators.png
csv=docs/integrators.csv
points=$(mktemp)
peer_csv=$(mktemp)
two_threads_csv=$(mktemp)
trap 'rm -f "$points" "$peer_csv" "$two_threads_csv"' EXIT

fail() { echo "plot_integrators: $*" >&2; exit 1; }
[[ $# -eq 0 || ( $# -eq 1 && $1 == --plot-only ) ]] || fail "usage: $0 [--plot-only]"
command -v gnuplot >/dev/null || fail "gnuplot not found; install it with scripts/setup.sh"
# the methods benchmarked on one thread (integrator_bench's other variants are left out), and
# those plotted: the same, and the default on two threads
default_method=quasi_newton_multigrid_gradient  # simulation.integrator's default, as benchmarked
methods=(implicit_euler pd_direct pd_colored_gauss_seidel newton quasi_newton "$default_method")
plotted=("${methods[@]}" "${default_method}_2_threads")
if [[ ${1:-} != --plot-only ]]; then
  bench=$build_dir/bench/integrator_bench
  peer=$build_dir/bench/bullet_sheet_bench
  [[ -x $bench && -x $peer ]] || fail "$bench or $peer not found; build them with scripts/build.sh"
  OMP_NUM_THREADS=1 "$bench" --benchmark_filter="HangingSheet/($(IFS='|'; echo "${methods[*]}"))/" \
    --benchmark_out="$csv" --benchmark_out_format=csv
  # the default on two threads with the tissu programs' spin count (apps/openmp_waiting.hpp),
  # timings only, renamed so that it plots as a method of its own
  OMP_NUM_THREADS=2 GOMP_SPINCOUNT=10000 TISSU_SHEET_REFERENCES=0 "$bench" \
    --benchmark_filter="HangingSheet/$default_method/" \
    --benchmark_out="$two_threads_csv" --benchmark_out_format=csv
  grep -E '^(name,|"BM_HangingSheet/)' "$two_threads_csv" |
    sed "s#^\"BM_HangingSheet/$default_method/#\"BM_HangingSheet/${default_method}_2_threads/#" \
      >>"$csv" || fail "no rows in $two_threads_csv"
  "$peer" --benchmark_out="$peer_csv" --benchmark_out_format=csv
  # with its own header: its counters are not the same columns
  grep -E '^(name,|"BulletSheet/)' "$peer_csv" >>"$csv" || fail "no Bullet rows in $peer_csv"
fi
[[ -f $csv ]] || fail "$csv not found; run without --plot-only first"

# "BM_HangingSheet/<method>/<N>/..." rows -> "<method> <particles> <ms per frame> <unconverged>",
# "BulletSheet/<N>/..." rows -> "bullet <particles> <ms per frame> 0"; each header line names
# the columns of the rows after it
awk -F, '
  /^name,/ { delete column; for (c = 1; c <= NF; ++c) column[$c] = c; next }
  column["name"] && $1 ~ /^"(BM_HangingSheet|BulletSheet)\// {
    gsub(/"/, "", $1); split($1, part, "/")
    method = $1 ~ /^BulletSheet/ ? "bullet" : part[2]
    unconverged = method == "bullet" ? 0 : $column["\"unconverged\""]
    print method, $column["\"particles\""], $column["\"ms_per_frame\""], unconverged
  }' "$csv" >"$points"

# one line per method; a method that missed its tolerance on some step is dotted and says so
plot="plot"
for method in "${plotted[@]}"; do
  unconverged=$(awk -v m="$method" '$1 == m { u += $4 } END { print u + 0 }' "$points")
  title=$method
  dash=1
  if [[ $unconverged != 0 ]]; then title="$method ($unconverged unconverged steps)"; dash=3; fi
  plot+=" \"$points\" using (strcol(1) eq \"$method\" ? \$2 : 1/0):3 with linespoints"
  plot+=" dashtype $dash pointsize 1 title \"$title\","
done
gnuplot <<PLOT
set terminal pngcairo size 1000,750 font ",11"
set output "$png"
set title "Stiff hanging sheet, one step of h = 1/30 s per frame, one thread (the default also on two): wall time per frame" noenhanced
set logscale xy
set xlabel "particles"
set ylabel "ms per frame"
set grid
set key bottom right noenhanced
$plot \
  "$points" using (strcol(1) eq "bullet" ? \$2 : 1/0):3 with linespoints linecolor "black" \
    pointtype 7 pointsize 1 title "Bullet soft body, 10 iterations (over-stretches, docs/benchmarks.md)", \
  x * 19.0 / 6561 with lines dashtype 2 linecolor "black" title "linear in the particle count"
PLOT
echo "wrote $png and $csv"
