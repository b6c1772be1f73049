# Runs one of the tools (Apps/) and checks its exit status, that stderr
# carries a "PROGRAM: ..." message when it fails, and (optionally) the files
# it writes. PROGRAM defaults to deepgi-render:
#   cmake -DEXE=... -DARGS=a;b;c -DEXPECT=2 [-DPROGRAM=name]
#         [-DOUTPUT=dir -DFILES=a.png;b.png]
#         [-DKEEP=file] [-DLINKS=name;...] [-DMESSAGE=regex] -P RunDeepGIRender.cmake
# MESSAGE: a regular expression that stderr, one line, must match.
# OUTPUT is removed before the run. KEEP (a path) is created before the run
# with a known content and must still have it afterwards; LINKS are
# symbolic links to KEEP created before the run (names in OUTPUT), each of
# which must afterwards be a regular file, KEEP's content unchanged. No
# temporary "*.partial-*" file may be left in OUTPUT.
if (NOT DEFINED PROGRAM)
  set(PROGRAM deepgi-render)
endif ()
if (DEFINED OUTPUT)
  file(REMOVE_RECURSE "${OUTPUT}")
endif ()
set(_keep_content "this file must not be written by ${PROGRAM}\n")
if (DEFINED KEEP)
  file(WRITE "${KEEP}" "${_keep_content}")
endif ()
foreach (link IN LISTS LINKS)
  file(MAKE_DIRECTORY "${OUTPUT}")
  file(CREATE_LINK "${KEEP}" "${OUTPUT}/${link}" SYMBOLIC)
endforeach ()
execute_process(
  COMMAND "${EXE}" ${ARGS}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
message("${out}")
if (NOT rc STREQUAL EXPECT)
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: exit status '${rc}', expected ${EXPECT}\n${err}")
endif ()
if (DEFINED MESSAGE)
  string(STRIP "${err}" _line)
  string(FIND "${_line}" "\n" _newline)
  if (NOT _line MATCHES "${MESSAGE}" OR NOT _newline EQUAL -1)
    message(FATAL_ERROR "${PROGRAM} ${ARGS}: stderr is not one line matching '${MESSAGE}':\n${err}")
  endif ()
endif ()
if (NOT EXPECT STREQUAL "0" AND NOT err MATCHES "${PROGRAM}: ")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: no '${PROGRAM}: ...' message on stderr:\n${err}")
endif ()
foreach (f IN LISTS FILES)
  if (NOT EXISTS "${OUTPUT}/${f}")
    message(FATAL_ERROR "${PROGRAM} ${ARGS}: ${OUTPUT}/${f} was not written")
  endif ()
endforeach ()
if (DEFINED KEEP)
  file(READ "${KEEP}" _content)
  if (NOT _content STREQUAL _keep_content)
    message(FATAL_ERROR "${PROGRAM} ${ARGS}: ${KEEP} was written (through a symbolic link?)")
  endif ()
endif ()
foreach (link IN LISTS LINKS)
  if (IS_SYMLINK "${OUTPUT}/${link}" OR NOT EXISTS "${OUTPUT}/${link}")
    message(FATAL_ERROR "${PROGRAM} ${ARGS}: ${OUTPUT}/${link} is not a new file that replaced "
                        "the symbolic link")
  endif ()
endforeach ()
if (DEFINED OUTPUT AND IS_DIRECTORY "${OUTPUT}")
  file(GLOB_RECURSE _partial "${OUTPUT}/*.partial-*")
  if (_partial)
    message(FATAL_ERROR "${PROGRAM} ${ARGS}: temporary files left: ${_partial}")
  endif ()
endif ()
