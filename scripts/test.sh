#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test.
#   scripts/test.sh              Release build in build/, every test
#   scripts/test.sh --sanitize   address+undefined sanitizer build in build-asan/, every test
#   scripts/test.sh --thread     ThreadSanitizer build in build-tsan/ (clang, with LLVM's OpenMP
#                                runtime and its Archer tool, so that OpenMP is checked too):
#                                the programs labelled `parallel` (ants and trials on threads)
#   scripts/test.sh --fuzz       libFuzzer build in build-fuzz/ (clang, address+undefined): each
#                                reader's harness for a fixed number of runs from its seed
#                                corpus (docs/fuzzing.md); fails on any finding
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
cmake_args=(-DCMAKE_BUILD_TYPE=Release)
# Sanitizer and fuzzing trees: clang, optimised, with line tables instead of full debug
# information (cmake/AntslamSanitizers.cmake).
sanitizer_build=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
                 "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -DNDEBUG")
targets=()
ctest_args=()
case "${1:-}" in
  --sanitize)
    build_dir=build-asan
    # No Python module: an AddressSanitizer extension loads only into a Python with libasan
    # preloaded, and CPython's own allocations then report leaks (docs/python.md).
    cmake_args=("${sanitizer_build[@]}" -DANTSLAM_SANITIZE=address,undefined
                -DANTSLAM_BUILD_BENCH=OFF -DANTSLAM_BUILD_PYTHON=OFF)
    ;;
  --thread)
    build_dir=build-tsan
    cmake_args=("${sanitizer_build[@]}" -DANTSLAM_SANITIZE=thread
                -DANTSLAM_BUILD_BENCH=OFF -DANTSLAM_BUILD_PYTHON=OFF)
    targets=(--target test_aco test_tsp test_qap test_slamgraph test_mapping test_contract)
    ctest_args=(-L parallel)
    # Archer (LLVM OpenMP's ThreadSanitizer tool) makes OpenMP's own synchronisation visible.
    # oneTBB's task bookkeeping is left out (cmake/tsan-ignorelist.txt); what remains of it are
    # its atomic counters against their plain initialisation, hence report_atomic_races=0.
    export OMP_TOOL_LIBRARIES=/usr/lib/llvm-14/lib/libarcher.so
    export TSAN_OPTIONS="halt_on_error=1 ignore_noninstrumented_modules=1 report_atomic_races=0"
    ;;
  --fuzz)
    build_dir=build-fuzz
    cmake_args=("${sanitizer_build[@]}" -DANTSLAM_BUILD_FUZZ=ON -DANTSLAM_BUILD_TESTS=OFF
                -DANTSLAM_BUILD_BENCH=OFF -DANTSLAM_BUILD_APP=OFF -DANTSLAM_BUILD_PYTHON=OFF)
    targets=(--target fuzzers)
    ;;
  "") ;;
  *) echo "usage: scripts/test.sh [--sanitize | --thread | --fuzz]" >&2; exit 2 ;;
esac

scripts/install-deps.sh
# A compiler cache, where one is installed, makes rebuilds of unchanged files free.
if command -v ccache >/dev/null 2>&1; then cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
jobs=$(nproc)
cmake -S . -B "$build_dir" "${cmake_args[@]}"
cmake --build "$build_dir" -j "$jobs" "${targets[@]}"
if [ "$build_dir" != build-fuzz ]; then
  ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" "${ctest_args[@]}"
  exit 0
fi

# Each harness from a fresh corpus (its seeds only) with a fixed seed, so a run is repeatable;
# the run counts give 10-20 s a harness on a loaded 2-core machine. Findings are kept in
# build-fuzz/findings/ (docs/fuzzing.md says how to replay one).
fuzz_runs=(tsplib:100000 qaplib:100000 tour:400000 carmen:120000 g2o:200000 fragment_set:30000 tum:400000
           relations:400000)
fuzz_dir="$build_dir/tests/fuzz"
failed=()
rm -rf "$build_dir/findings" && mkdir -p "$build_dir/findings"
for entry in "${fuzz_runs[@]}"; do
  name=${entry%%:*}
  corpus="$build_dir/corpus/$name"
  rm -rf "$corpus" && mkdir -p "$corpus"
  log="$build_dir/findings/fuzz_$name.log"
  if "$fuzz_dir/fuzz_$name" -runs="${entry#*:}" -seed=1 -timeout=10 -rss_limit_mb=2048 \
       -dict="tests/fuzz/fuzz_$name.dict" -artifact_prefix="$build_dir/findings/fuzz_$name-" \
       "$corpus" "$fuzz_dir/seeds/fuzz_$name" >"$log" 2>&1; then
    echo "fuzz_$name: $(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -n 1)"
  else
    failed+=("fuzz_$name")
    echo "fuzz_$name: FAILED, see $log" >&2
    grep -E '^(finding|==[0-9]+==ERROR|SUMMARY)' "$log" >&2 || true
  fi
done
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
