#!/usr/bin/env bash
# The contour study's figures of the docs (docs/contour.md#figures) from the same path as every
# hecal figure: runs each `hecal contour study` command of docs/contour.md's command block with
# the built CLI (writing docs/contour/*.csv and the pages out/contour/*.html, docs/report.md),
# then screenshots the pages' figures in headless Chromium with the network off
# (web/figure_shots.mjs): Fig. 3 of each motion into docs/contour/{tx,ty,tz,rx,ry,rz}.png and
# Fig. 4 of rx.html (no motion) and rx10.html (10° about x) into docs/contour/cov-rx0.png and
# cov-rx10.png. No figure is drawn by hand.
# Usage: scripts/docs-figures.sh [BUILD_DIR]   (default build; needs chromium and web/node_modules:
# scripts/install-deps.sh --browser)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
hecal="$(pwd)/$build/bin/hecal"
chromium=${HECAL_CHROMIUM:-/usr/bin/chromium}
for needed in "$hecal" "$chromium"; do
  if [[ ! -x "$needed" ]]; then
    echo "docs-figures: $needed is missing (fix: build hecal; scripts/install-deps.sh --browser)" >&2
    exit 1
  fi
done
mkdir -p out/contour
# The command block: every line that starts with `hecal contour study`.
grep '^hecal contour study ' docs/contour.md | while read -r -a words; do
  "$hecal" "${words[@]:1}" >/dev/null
  echo "ran: ${words[*]}"
done
shots=()
for motion in tx ty tz rx ry rz; do
  shots+=("$(pwd)/out/contour/$motion.html" '#fig3' "$(pwd)/docs/contour/$motion.png")
done
shots+=("$(pwd)/out/contour/rx.html" '#fig4' "$(pwd)/docs/contour/cov-rx0.png")
shots+=("$(pwd)/out/contour/rx10.html" '#fig4' "$(pwd)/docs/contour/cov-rx10.png")
cd web
node figure_shots.mjs "$chromium" "${shots[@]}"
