# --collect on a copy of a finished results folder (FROM: its runs and refs, into OUT), asking
# for more counts than were run: nothing may run, and OUT/robust.csv must equal FROM/robust.csv.
# With EARLIER=ON the copy also gets FROM/robust.csv as --earlier rows: with the runs copied each
# run must replace its earlier row (no row twice); with RUNS=OFF (refs only) the earlier rows
# must come through as they are.
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
file(COPY "${FROM}/refs" DESTINATION "${OUT}")
if(NOT RUNS STREQUAL "OFF")
  file(COPY "${FROM}/runs" DESTINATION "${OUT}")
endif()
if(EARLIER)
  file(COPY_FILE "${FROM}/robust.csv" "${OUT}/earlier.csv")
  list(APPEND args --earlier "${OUT}/earlier.csv")
endif()
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --out "${OUT}" --collect ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}; stderr:\n${err}")
endif()
file(READ "${FROM}/robust.csv" expected)
file(READ "${OUT}/robust.csv" collected)
if(NOT collected STREQUAL expected)
  message(FATAL_ERROR "collected rows differ from the runs':\n${collected}\nexpected:\n${expected}")
endif()
