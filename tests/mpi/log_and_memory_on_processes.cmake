# `revsph run` on 2 processes with its output sent to a file (here a pipe): plain progress lines,
# no carriage return or escape code, although Open MPI gives each process a pseudo-terminal
# (core/progress.hpp); REVSPH_PROGRESS=bar brings the bar back. summary.json holds process 0's
# peak memory and the largest over the processes, not less. Run by CTest:
# cmake -DMPIEXEC=... -DREVSPH=... -DWORK=DIR -P log_and_memory_on_processes.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
file(REMOVE_RECURSE ${WORK})
string(ASCII 13 carriage_return)
string(ASCII 27 escape)
foreach(setting auto bar)
  execute_process(
    COMMAND ${MPIEXEC} -np 2 --oversubscribe -x OMP_NUM_THREADS=1 -x REVSPH_PROGRESS=${setting}
            ${REVSPH} run dambreak-small --steps 20 --threads 1 --out ${WORK}/${setting}
    OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 120)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "REVSPH_PROGRESS=${setting}: exit ${status}\n${errors}")
  endif()
  string(FIND "${output}" "run 20/20 steps" progress_line)
  string(FIND "${output}" "${carriage_return}" carriage_return_at)
  string(FIND "${output}" "${escape}" escape_at)
  if(progress_line EQUAL -1)
    message(FATAL_ERROR "REVSPH_PROGRESS=${setting}: no progress line in\n${output}")
  endif()
  if(setting STREQUAL "auto" AND (NOT carriage_return_at EQUAL -1 OR NOT escape_at EQUAL -1))
    message(FATAL_ERROR "a log written on 2 processes holds carriage returns or escape codes")
  endif()
  if(setting STREQUAL "bar" AND (carriage_return_at EQUAL -1 OR escape_at EQUAL -1))
    message(FATAL_ERROR "REVSPH_PROGRESS=bar on 2 processes: no bar")
  endif()
endforeach()
file(READ ${WORK}/auto/summary.json summary)
string(JSON own GET "${summary}" peak_memory_bytes)
string(JSON largest ERROR_VARIABLE missing GET "${summary}" peak_memory_bytes_max_over_processes)
if(missing)
  message(FATAL_ERROR "summary.json: ${missing}")
endif()
message(STATUS "peak memory: process 0 ${own} bytes, the largest over the processes ${largest}")
if(own LESS_EQUAL 0 OR largest LESS own)
  message(FATAL_ERROR "summary.json: peak_memory_bytes_max_over_processes ${largest} < "
                      "peak_memory_bytes ${own}")
endif()
file(REMOVE_RECURSE ${WORK})
