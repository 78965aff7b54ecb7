# Installs the build into PREFIX, takes the PYTHONPATH the install prints, and imports the
# installed module with PYTHON from a neutral folder: it must be the installed one, and work.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "install failed:\n${out}\n${err}")
endif()
if(NOT out MATCHES "antslam Python module: PYTHONPATH=([^\n]+)")
  message(FATAL_ERROR "the install printed no PYTHONPATH:\n${out}")
endif()
set(path ${CMAKE_MATCH_1})
set(ENV{PYTHONPATH} ${path})
execute_process(
  COMMAND ${PYTHON} -c
          "import antslam; s = antslam.slam.synth('paper9'); print(antslam.__file__, len(s))"
  WORKING_DIRECTORY ${PREFIX} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "import failed with PYTHONPATH=${path}:\n${err}")
endif()
if(NOT out MATCHES "^${path}/antslam/__init__.py 9\n$")
  message(FATAL_ERROR "imported the wrong module (expected one under ${path}):\n${out}")
endif()
