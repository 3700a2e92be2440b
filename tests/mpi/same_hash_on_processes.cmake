# `revsph hash CASE --steps STEPS` on each process count of COUNTS (and with each thread count of
# THREADS) must print the one-process, one-thread hash (docs/design/distributed.md, piece 4).
# Run by CTest: cmake -DMPIEXEC=... -DREVSPH=... -DCASE=... -DSTEPS=... -DCOUNTS=1,2,3
# -DTHREADS=1,2 [-DEXTRA=--set=KEY=VALUE] -P same_hash_on_processes.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
string(REPLACE "," ";" COUNTS "${COUNTS}")
string(REPLACE "," ";" THREADS "${THREADS}")
set(reference "")
foreach(threads IN LISTS THREADS)
  foreach(count IN LISTS COUNTS)
    execute_process(
      COMMAND ${MPIEXEC} -np ${count} --oversubscribe -x OMP_NUM_THREADS=${threads}
              ${REVSPH} hash ${CASE} --steps ${STEPS} --threads ${threads} ${EXTRA}
      OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status
      OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${CASE} on ${count} processes x ${threads} threads: exit ${status}\n${errors}")
    endif()
    string(REGEX MATCH "[0-9a-f]+$" hash "${output}")
    message(STATUS "${CASE} ${count} processes x ${threads} threads: ${hash}")
    if(reference STREQUAL "")
      set(reference "${hash}")
    elseif(NOT hash STREQUAL reference)
      message(FATAL_ERROR "${CASE}: ${count} processes x ${threads} threads give ${hash}, "
                          "the first run ${reference}")
    endif()
  endforeach()
endforeach()
