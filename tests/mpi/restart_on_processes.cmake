# A one-process run's snapshot continued on 1, 2 and 3 processes (`mpirun -np P revsph hash
# SNAPSHOT --steps S`) ends with the hash of one uninterrupted run of twice S steps
# (docs/design/distributed.md, piece 5: the whole state restored on every process, each keeping
# its region's share). Run by CTest:
# cmake -DMPIEXEC=... -DREVSPH=... -DCASE=... -DSTEPS=... -DWORK=dir -P restart_on_processes.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(ENV{OMP_NUM_THREADS} 1)
file(REMOVE_RECURSE ${WORK})
math(EXPR twice "2 * ${STEPS}")
execute_process(COMMAND ${REVSPH} hash ${CASE} --steps ${twice} --threads 1
                OUTPUT_VARIABLE whole OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the uninterrupted run failed: exit ${status}")
endif()
execute_process(COMMAND ${REVSPH} run ${CASE} --steps ${STEPS} --threads 1 --out ${WORK}
                        --set output.snapshot_every=${STEPS}
                OUTPUT_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the first half failed: exit ${status}")
endif()
file(GLOB snapshots ${WORK}/snapshots/step_*${STEPS}.h5)
list(GET snapshots -1 snapshot)
foreach(count 1 2 3)
  execute_process(
    COMMAND ${MPIEXEC} -np ${count} --oversubscribe -x OMP_NUM_THREADS=1
            ${REVSPH} hash ${snapshot} --steps ${STEPS} --threads 1
    OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "continued on ${count} processes: exit ${status}\n${errors}")
  endif()
  string(REGEX MATCH "[0-9a-f]+$" hash "${output}")
  message(STATUS "${CASE} continued on ${count} processes: ${hash}")
  if(NOT hash STREQUAL whole)
    message(FATAL_ERROR "continued on ${count} processes: ${hash}, uninterrupted: ${whole}")
  endif()
endforeach()
