# Installs the project into a scratch prefix, then configures, builds and runs a downstream
# project that uses find_package(antslam). Invoked by CTest with -DBUILD_DIR, -DSOURCE_DIR (the
# consumer project), -DWORK_DIR, -DCONSUMER_COMPILER (the compiler that built the package),
# -DCONSUMER_FLAGS (compiler and linker flags, such as sanitizers), optionally -DCONFIGURE_ARGS
# (more cache entries, |-separated) and -DREADME (a Markdown file: its first ```cpp block is the
# consumer's main.cpp, so that the README's example cannot go stale).
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed: ${ARGN}\n${out}\n${err}")
  endif()
  message("${out}")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(snippet_args "")
if(README)
  file(READ ${README} text)
  string(REGEX MATCH "```cpp\n([^`]*)```" block "${text}")
  if(NOT block)
    message(FATAL_ERROR "${README}: no ```cpp block")
  endif()
  file(WRITE ${WORK_DIR}/snippet/main.cpp "${CMAKE_MATCH_1}")
  set(snippet_args -DSNIPPET=${WORK_DIR}/snippet/main.cpp)
endif()
string(REPLACE "|" ";" configure_args "${CONFIGURE_ARGS}")
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/install)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/install -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CONSUMER_COMPILER}
    "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}"
    ${snippet_args} ${configure_args})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
