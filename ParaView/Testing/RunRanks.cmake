# Runs a pvbatch script on RANKS MPI ranks and fails clearly, instead of
# hanging, when the run does not end within TIMEOUT seconds:
#   cmake -DMPIEXEC=... -DPVBATCH=... -DSCRIPT=... -DPLUGIN=... -DOUTPUT=...
#         -DRANKS=N -DTIMEOUT=S -P RunRanks.cmake
# mpiexec may run as root here (CI containers); it oversubscribes the cores.
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
execute_process(
  COMMAND "${MPIEXEC}" --oversubscribe -n "${RANKS}" "${PVBATCH}" "${SCRIPT}" "${PLUGIN}"
    "${OUTPUT}" "${RANKS}"
  TIMEOUT "${TIMEOUT}"
  RESULT_VARIABLE result)
if (result MATCHES "timeout")
  message(FATAL_ERROR "pvbatch on ${RANKS} ranks did not finish within ${TIMEOUT} s "
    "(a rank waiting for the others' compositing?)")
elseif (result)
  message(FATAL_ERROR "pvbatch on ${RANKS} ranks failed: ${result}")
endif ()
