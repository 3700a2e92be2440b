# A snapshot written by a run on WRITERS processes (1 unless given), continued on 1, 2 and 3
# processes (`mpirun -np P revsph hash SNAPSHOT --steps S`), ends with the hash of one
# uninterrupted run of twice S steps (docs/design/distributed.md, piece 5: the whole state
# restored on every process, each keeping its region's share). Run by CTest:
# cmake -DMPIEXEC=... -DREVSPH=... -DCASE=... -DSTEPS=... -DWORK=dir [-DWRITERS=3]
# -P restart_on_processes.cmake
include(${CMAKE_CURRENT_LIST_DIR}/revsph_hash_on.cmake)
set(ENV{OMP_NUM_THREADS} 1)
file(REMOVE_RECURSE ${WORK})
math(EXPR twice "2 * ${STEPS}")
revsph_hash_on(1 1 "${CASE}, ${twice} steps uninterrupted" whole ${CASE} --steps ${twice})
if(NOT DEFINED WRITERS)
  set(WRITERS 1)
endif()
execute_process(COMMAND ${MPIEXEC} -np ${WRITERS} --oversubscribe -x OMP_NUM_THREADS=1
                        ${REVSPH} run ${CASE} --steps ${STEPS} --threads 1 --out ${WORK}
                        --set output.snapshot_every=${STEPS}
                OUTPUT_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the first half on ${WRITERS} processes failed: exit ${status}")
endif()
file(GLOB snapshots ${WORK}/snapshots/step_*${STEPS}.h5)
list(GET snapshots -1 snapshot)
foreach(count 1 2 3)
  revsph_hash_on(${count} 1 "${CASE} continued on ${count} processes" hash ${snapshot}
                 --steps ${STEPS})
  if(NOT hash STREQUAL whole)
    message(FATAL_ERROR "continued on ${count} processes: ${hash}, uninterrupted: ${whole}")
  endif()
endforeach()
