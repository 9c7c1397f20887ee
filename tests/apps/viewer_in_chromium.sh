#!/usr/bin/env bash
# The browser viewer in a real browser (issue 20): Debian's headless Chromium loads the page of a
# torn run and of an adaptive one from file://, the slider set to a frame by the page's #frame=
# option, and a screenshot shows the cloth, its pins and the stats curves.
# usage: viewer_in_chromium.sh TISSU DATA_SCENARIOS_DIR OUT_DIR
set -u
tissu=$1 scenarios=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
chromium_in() {  # chromium_in PROFILE_NAME ARGS...: headless, software WebGL, its own profile
  local profile=$out/profile_$1
  shift
  timeout 120 chromium --headless --no-sandbox --disable-dev-shm-usage --disable-gpu \
    --use-angle=swiftshader \
    --enable-unsafe-swiftshader --user-data-dir="$profile" --window-size=1100,700 \
    --virtual-time-budget=5000 "$@" 2>/dev/null
}

for scene in tearing flag; do
  "$tissu" run "$scenarios/$scene.json" --out "$out/$scene" --quiet --frames 8 \
    --set render.enabled=false --set output.meshes=false || fail "$scene: the run failed"
  url=$("$tissu" view "$out/$scene" 2>/dev/null) || fail "$scene: tissu view failed"
  [ "${url#file://}" != "$url" ] || fail "$scene: tissu view printed $url"

  # the slider on frame 5: the page says so once it has shown it
  dom=$(chromium_in "${scene}_dom" --dump-dom "$url#frame=5")
  echo "$dom" | grep -q 'data-frame="5"' ||
    fail "$scene: the page did not show frame 5: $(echo "$dom" | grep -o '<span id="status"[^<]*')"

  # the last frame, coloured by strain: the cloth covers part of the view, the pins are drawn
  chromium_in "${scene}_shot" --screenshot="$out/$scene.png" "$url#frame=last&colouring=strain" \
    > /dev/null
  /usr/bin/python3 - "$out/$scene.png" "$scene" <<'PY' || exit 1
import sys
import matplotlib.image as image
import numpy as np
pixels = (image.imread(sys.argv[1])[..., :3] * 255).astype(int)
view, plots = pixels[:640, :740], pixels[:, 740:]
cloth = np.abs(view - [242, 242, 242]).sum(axis=2) > 40  # not the background
pins = (view[..., 0] > 150) & (view[..., 1] < 80) & (view[..., 2] < 80)
curves = (plots[..., 2] > 140) & (plots[..., 0] < 80)
print(f"{sys.argv[2]}: cloth {cloth.mean():.1%} of the view, {pins.sum()} pin pixels, "
      f"{curves.sum()} curve pixels")
if not (0.03 < cloth.mean() < 0.9 and pins.sum() > 20 and curves.sum() > 200):
    sys.exit(f"FAIL: {sys.argv[2]}: the screenshot does not show the cloth, pins and curves")
PY
done
echo ok
