#!/usr/bin/env bash
# Builds hecal with warnings as errors and runs every correctness test (ctest label "unit"; the
# bad-input corpus, label "robustness", is part of it).
# Slow studies carry the label "slow" and run with: ctest --test-dir build -L slow
# Installs the Debian packages it needs first (scripts/install-deps.sh, apt-get only).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build=${HECAL_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHECAL_WERROR=ON >/dev/null
cmake --build "$build" -j2
ctest --test-dir "$build" -L unit --output-on-failure -j2
