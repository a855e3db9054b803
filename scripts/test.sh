#!/usr/bin/env bash
# Builds hecal with warnings as errors and runs every correctness test (ctest label "unit"; the
# bad-input corpus and the fuzzers' kept inputs, label "robustness", are part of it).
# It also builds the "robustness" tests a second time under AddressSanitizer and
# UndefinedBehaviorSanitizer and runs them there (README "Reliability"). That build is unoptimised
# (-O0): with -O3 the sanitizers make the compiler about four times slower and would double CI's
# time; set HECAL_SANITIZED_CHECKS=0 to skip it while iterating. The whole unit suite under the
# sanitizers is: cmake -S . -B build-asan -DHECAL_SANITIZE=ON && cmake --build build-asan -j2 &&
# ctest --test-dir build-asan -L unit
# Slow studies carry the label "slow" and run with: ctest --test-dir build -L slow
# Before a merge that touches a solver or the noise estimation also run the slow scale check
# (apps/hecal/scale_slow_test.cc; CPU limits at 10⁴ and 10⁵ stations, ~10 min for every method):
# ctest --test-dir build -L slow -R cli_scale_slow_test (needs the hecal target built).
# Installs the Debian packages it needs first (scripts/install-deps.sh, apt-get only).
#
# Where the time goes (2 cores, no compiler cache; CPU = user + sys, which the machine's other
# load changes far less than wall time): about 190 test files of 5–10 s CPU each at -O3 (gtest's
# assertion code and the headers; gtest + gmock + Eigen + the standard headers alone 1.8 s), about
# 180 library and CLI files of 1.5–12.5 s (Ceres and Eigen templates), 0.05–0.4 s per link with
# GNU ld; the sanitized -O0 build of the libraries and the CLI about 8 minutes (6–12 s per file,
# mostly code generation, so a precompiled header saves only 0.3–0.8 s there); then the unit
# tests about 2 minutes on both cores and the sanitized corpus about 2 minutes on one core
# (cli_robustness_test alone). So:
#  - the test files are compiled at -Og (cmake/HecalHelpers.cmake: 13–32% less CPU each, about
#    5 CPU-minutes; the unit tests take about 15% more CPU);
#  - lld (a CLI test's link 0.40 s → 0.08 s CPU) and Ninja (no make and dependency-scanning
#    processes per target; not measured on its own, a no-op make of the tree costs 4.7 s CPU)
#    where the build folder is new;
#  - the sanitized corpus runs beside the unit suite instead of after it, on the core it leaves.
# Before: 27.7 min wall on a clean clone, load ≈ 2. After: 22.6 min wall on a clean clone with
# nothing else running (2,476 s user + 198 s system; the two builds about 18 min, then the unit
# suite and the sanitized corpus side by side 4.4 min — the corpus takes 259 s there, sharing the
# cores). Last measured: 22.8 and 23.5 min wall in two runs (2,496 + 202 s and 2,563 + 210 s
# user + system CPU) with 205 unit tests, the test phase 4.2 min (the corpus 250 s; the slowest
# unit tests 44–51 s each: kuka2 real data, image calibration, epipolar robot noise, the study).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build=${HECAL_BUILD_DIR:-build}
sanitized=${HECAL_SANITIZED_BUILD_DIR:-build-sanitized}

# configure <folder> <cmake options>...: Ninja for a new folder (an existing one keeps the
# generator it was made with), lld for the ~200 test executables.
configure() {
  local dir=$1
  shift
  local generator=()
  [ -f "$dir/CMakeCache.txt" ] || generator=(-G Ninja)
  cmake -S . -B "$dir" "${generator[@]}" -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld "$@" >/dev/null
}

configure "$build" -DCMAKE_BUILD_TYPE=Release -DHECAL_WERROR=ON
cmake --build "$build" -j2

robustness=
if [ "${HECAL_SANITIZED_CHECKS:-1}" != 0 ]; then
  configure "$sanitized" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O0 -DNDEBUG" \
    -DHECAL_SANITIZE=ON -DHECAL_WERROR=ON
  cmake --build "$sanitized" -j2 --target robustness_checks
  ctest --test-dir "$sanitized" -L robustness --output-on-failure >"$sanitized/robustness.log" 2>&1 &
  robustness=$!
fi

status=0
ctest --test-dir "$build" -L unit --output-on-failure -j2 || status=1
if [ -n "$robustness" ]; then
  echo "Under AddressSanitizer and UndefinedBehaviorSanitizer ($sanitized):"
  wait "$robustness" || status=1
  cat "$sanitized/robustness.log"
fi
exit "$status"
