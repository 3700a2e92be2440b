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
  # Re-run this when HEAD moves (a commit updates the branch's ref file), so that a rebuild after
  # a commit does not keep reporting the commit of the first configure.
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --absolute-git-dir
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE _revsph_git_dir
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  execute_process(COMMAND ${GIT_EXECUTABLE} symbolic-ref -q HEAD
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE _revsph_git_ref
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  foreach(_revsph_git_file HEAD ${_revsph_git_ref})
    if(_revsph_git_dir AND EXISTS "${_revsph_git_dir}/${_revsph_git_file}")
      set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
        "${_revsph_git_dir}/${_revsph_git_file}")
    endif()
  endforeach()
endif()
string(TOUPPER "${CMAKE_BUILD_TYPE}" _revsph_build_type_upper)
set(REVSPH_BUILD_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_revsph_build_type_upper}} -ffp-contract=off -fno-fast-math -fno-math-errno")
string(STRIP "${REVSPH_BUILD_FLAGS}" REVSPH_BUILD_FLAGS)
configure_file(${PROJECT_SOURCE_DIR}/core/build_info.hpp.in ${PROJECT_BINARY_DIR}/generated/core/build_info.hpp @ONLY)
