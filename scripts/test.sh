#!/usr/bin/env bash
# Builds hecal with warnings as errors and runs every correctness test (ctest label "unit"; the
# bad-input corpus and the fuzzers' kept inputs, label "robustness", are part of it).
# With HECAL_SANITIZED_CHECKS=1 it also builds the "robustness" tests a second time under
# AddressSanitizer and UndefinedBehaviorSanitizer and runs them there, beside the unit suite
# (docs/reliability.md). That build is unoptimised (-O0: with -O3 the sanitizers make the
# compiler about four times slower). It is off by default because it no longer fits CI's time:
# on a clean clone on 2 cores (2026-11-29) the release build took 29.3 min wall (683 steps; the
# heaviest files 30–59 s each: estimation/noise_estimation.cc, pose/dlt_pose.cc,
# pose/linear_pose.cc, contour/shape_space.cc, estimation/epipolar_robot_noise.cc,
# estimation/model_check.cc) and the sanitized build was on course for about 25 min more, which
# with the unit suite (4.8 min for 215 tests) makes an hour against CI's 30-minute target; without
# it, about 34 min. Run it before a
# merge that touches input handling: HECAL_SANITIZED_CHECKS=1 scripts/test.sh. The whole unit
# suite under the sanitizers is: cmake -S . -B build-asan -DHECAL_SANITIZE=ON &&
# cmake --build build-asan -j2 && ctest --test-dir build-asan -L unit
# Slow studies carry the label "slow", are not built by default, and run with:
# cmake --build build --target slow_checks && ctest --test-dir build -L slow
# Before a merge that touches a solver or the noise estimation also run the slow scale check
# (apps/hecal/scale_slow_test.cc; CPU limits at 10⁴ and 10⁵ stations, ~10 min for every method):
# cmake --build build --target slow_checks && ctest --test-dir build -L slow -R cli_scale_slow_test.
# Installs the Debian packages it needs first (scripts/install-deps.sh, apt-get only).
#
# Build settings that save time (measured earlier): the test files are compiled at -Og
# (cmake/HecalHelpers.cmake: 13–32% less CPU each); lld (a CLI test's link 0.40 s → 0.08 s CPU)
# and Ninja where the build folder is new.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --browser
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
if [ "${HECAL_SANITIZED_CHECKS:-0}" != 0 ]; then
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
