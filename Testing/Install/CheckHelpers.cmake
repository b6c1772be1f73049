# Helpers of the install and package checks: fail() stops with a message,
# run() runs a command, fails on a non-zero status and returns its stdout
# in `out`. A command's arguments are a CMake list: no semicolons inside.
function(fail message)
  message(FATAL_ERROR "${DEEPGI_CHECK_NAME}: ${message}")
endfunction()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (rc)
    fail("'${ARGN}' failed (${rc}):\n${out}\n${err}")
  endif ()
  set(out "${out}" PARENT_SCOPE)
endfunction()
