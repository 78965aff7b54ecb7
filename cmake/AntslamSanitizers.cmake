# ANTSLAM_SANITIZE=address,undefined  -> ASan + UBSan (CI runs the suite once this way)
# ANTSLAM_SANITIZE=thread             -> TSan, for the serial and TBB backends. libgomp is not
#                                        TSan-instrumented, so OpenMP runs report false races.
if(ANTSLAM_SANITIZE)
  message(STATUS "antslam: building with -fsanitize=${ANTSLAM_SANITIZE}")
  add_compile_options(-fsanitize=${ANTSLAM_SANITIZE} -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${ANTSLAM_SANITIZE})
  if(ANTSLAM_SANITIZE MATCHES "undefined")
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
endif()
