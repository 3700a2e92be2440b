# A fault met by some of the processes of a distributed run ends every process within seconds
# with the one-line message and exit status 3 (docs/design/distributed.md, piece 6); no process
# waits for the faulting one in an exchange. Run by CTest:
# cmake -DMPIEXEC=... -DREVSPH=... -P fault_ends_every_process.cmake
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
# gresho has no walls: a strong gravity drops the bottom of the fluid out of the domain, in the
# region of whichever process holds it.
execute_process(
  COMMAND ${MPIEXEC} -np 3 --oversubscribe -x OMP_NUM_THREADS=1
          ${REVSPH} hash gresho --steps 2000 --threads 1 --set physics.gravity=1e5
  OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 120)
message(STATUS "exit ${status}\n${errors}")
if(NOT status EQUAL 3)
  message(FATAL_ERROR "expected exit status 3 (the simulation stopped), got ${status}")
endif()
if(NOT errors MATCHES
   "revsph: error: the run stopped: step [0-9]+: fluid particle [0-9]+: position: left the domain")
  message(FATAL_ERROR "no one-line fault message")
endif()
