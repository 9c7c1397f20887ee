#!/usr/bin/env bash
# The animation caches in a real Blender (issue 20): Debian's Blender, headless, plays frames.pc2
# on the imported frame-0 OBJ and imports each .glb; scripts/check_in_blender.py compares both
# with the frame OBJs.  usage: caches_in_blender.sh TISSU SCENARIO OUT_DIR
set -u
tissu=$1 scenario=$2 out=$3
rm -rf "$out"
"$tissu" run "$scenario" --out "$out" --quiet --frames 20 --set output.mesh_every=5 \
  --set output.glb=true --set render.enabled=false --set output.viewer=false || exit 1
report=$(blender -b --factory-startup --python "$(dirname "$0")/../../scripts/check_in_blender.py" \
  -- "$out" 2>&1)
status=$?
echo "$report" | grep -E "^(PC2|frame_|ok|FAIL)"
[ $status -eq 0 ] && echo "$report" | grep -q "^ok: 5 frames"
