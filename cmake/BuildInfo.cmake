# Records how the binary was built (compiler, flags, version, git commit) so that every run's
# summary.json says which build produced its hash.
find_package(Git QUIET)
set(REVSPH_GIT_COMMIT "unknown")
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE REVSPH_GIT_COMMIT
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT REVSPH_GIT_COMMIT)
    set(REVSPH_GIT_COMMIT "unknown")
  endif()
endif()
string(TOUPPER "${CMAKE_BUILD_TYPE}" _revsph_build_type_upper)
set(REVSPH_BUILD_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_revsph_build_type_upper}} -ffp-contract=off -fno-fast-math -fno-math-errno")
string(STRIP "${REVSPH_BUILD_FLAGS}" REVSPH_BUILD_FLAGS)
configure_file(${PROJECT_SOURCE_DIR}/core/build_info.hpp.in ${PROJECT_BINARY_DIR}/generated/core/build_info.hpp @ONLY)
