# Runs a program of this directory and checks its exit status, that stderr
# carries a "PROGRAM: ..." message when it fails, and (optionally) the files
# it writes. PROGRAM defaults to deepgi-render:
#   cmake -DEXE=... -DARGS=a;b;c -DEXPECT=2 [-DPROGRAM=name]
#         [-DOUTPUT=dir -DFILES=a.png;b.png] -P RunDeepGIRender.cmake
if (NOT DEFINED PROGRAM)
  set(PROGRAM deepgi-render)
endif ()
if (DEFINED OUTPUT)
  file(REMOVE_RECURSE "${OUTPUT}")
endif ()
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
foreach (f IN LISTS FILES)
  if (NOT EXISTS "${OUTPUT}/${f}")
    message(FATAL_ERROR "${PROGRAM} ${ARGS}: ${OUTPUT}/${f} was not written")
  endif ()
endforeach ()
