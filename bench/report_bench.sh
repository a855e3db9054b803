#!/usr/bin/env bash
# `hecal report` timing at 50 and 10⁴ stations and from 28 images with thumbnails
# (docs/report.md#size-and-speed). The 50-station
# result is MoveIt Calibration's real one; the 10⁴-station result is that file with its stations
# repeated (ids made unique, every 37th flagged) and a robot table of 10⁴ rows to match, so the
# page carries 10⁴ residuals and 10⁴ robot poses (plotted: 2000 and 200, said on the page).
# The images case is rwhe-kuka2's 28 chessboard images (1920 × 1200 PNG): its result from
# `calibrate --images` (every corner and residual in the file) reported with `--images`, so the
# page embeds 28 thumbnails, decoded from the PNGs (one at a time, vision/image_read.h) and
# downscaled and encoded on every core.
# Prints the median wall time of 5 runs for each. Usage: bench/report_bench.sh [BUILD_DIR [KEEP]]
# (KEEP: a folder that receives the pages, e.g. to load them with web/report_pages.mjs).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
hecal="$(cd "${1:-$root/build}" && pwd)/bin/hecal"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root"
"$hecal" import --format moveit data/moveit-calibration/pose_samples.json \
  --robot "$work/robot50.csv" --camera "$work/camera50.csv" >/dev/null
"$hecal" calibrate --robot "$work/robot50.csv" --camera "$work/camera50.csv" \
  --setup eye-to-hand --output "$work/r50.json" >/dev/null
"$hecal" calibrate --images data/rwhe-kuka2/images --target data/rwhe-kuka2/target.yaml \
  --robot data/rwhe-kuka2/RobotPosesVec.txt --setup eye-in-hand --output "$work/kuka2.json" \
  >/dev/null
python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
r = json.load(open(f"{work}/r50.json"))
n = 10_000
base = r["residuals"]["per_station"]
r["residuals"]["per_station"] = [dict(base[k % len(base)], id=str(k), outlier=(k % 37 == 0))
                                 for k in range(n)]
r["stations"]["used"] = [str(k) for k in range(n)]
json.dump(r, open(f"{work}/r10k.json", "w"))
rows = [l for l in open(f"{work}/robot50.csv") if not l.startswith("#")]
with open(f"{work}/robot10k.csv", "w") as out:
    out.write(rows[0])
    for k in range(n):
        out.write(str(k) + rows[1 + k % (len(rows) - 1)][rows[1 + k % (len(rows) - 1)].index(","):])
PY
median() {
  local times=()
  for _ in 1 2 3 4 5; do
    local start end
    start=$(date +%s.%N)
    "$hecal" report "$@" >/dev/null
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc)")
  done
  printf '%s\n' "${times[@]}" | sort -n | sed -n 3p
}
echo "stations  seconds (median of 5)  page bytes"
t50=$(median "$work/r50.json" --robot "$work/robot50.csv" --output "$work/r50.html")
echo "50        $t50  $(stat -c %s "$work/r50.html")"
t10k=$(median "$work/r10k.json" --robot "$work/robot10k.csv" --output "$work/r10k.html")
echo "10000     $t10k  $(stat -c %s "$work/r10k.html")"
tk=$(median "$work/kuka2.json" --images data/rwhe-kuka2/images --output "$work/kuka2.html")
echo "28 images $tk  $(stat -c %s "$work/kuka2.html") (result file $(stat -c %s "$work/kuka2.json"))"
if [[ -n "${2:-}" ]]; then
  cp "$work/r50.html" "$work/r10k.html" "$work/kuka2.html" "$2"/
fi
