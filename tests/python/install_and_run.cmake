# Installs the build into PREFIX (cmake --install) and runs a Python test against the install:
#   cmake -DBUILD=DIR -DPREFIX=DIR -DTEST=script.py -P install_and_run.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
execute_process(COMMAND /usr/bin/python3 ${TEST} ${PREFIX} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${TEST} failed (${status})")
endif()
