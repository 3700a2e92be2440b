# `revsph verify CASE --steps STEPS` on 2 processes reports what it reports on one
# (docs/design/distributed.md: the states compared by global index, the speeds' histograms summed
# over the processes): the same hashes, verdict, distances, energy budget and entropies; and, if
# BITWISE is set, the verdict "bitwise identical". Run by CTest:
# cmake -DMPIEXEC=... -DREVSPH=... -DCASE=... -DSTEPS=... [-DBITWISE=1] -P verify_on_processes.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(reports "")
foreach(count 1 2)
  execute_process(
    COMMAND ${MPIEXEC} -np ${count} --oversubscribe -x OMP_NUM_THREADS=1
            ${REVSPH} verify ${CASE} --steps ${STEPS} --threads 1
    OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${CASE} on ${count} processes: exit ${status}\n${output}\n${errors}")
  endif()
  # What the experiment found: whole lines, not its timing or progress lines (those start with a
  # carriage return). Brackets and semicolons would split CMake's lists.
  string(REPLACE "[" "<" output "${output}")
  string(REPLACE "]" ">" output "${output}")
  string(REPLACE ";" "," output "${output}")
  string(REGEX MATCHALL "\n(  |[a-z-]+ state hash:|turning-point hash:|energy|entropy of|verdict:)[^\n]*"
         found "${output}")
  string(JOIN "\n" report ${found})
  message(STATUS "${CASE} on ${count} processes:\n${report}")
  list(APPEND reports "${report}")
endforeach()
list(GET reports 0 one)
list(GET reports 1 two)
if(NOT one STREQUAL two)
  message(FATAL_ERROR "${CASE}: verify on 2 processes reports otherwise than on one")
endif()
if(BITWISE AND NOT one MATCHES "verdict: bitwise identical")
  message(FATAL_ERROR "${CASE}: not bitwise identical")
endif()
