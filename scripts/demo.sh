#!/usr/bin/env bash
# The main job on bundled real data: imports MoveIt Calibration's 50 real eye-to-hand pose pairs
# (data/moveit-calibration, BSD-3-Clause), calibrates with every method side by side and with the
# default maximum-likelihood method, and writes out/result.json (+ out/all-methods.json); then
# calibrates from the 28 real chessboard images of data/rwhe-kuka2 and its KUKA poses in one step
# (detection, intrinsics, PnP, ml, joint reprojection refinement) → out/kuka2-images.json.
# Each calibration writes its interactive HTML page too (docs/report.md): out/report.html (MoveIt,
# every method side by side, ml first) and out/kuka2-report.html; both open offline.
# Then the same calibration from Python: installs the `hecal` module (cmake --install, component
# python, into the system's Python path) and runs examples/python/drop_in_cv2.py, so that
# `python3 -c "import hecal"` works afterwards (docs/python.md).
# Installs the Debian packages it needs and builds if needed.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build=${HECAL_BUILD_DIR:-build}
module=$(ls "$build"/python/hecal/_hecal*.so 2>/dev/null | head -1 || true)
if [[ ! -x "$build/bin/hecal" || -z "$module" ]] ||
   [[ -n "$(find src apps include python web -newer "$build/bin/hecal" -print -quit)" ]]; then
  scripts/configure.sh "$build" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$build" -j2 --target hecal hecal_python
fi
hecal="$build/bin/hecal"
mkdir -p out
"$hecal" import --format moveit data/moveit-calibration/pose_samples.json \
  --robot out/moveit-robot.csv --camera out/moveit-camera.csv
"$hecal" calibrate --robot out/moveit-robot.csv --camera out/moveit-camera.csv \
  --setup eye-to-hand --method all --output out/all-methods.json \
  --report out/report.html > out/all-methods.txt
"$hecal" calibrate --robot out/moveit-robot.csv --camera out/moveit-camera.csv \
  --setup eye-to-hand --output out/result.json
"$hecal" calibrate --images data/rwhe-kuka2/images --target data/rwhe-kuka2/target.yaml \
  --robot data/rwhe-kuka2/RobotPosesVec.txt --setup eye-in-hand \
  --output out/kuka2-images.json --report out/kuka2-report.html > out/kuka2-images.txt
sudo=
[[ $(id -u) -eq 0 ]] || sudo=sudo  # the system's Python path is root's
$sudo cmake --install "$build" --component python >/dev/null
python3 examples/python/drop_in_cv2.py > out/python-drop-in.txt
echo "results: out/result.json (ml), out/all-methods.json and out/all-methods.txt (every method)"
echo "         out/kuka2-images.json and out/kuka2-images.txt (from the rwhe-kuka2 images)"
echo "         out/python-drop-in.txt (import hecal: the cv2.calibrateHandEye drop-in)"
echo "pages:   out/report.html (MoveIt, open it in a browser), out/kuka2-report.html"
