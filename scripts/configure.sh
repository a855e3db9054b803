#!/usr/bin/env bash
# scripts/configure.sh <build folder> [cmake options...]: configures hecal's build folder as the
# scripts build it (docs/build.md#build-time): a new folder with Ninja, every folder linked with
# lld; the compiler is CMake's choice (clang++ when installed and $CXX names none). An existing
# folder keeps the generator and compiler it was made with.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=$1
shift
new=()
[ -f "$dir/CMakeCache.txt" ] || new=(-G Ninja)
exec cmake -S . -B "$dir" "${new[@]}" -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld \
  -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=lld -DCMAKE_MODULE_LINKER_FLAGS=-fuse-ld=lld "$@" >/dev/null
