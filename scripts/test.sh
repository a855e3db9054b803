#!/usr/bin/env bash
# Builds hecal with warnings as errors and runs every correctness test (ctest label "unit"; the
# bad-input corpus and the fuzzers' kept inputs, label "robustness", are part of it).
# Then builds the "robustness" tests a second time under AddressSanitizer and
# UndefinedBehaviorSanitizer and runs them there (README "Reliability"). That build is unoptimised
# (-O0): with -O3 the sanitizers make the compiler about four times slower and would double CI's
# time; set HECAL_SANITIZED_CHECKS=0 to skip it while iterating. The whole unit suite under the
# sanitizers is: cmake -S . -B build-asan -DHECAL_SANITIZE=ON && cmake --build build-asan -j2 &&
# ctest --test-dir build-asan -L unit
# Slow studies carry the label "slow" and run with: ctest --test-dir build -L slow
# Installs the Debian packages it needs first (scripts/install-deps.sh, apt-get only).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build=${HECAL_BUILD_DIR:-build}
# Ninja where a build folder is new (an existing one keeps the generator it was made with), and
# lld for the ~200 test executables. Both from install-deps.sh.
configure() {
  local dir=$1
  shift
  local generator=()
  [ -f "$dir/CMakeCache.txt" ] || generator=(-G Ninja)
  cmake -S . -B "$dir" "${generator[@]}" -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld "$@" >/dev/null
}
configure "$build" -DCMAKE_BUILD_TYPE=Release -DHECAL_WERROR=ON
cmake --build "$build" -j2
ctest --test-dir "$build" -L unit --output-on-failure -j2

if [ "${HECAL_SANITIZED_CHECKS:-1}" != 0 ]; then
  sanitized=${HECAL_SANITIZED_BUILD_DIR:-build-sanitized}
  configure "$sanitized" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O0 -DNDEBUG" \
    -DHECAL_SANITIZE=ON -DHECAL_WERROR=ON
  cmake --build "$sanitized" -j2 --target robustness_checks
  ctest --test-dir "$sanitized" -L robustness --output-on-failure -j2
fi
