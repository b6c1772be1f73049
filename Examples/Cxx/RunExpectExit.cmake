# Runs a program and checks its exit status and that stderr carries a
# "PROGRAM: ..." message when it fails:
#   cmake -DEXE=... -DARGS=a;b;c -DEXPECT=2 -DPROGRAM=name -P RunExpectExit.cmake
execute_process(
  COMMAND "${EXE}" ${ARGS}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
message("${out}")
if (NOT rc STREQUAL EXPECT)
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: exit status '${rc}', expected ${EXPECT}\n${err}")
endif ()
if (NOT EXPECT STREQUAL "0" AND NOT err MATCHES "${PROGRAM}: ")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: no '${PROGRAM}: ...' message on stderr:\n${err}")
endif ()
