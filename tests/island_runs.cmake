# Runs `antslam ARGS --colonies K OUTPUT_OPTION <file>` once per RUNS entry "R:K" (R ranks:
# R = 1 without a launcher, else MPIEXEC -n R, oversubscribed beyond the cores) and requires
# every run's file <file>COMPARE_SUFFIX to be byte-identical to that of the single-process run
# with the same K, and every run to print SUMMARY_REGEX once (rank 0 alone prints).
#   ANTSLAM, MPIEXEC, OUT (a scratch directory), ARGS and RUNS ('|'-separated), OUTPUT_OPTION
#   (--tour-out, -o), COMPARE_SUFFIX (empty, .trials.csv), SUMMARY_REGEX
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" runs "${RUNS}")
file(MAKE_DIRECTORY "${OUT}")
foreach(run IN LISTS runs)
  string(REPLACE ":" ";" parts "${run}")
  list(GET parts 0 ranks)
  list(GET parts 1 colonies)
  set(output "${OUT}/r${ranks}-k${colonies}")
  set(compared "${output}${COMPARE_SUFFIX}")
  file(REMOVE "${compared}")
  set(launcher "")
  if(ranks GREATER 1)
    set(launcher "${MPIEXEC}" -n ${ranks} --oversubscribe)
  endif()
  execute_process(COMMAND ${launcher} "${ANTSLAM}" ${args} --colonies ${colonies}
                          ${OUTPUT_OPTION} "${output}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${run}: exit ${rc}; stderr:\n${err}")
  endif()
  string(REGEX MATCHALL "${SUMMARY_REGEX}" printed "${out}")
  list(LENGTH printed times)
  if(NOT times EQUAL 1)
    message(FATAL_ERROR "${run}: the summary was printed ${times} times:\n${out}")
  endif()
  if(NOT EXISTS "${compared}")
    message(FATAL_ERROR "${run}: ${compared} was not written")
  endif()
  if(ranks GREATER 1)
    execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files
                            "${OUT}/r1-k${colonies}${COMPARE_SUFFIX}" "${compared}"
                    RESULT_VARIABLE differ)
    if(NOT differ EQUAL 0)
      message(FATAL_ERROR "${run}: ${compared} differs from the single-process run's")
    endif()
  endif()
endforeach()
