#!/usr/bin/env bash
# The HTML report in a real browser (docs/report.md#tests; ctest `report_browser`, labels unit and
# browser). Writes each kind of page from bundled data with the built CLI:
#   moveit-ml.html   MoveIt Calibration's 50 eye-to-hand stations, `hecal report --robot`
#   moveit-all.html  the same, `calibrate --method all --report`
#   kuka2.html       rwhe-kuka2's 28 chessboard images, `calibrate --images --report` (with the
#                    thumbnails, the residual field and the corner coverage)
#   kuka2-detect.html the same images, `hecal detect --report` (the detect page)
#   simulate.html    a small thesis study (2 settings × 20 trials × 3 methods, with covariance),
#                    `simulate --report`
#   contour-study.html  the contour study along rx (5 steps × 500 samples), `contour study --report`
#   global.html      the target-free result of tests/data/report/global-*.csv (a synthetic
#                    scene; 2000 cubes: not certified, fast), `calibrate --method global
#                    --output`, then `hecal report`
# checks that a foreign JSON exits 2 naming the field and writes nothing, then loads every page in
# headless Chromium with the network off (web/report_pages.mjs: no console error, no request but
# the file, every figure drawn, a click on an image entry shows that image's thumbnail) and keeps
# a screenshot beside each page.
# Usage: browser_test.sh HECAL OUT_DIR   (needs scripts/install-deps.sh --browser: chromium, and
# web/node_modules from npm ci)
set -euo pipefail
hecal=$1
out=$2
root="$(cd "$(dirname "$0")/../.." && pwd)"
chromium=${HECAL_CHROMIUM:-/usr/bin/chromium}
if [[ ! -x "$chromium" ]]; then
  echo "browser_test: $chromium is missing (fix: scripts/install-deps.sh --browser)" >&2
  exit 1
fi
mkdir -p "$out"
cd "$root"
"$hecal" import --format moveit data/moveit-calibration/pose_samples.json \
  --robot "$out/moveit-robot.csv" --camera "$out/moveit-camera.csv" >/dev/null
"$hecal" calibrate --robot "$out/moveit-robot.csv" --camera "$out/moveit-camera.csv" \
  --setup eye-to-hand --output "$out/moveit-ml.json" >/dev/null
"$hecal" report "$out/moveit-ml.json" --robot "$out/moveit-robot.csv" \
  --output "$out/moveit-ml.html" >/dev/null
"$hecal" calibrate --robot "$out/moveit-robot.csv" --camera "$out/moveit-camera.csv" \
  --setup eye-to-hand --method all --report "$out/moveit-all.html" >/dev/null
"$hecal" calibrate --images data/rwhe-kuka2/images --target data/rwhe-kuka2/target.yaml \
  --robot data/rwhe-kuka2/RobotPosesVec.txt --setup eye-in-hand --threads 2 \
  --report "$out/kuka2.html" >/dev/null
"$hecal" detect --images data/rwhe-kuka2/images --target data/rwhe-kuka2/target.yaml \
  --threads 2 --output "$out/kuka2-detect.csv" --report "$out/kuka2-detect.html" >/dev/null
"$hecal" simulate --stations 3,6 --trials 20 --sigma 0.3 --method ml,tsai-lenz,park-martin \
  --covariance linear --threads 2 --report "$out/simulate.html" >/dev/null
"$hecal" contour study --motion rx --from 0 --to 20 --steps 5 --samples 500 --threads 2 \
  --report "$out/contour-study.html" >/dev/null
"$hecal" calibrate --method global --setup eye-in-hand --robot tests/data/report/global-robot.csv \
  --correspondences tests/data/report/global-bearings.csv --pixel-sigma 0.000625 --reach 1 \
  --max-cubes 2000 --threads 2 --output "$out/global.json" >/dev/null 2>&1
"$hecal" report "$out/global.json" --output "$out/global.html" >/dev/null

# A foreign JSON: exit 2, one line naming the field, no page.
echo '{"hecal_version": "0.1.0", "setup": "eye-to-hand", "method": "ml", "units": {"length": "m"}, "X": {"frame": "T_base_camera", "matrix": [[1, 0, 0]]}}' \
  >"$out/foreign.json"
rm -f "$out/foreign.html"
set +e
message=$("$hecal" report "$out/foreign.json" --output "$out/foreign.html" 2>&1)
status=$?
set -e
if [[ $status -ne 2 || "$message" != *"field X.matrix: expected a 4x4 matrix"* || -e "$out/foreign.html" ]]; then
  echo "browser_test: foreign JSON: exit $status, '$message'" >&2
  exit 1
fi

cd "$root/web"
node report_pages.mjs "$chromium" "$out/moveit-ml.html" "$out/moveit-all.html" "$out/kuka2.html" \
  "$out/kuka2-detect.html" "$out/simulate.html" "$out/contour-study.html" "$out/global.html"
