# ANTSLAM_BUILD_FUZZ=ON -> the libFuzzer harnesses of tests/fuzz (docs/fuzzing.md). Needs clang:
# every library is compiled with address+undefined sanitizers and libFuzzer's coverage
# instrumentation (-fsanitize=fuzzer-no-link); each harness links libFuzzer's main
# (-fsanitize=fuzzer). Line tables are enough for symbolized reports and compile faster than
# -g. Build only the `fuzzers` target: it pulls in just the readers' libraries.
if(NOT ANTSLAM_BUILD_FUZZ)
  return()
endif()
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "antslam: ANTSLAM_BUILD_FUZZ needs clang (libFuzzer), not "
                      "${CMAKE_CXX_COMPILER_ID}: configure with -DCMAKE_CXX_COMPILER=clang++")
endif()
if(ANTSLAM_SANITIZE)
  message(FATAL_ERROR "antslam: ANTSLAM_BUILD_FUZZ brings its own sanitizers (address,undefined);"
                      " leave ANTSLAM_SANITIZE empty")
endif()
message(STATUS "antslam: building the libFuzzer harnesses (fuzzer-no-link,address,undefined)")
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer -gline-tables-only)
add_link_options(-fsanitize=address,undefined)
