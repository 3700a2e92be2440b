# Shared by the distributed lane's scripts: `mpirun -np PROCESSES revsph hash ARGS... --threads
# THREADS` (REVSPH and MPIEXEC set by the caller), failing the test with LABEL and revsph's own
# message if it does not succeed; the printed hash in RESULT.
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)

function(revsph_hash_on processes threads label result)
  execute_process(
    COMMAND ${MPIEXEC} -np ${processes} --oversubscribe -x OMP_NUM_THREADS=${threads}
            ${REVSPH} hash ${ARGN} --threads ${threads}
    OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${label}: exit ${status}\n${errors}")
  endif()
  string(REGEX MATCH "[0-9a-f]+$" hash "${output}")
  message(STATUS "${label}: ${hash}")
  set(${result} "${hash}" PARENT_SCOPE)
endfunction()
