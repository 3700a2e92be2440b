# `revsph run CASE --steps STEPS` on 1 process and on each count of COUNTS writes the same files
# (docs/design/distributed.md, pieces 3 and 5): energy.csv and diagnostics.csv to the last digit,
# run.xdmf, and every snapshot's datasets bit for bit (tests/mpi/same_run_files.py). Run by CTest:
# cmake -DMPIEXEC=... -DREVSPH=... -DPYTHON=... -DCASE=... -DSTEPS=... -DCOUNTS=2,3 -DWORK=dir
# [-DEXTRA=--set=KEY=VALUE|--set=...] -P run_on_processes.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
string(REPLACE "," ";" COUNTS "${COUNTS}")
string(REPLACE "|" ";" EXTRA "${EXTRA}")
file(REMOVE_RECURSE ${WORK})
math(EXPR every "${STEPS} / 2")
foreach(count 1 ${COUNTS})
  execute_process(
    COMMAND ${MPIEXEC} -np ${count} --oversubscribe -x OMP_NUM_THREADS=1
            ${REVSPH} run ${CASE} --steps ${STEPS} --threads 1 --out ${WORK}/np${count}
            --set output.snapshot_every=${every} --set output.energy_every=10 ${EXTRA}
    OUTPUT_QUIET ERROR_VARIABLE errors RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${CASE} on ${count} processes: exit ${status}\n${errors}")
  endif()
  if(NOT count EQUAL 1)
    execute_process(
      COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/same_run_files.py ${WORK}/np1 ${WORK}/np${count}
      OUTPUT_VARIABLE report RESULT_VARIABLE status)
    message(STATUS "${CASE} on ${count} processes: ${report}")
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${CASE}: the run on ${count} processes wrote other files")
    endif()
  endif()
endforeach()
