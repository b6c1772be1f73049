# Runs deepgi-render and checks its exit status (and, optionally, the files
# it writes). Used by the tests in this directory:
#   cmake -DEXE=... -DARGS=a;b;c -DEXPECT=2 [-DOUTPUT=dir -DFILES=a.png;b.png] -P RunDeepGIRender.cmake
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
  message(FATAL_ERROR "deepgi-render ${ARGS}: exit status '${rc}', expected ${EXPECT}\n${err}")
endif ()
if (NOT EXPECT STREQUAL "0" AND NOT err MATCHES "deepgi-render: ")
  message(FATAL_ERROR "deepgi-render ${ARGS}: no 'deepgi-render: ...' message on stderr:\n${err}")
endif ()
foreach (f IN LISTS FILES)
  if (NOT EXISTS "${OUTPUT}/${f}")
    message(FATAL_ERROR "deepgi-render ${ARGS}: ${OUTPUT}/${f} was not written")
  endif ()
endforeach ()
