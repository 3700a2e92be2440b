# `revsph hash CASE --steps STEPS` on each process count of COUNTS (and with each thread count of
# THREADS) must print the one-process, one-thread hash (docs/design/distributed.md, piece 4).
# Run by CTest: cmake -DMPIEXEC=... -DREVSPH=... -DCASE=... -DSTEPS=... -DCOUNTS=1,2,3
# -DTHREADS=1,2 [-DEXTRA=--set=KEY=VALUE|--set=...] -P same_hash_on_processes.cmake
include(${CMAKE_CURRENT_LIST_DIR}/revsph_hash_on.cmake)
string(REPLACE "," ";" COUNTS "${COUNTS}")
string(REPLACE "," ";" THREADS "${THREADS}")
string(REPLACE "|" ";" EXTRA "${EXTRA}")
set(reference "")
foreach(threads IN LISTS THREADS)
  foreach(count IN LISTS COUNTS)
    revsph_hash_on(${count} ${threads} "${CASE} on ${count} processes x ${threads} threads"
                   hash ${CASE} --steps ${STEPS} ${EXTRA})
    if(reference STREQUAL "")
      set(reference "${hash}")
    elseif(NOT hash STREQUAL reference)
      message(FATAL_ERROR "${CASE}: ${count} processes x ${threads} threads give ${hash}, "
                          "the first run ${reference}")
    endif()
  endforeach()
endforeach()
