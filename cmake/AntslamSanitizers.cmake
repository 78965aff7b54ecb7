# ANTSLAM_SANITIZE=address,undefined  -> ASan + UBSan (CI runs the suite once this way)
# ANTSLAM_SANITIZE=thread             -> TSan (CI runs the parallel programs this way). Build
#                                        with clang: libgomp is not TSan-instrumented, LLVM's
#                                        OpenMP runtime reports to TSan through its Archer tool
#                                        (OMP_TOOL_LIBRARIES, see scripts/test.sh --thread), and
#                                        oneTBB's headers stay uninstrumented
#                                        (tsan-ignorelist.txt).
# Line tables are enough for symbolized reports. Clang with line tables compiles the engine's
# heaviest translation units (a colony instantiated for every backend) at -O2 four times faster
# than GCC with -g, so scripts/test.sh builds both sanitizer trees with clang.
if(ANTSLAM_SANITIZE)
  message(STATUS "antslam: building with -fsanitize=${ANTSLAM_SANITIZE}")
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    add_compile_options(-fsanitize=${ANTSLAM_SANITIZE} -fno-omit-frame-pointer -gline-tables-only)
  else()
    add_compile_options(-fsanitize=${ANTSLAM_SANITIZE} -fno-omit-frame-pointer -g1)
  endif()
  add_link_options(-fsanitize=${ANTSLAM_SANITIZE})
  if(ANTSLAM_SANITIZE MATCHES "undefined")
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
  if(ANTSLAM_SANITIZE MATCHES "thread" AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    add_compile_options(-fsanitize-ignorelist=${CMAKE_CURRENT_LIST_DIR}/tsan-ignorelist.txt)
  elseif(ANTSLAM_SANITIZE MATCHES "thread")
    message(WARNING "antslam: ThreadSanitizer with ${CMAKE_CXX_COMPILER_ID}: libgomp is not "
                    "instrumented, so OpenMP runs report false races; use clang++")
  endif()
endif()
