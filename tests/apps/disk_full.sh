#!/usr/bin/env bash
# Runs tissu with writes the disk refuses: each run must stop with exit status 1 and one line on
# stderr naming the file it could not write, and leave every file in its folder whole (no
# truncated mesh, image or stats row, no temporary). The refusal is a file size limit (ulimit -f,
# in KiB in bash; SIGXFSZ ignored, as tissu also does), which fails writes with EFBIG ("File too
# large") where a full disk fails them with ENOSPC: the same code path, without a small file
# system.  usage: disk_full.sh TISSU SCENARIO OUT_DIR
set -u
tissu=$1 scenario=$2 out=$3
. "$(dirname "$0")/complete_outputs.sh"
. "$(dirname "$0")/one_line_error.sh"
failures=0

# usage: expect_refused NAME LIMIT_KIB EXPECTED_TEXT [tissu run options...]
expect_refused() {
  local name=$1 limit_kib=$2 text=$3
  shift 3
  local dir=$out/$name stderr status
  rm -rf "$dir"
  mkdir -p "$dir"
  # the viewer (a 550 kB page) is off but in its own case
  stderr=$( (trap '' XFSZ; ulimit -f "$limit_kib"; exec "$tissu" run "$scenario" --out "$dir" --quiet \
    --set output.viewer=false "$@") 2>&1 >/dev/null)
  status=$?
  local ok=1
  echo -n "$name: "
  check_one_line_error "$status" "$stderr" 1 "$dir/$text" || ok=0
  check_complete_outputs "$dir" || { echo "FAIL $name: an output is not whole"; ok=0; }
  [ $ok -eq 1 ] || failures=$((failures + 1))
}

# the first frame's mesh (a 60 x 60 grid: about 400 kB) over a 64 KiB limit: nothing of it, and no
# stats row for its frame
expect_refused mesh 64 "frame_00000.obj: cannot write mesh: File too large" \
  --set "cloth.grid.resolution=[60,60]"
[ ! -e "$out/mesh/frame_00000.obj" ] || { echo "FAIL mesh: frame_00000.obj written"; failures=$((failures + 1)); }
# scenario.json (about 2.4 kB), the first file a run writes, over a 1 KiB limit
expect_refused scenario 1 "scenario.json: cannot write resolved scenario: File too large"
[ ! -e "$out/scenario/stats.csv" ] || { echo "FAIL scenario: stats.csv written"; failures=$((failures + 1)); }
# stats.csv outgrows 4 KiB after a few frames: it ends with its last whole row
expect_refused stats 4 "stats.csv: cannot write statistics: File too large" \
  --frames 200 --set output.meshes=false --set output.point_cache=false
# frames.pc2 outgrows 8 KiB: it ends with its last whole sample, which its header counts
expect_refused pc2 8 "frames.pc2: cannot write point cache: File too large" \
  --frames 200 --set output.meshes=false
# frames.h5 outgrows 64 KiB: every frame group it keeps is whole, one per stats row
expect_refused h5 64 "frames.h5: cannot write arrays: File too large" \
  --frames 200 --set output.meshes=false --set output.point_cache=false --set output.arrays=true
/usr/bin/python3 - "$out/h5" <<'PY' || failures=$((failures + 1))
import sys, h5py
folder = sys.argv[1]
rows = sum(1 for _ in open(f"{folder}/stats.csv")) - 1
with h5py.File(f"{folder}/frames.h5", "r") as f:
    frames = f["frames"]
    whole = all(len(frames[k]) == 6 for k in frames)
    if len(frames) != rows or not whole:
        sys.exit(f"FAIL h5: {len(frames)} frame groups (whole: {whole}) for {rows} stats rows")
PY
# the same for binary PLY
expect_refused ply 64 "frame_00000.ply: cannot write mesh: File too large" \
  --set output.mesh_format=ply --set "cloth.grid.resolution=[60,60]"
# the viewer's frames.js outgrows 640 KiB (its page, about 570 kB, fits): it ends with a whole line
expect_refused viewer 640 "viewer/frames.js: cannot write viewer frames: File too large" \
  --frames 1000 --set output.meshes=false --set output.viewer=true
[ "$(tail -c 1 "$out/viewer/viewer/frames.js" | od -An -c | tr -d ' ')" = '\n' ] &&
  [ "$(tail -n 1 "$out/viewer/viewer/frames.js" | tail -c 4)" = '});' ] ||
  { echo "FAIL viewer: frames.js does not end with a whole frame"; failures=$((failures + 1)); }
# the same for a glTF binary
expect_refused glb 64 "frame_00000.glb: cannot write mesh: File too large" \
  --set output.meshes=false --set output.glb=true --set "cloth.grid.resolution=[60,60]"
# a rendered image (about 11 kB) over an 8 KiB limit
expect_refused png 8 "frame_00000.png: cannot write PNG image: File too large" \
  --frames 1 --set output.meshes=false --set render.enabled=true --set render.video=false \
  --set render.width=640 --set render.height=480

[ $failures -eq 0 ] && echo ok
exit $((failures > 0))
