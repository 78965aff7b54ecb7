#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test.
#   scripts/test.sh              Release build in build/
#   scripts/test.sh --sanitize   address+undefined sanitizer build in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
cmake_args=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  build_dir=build-asan
  cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DANTSLAM_SANITIZE=address,undefined
              -DANTSLAM_BUILD_BENCH=OFF)
fi

scripts/install-deps.sh
# A compiler cache, where one is installed, makes rebuilds of unchanged files free.
if command -v ccache >/dev/null 2>&1; then cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
jobs=$(nproc)
cmake -S . -B "$build_dir" "${cmake_args[@]}"
cmake --build "$build_dir" -j "$jobs"
ctest --test-dir "$build_dir" --output-on-failure -j "$jobs"
