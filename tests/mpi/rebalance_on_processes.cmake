# The regions cut again at every migration (REVSPH_REBALANCE_ABOVE=1) change no bit: `revsph run
# CASE --steps STEPS` on each process count of COUNTS ends with the one-process run's state hash,
# and the distributed runs did rebalance (summary.json's distribution record). With
# -DBY_TIME=1 the cuts are those made on the processes' measured computing times, at every reading
# (REVSPH_BALANCE_BY_TIME=every_reading): whatever the timings, every process cuts alike.
# Run by CTest: cmake -DMPIEXEC=... -DREVSPH=... -DCASE=... -DSTEPS=... -DCOUNTS=3,4
# -DTHREADS=1 -DWORK=DIR [-DBY_TIME=1] -P rebalance_on_processes.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
if(BY_TIME)
  set(ENV{REVSPH_REBALANCE_ABOVE} 1.05)
  set(ENV{REVSPH_BALANCE_BY_TIME} every_reading)
  set(counted rebalances_by_measured_time)
else()
  set(ENV{REVSPH_REBALANCE_ABOVE} 1)
  set(ENV{REVSPH_BALANCE_BY_TIME} on)
  set(counted rebalances)
endif()
string(REPLACE "," ";" COUNTS "${COUNTS}")
file(REMOVE_RECURSE ${WORK})

function(run_on processes out)
  execute_process(
    COMMAND ${MPIEXEC} -np ${processes} --oversubscribe -x OMP_NUM_THREADS=${THREADS}
            -x REVSPH_REBALANCE_ABOVE -x REVSPH_BALANCE_BY_TIME ${REVSPH} run ${CASE} --steps ${STEPS} --threads ${THREADS}
            --out ${out}
    OUTPUT_QUIET ERROR_VARIABLE errors RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${CASE} on ${processes} processes: exit ${status}\n${errors}")
  endif()
endfunction()

run_on(1 ${WORK}/np1)
file(READ ${WORK}/np1/summary.json summary)
string(JSON reference GET "${summary}" final_hash)
foreach(count IN LISTS COUNTS)
  run_on(${count} ${WORK}/np${count})
  file(READ ${WORK}/np${count}/summary.json summary)
  string(JSON hash GET "${summary}" final_hash)
  string(JSON rebalances GET "${summary}" distribution ${counted})
  message(STATUS "${CASE} on ${count} processes: ${hash}, ${rebalances} ${counted}")
  if(NOT hash STREQUAL reference)
    message(FATAL_ERROR "${CASE}: ${count} processes give ${hash}, one process ${reference}")
  endif()
  if(rebalances LESS 1)
    message(FATAL_ERROR "${CASE} on ${count} processes: no ${counted}: the test tests nothing")
  endif()
endforeach()
