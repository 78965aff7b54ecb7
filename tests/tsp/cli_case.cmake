# One command-line test: runs ANTSLAM with ARGS (a |-separated list), checks the exit status
# (EXPECT_FAIL: non-zero, else zero) and that stdout+stderr match EXPECT (a regex). Optional
# CHECK_FILE must then exist and match CHECK_REGEX.
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${ANTSLAM} ${args} RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
set(all "${out}${err}")
if(EXPECT_FAIL AND status EQUAL 0)
  message(FATAL_ERROR "expected a failure, got status 0:\n${all}")
elseif(NOT EXPECT_FAIL AND NOT status EQUAL 0)
  message(FATAL_ERROR "expected success, got status ${status}:\n${all}")
endif()
if(NOT all MATCHES "${EXPECT}")
  message(FATAL_ERROR "output does not match '${EXPECT}':\n${all}")
endif()
if(CHECK_FILE)
  if(NOT EXISTS "${CHECK_FILE}")
    message(FATAL_ERROR "${CHECK_FILE} was not written")
  endif()
  file(READ "${CHECK_FILE}" content)
  if(NOT content MATCHES "${CHECK_REGEX}")
    message(FATAL_ERROR "${CHECK_FILE} does not match '${CHECK_REGEX}':\n${content}")
  endif()
endif()
