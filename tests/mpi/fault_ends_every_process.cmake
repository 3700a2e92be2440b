# A fault met by some of the processes of a distributed run ends every process within seconds
# with the one-line message and exit status 3 (docs/design/distributed.md, piece 6); no process
# waits for the faulting one in an exchange. The faults found at the same point of a step by
# several processes are agreed on: the one line is the one-process run's (the lowest particle
# index), printed once, and `revsph run` leaves summary.json (completed: false) and its last
# snapshot. Run by CTest: cmake -DMPIEXEC=... -DREVSPH=... -DWORK=DIR -P fault_ends_every_process.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
# gresho has no walls: a strong gravity drops the bottom row of the fluid out of the domain at
# once, in the regions of several processes.
set(fault_line "revsph: error: the run stopped: step [0-9]+: fluid particle [0-9]+: position: left the domain[^\n]*")
foreach(count 1 3)
  execute_process(
    COMMAND ${MPIEXEC} -np ${count} --oversubscribe -x OMP_NUM_THREADS=1
            ${REVSPH} hash gresho --steps 2000 --threads 1 --set physics.gravity=1e5
    OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 120)
  message(STATUS "${count} processes: exit ${status}\n${errors}")
  if(NOT status EQUAL 3)
    message(FATAL_ERROR "expected exit status 3 (the simulation stopped), got ${status}")
  endif()
  string(REGEX MATCHALL "${fault_line}" lines "${errors}")
  list(LENGTH lines found)
  if(NOT found EQUAL 1)
    message(FATAL_ERROR "${count} processes: ${found} fault lines, not one")
  endif()
  list(APPEND reports "${lines}")
endforeach()
list(GET reports 0 one)
list(GET reports 1 three)
if(NOT one STREQUAL three)
  message(FATAL_ERROR "3 processes report\n  ${three}\none process\n  ${one}")
endif()
file(REMOVE_RECURSE ${WORK})
execute_process(
  COMMAND ${MPIEXEC} -np 3 --oversubscribe -x OMP_NUM_THREADS=1
          ${REVSPH} run gresho --steps 2000 --threads 1 --set physics.gravity=1e5
          --set output.snapshot_every=10 --out ${WORK}
  OUTPUT_QUIET ERROR_QUIET RESULT_VARIABLE status TIMEOUT 120)
if(NOT status EQUAL 3 OR NOT EXISTS ${WORK}/summary.json)
  message(FATAL_ERROR "run on 3 processes: exit ${status}, summary.json written: no")
endif()
file(READ ${WORK}/summary.json summary)
string(JSON completed GET "${summary}" completed)
string(JSON last GET "${summary}" last_snapshot)
if(completed OR NOT EXISTS ${last})
  message(FATAL_ERROR "run on 3 processes: completed ${completed}, last snapshot ${last}")
endif()
