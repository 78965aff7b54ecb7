#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test.
#   scripts/test.sh              Release build in build/, every test
#   scripts/test.sh --sanitize   address+undefined sanitizer build in build-asan/, every test
#   scripts/test.sh --thread     ThreadSanitizer build in build-tsan/ (clang, with LLVM's OpenMP
#                                runtime and its Archer tool, so that OpenMP is checked too):
#                                the programs labelled `parallel` (ants and trials on threads)
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
cmake_args=(-DCMAKE_BUILD_TYPE=Release)
targets=()
ctest_args=()
case "${1:-}" in
  --sanitize)
    build_dir=build-asan
    # No Python module: an AddressSanitizer extension loads only into a Python with libasan
    # preloaded, and CPython's own allocations then report leaks (docs/python.md).
    cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DANTSLAM_SANITIZE=address,undefined
                -DANTSLAM_BUILD_BENCH=OFF -DANTSLAM_BUILD_PYTHON=OFF)
    ;;
  --thread)
    build_dir=build-tsan
    cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DANTSLAM_SANITIZE=thread
                -DANTSLAM_BUILD_BENCH=OFF -DANTSLAM_BUILD_PYTHON=OFF -DCMAKE_CXX_COMPILER=clang++)
    targets=(--target test_aco test_tsp test_slamgraph test_mapping test_contract)
    ctest_args=(-L parallel)
    # Archer (LLVM OpenMP's ThreadSanitizer tool) makes OpenMP's own synchronisation visible.
    # oneTBB's task bookkeeping is left out (cmake/tsan-ignorelist.txt); what remains of it are
    # its atomic counters against their plain initialisation, hence report_atomic_races=0.
    export OMP_TOOL_LIBRARIES=/usr/lib/llvm-14/lib/libarcher.so
    export TSAN_OPTIONS="halt_on_error=1 ignore_noninstrumented_modules=1 report_atomic_races=0"
    ;;
  "") ;;
  *) echo "usage: scripts/test.sh [--sanitize | --thread]" >&2; exit 2 ;;
esac

scripts/install-deps.sh
# A compiler cache, where one is installed, makes rebuilds of unchanged files free.
if command -v ccache >/dev/null 2>&1; then cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
jobs=$(nproc)
cmake -S . -B "$build_dir" "${cmake_args[@]}"
cmake --build "$build_dir" -j "$jobs" "${targets[@]}"
ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" "${ctest_args[@]}"
