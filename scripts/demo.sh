#!/usr/bin/env bash
# The main job on bundled real data: imports MoveIt Calibration's 50 real eye-to-hand pose pairs
# (data/moveit-calibration, BSD-3-Clause), calibrates with every method side by side and with the
# default maximum-likelihood method, and writes out/result.json (+ out/all-methods.json).
# Installs the Debian packages it needs and builds if needed.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build=${HECAL_BUILD_DIR:-build}
if [[ ! -x "$build/bin/hecal" ]] || [[ -n "$(find src apps include -newer "$build/bin/hecal" -print -quit)" ]]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j2 --target hecal
fi
hecal="$build/bin/hecal"
mkdir -p out
"$hecal" import --format moveit data/moveit-calibration/pose_samples.json \
  --robot out/moveit-robot.csv --camera out/moveit-camera.csv
"$hecal" calibrate --robot out/moveit-robot.csv --camera out/moveit-camera.csv \
  --setup eye-to-hand --method all --output out/all-methods.json > out/all-methods.txt
"$hecal" calibrate --robot out/moveit-robot.csv --camera out/moveit-camera.csv \
  --setup eye-to-hand --output out/result.json
echo "results: out/result.json (ml), out/all-methods.json and out/all-methods.txt (every method)"
