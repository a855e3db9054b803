#!/usr/bin/env bash
# Builds hecal with warnings as errors and runs every correctness test (ctest label "unit"; the
# bad-input corpus and the fuzzers' kept inputs, label "robustness", are part of it), then the
# robustness tests once more in a second build under AddressSanitizer and UndefinedBehaviorSanitizer
# (docs/reliability.md), beside the unit suite. HECAL_SANITIZED_CHECKS=0 leaves the sanitized run
# out (a quicker local check; CI runs it).
#
# The builds (docs/build.md#build-time; scripts/configure.sh): clang (CXX=g++ chooses GCC), Ninja,
# lld, unity batches (HECAL_UNITY_BUILD), one test executable per module. The sanitized
# build is its own folder with only what the robustness tests need (the libraries, the CLI, the
# robustness test executables and the fuzz replays: target robustness_checks), at -O0 in one
# unity batch per target, the vision module at -O1 (HECAL_SANITIZE_OPTIMISED_MODULES).
#
# Slow studies carry the label "slow", are not built by default, and run with:
#   cmake --build build --target slow_checks && ctest --test-dir build -L slow
# Before a merge that touches a solver or the noise estimation also run the slow scale check
# (apps/hecal/scale_slow_test.cc; CPU limits at 10⁴ and 10⁵ stations, ~10 min for every method):
#   cmake --build build --target slow_checks && ctest --test-dir build -L slow -R cli_scale_slow_test
# The whole unit suite under the sanitizers:
#   scripts/configure.sh build-asan -DHECAL_SANITIZE=ON &&
#   cmake --build build-asan -j2 && ctest --test-dir build-asan -L unit
# Installs the Debian packages it needs first (scripts/install-deps.sh, apt-get only).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --browser --sanitizers
build=${HECAL_BUILD_DIR:-build}
sanitized=${HECAL_SANITIZED_BUILD_DIR:-build-sanitized}

scripts/configure.sh "$build" -DCMAKE_BUILD_TYPE=Release -DHECAL_WERROR=ON
cmake --build "$build" -j2

robustness=
if [ "${HECAL_SANITIZED_CHECKS:-1}" != 0 ]; then
  scripts/configure.sh "$sanitized" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O0 -DNDEBUG" \
    -DHECAL_SANITIZE=ON -DHECAL_WERROR=ON -DHECAL_BUILD_PYTHON=OFF -DHECAL_UNITY_BATCH=0 \
    -DHECAL_TEST_UNITY_BATCH=0
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
