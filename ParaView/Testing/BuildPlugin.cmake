# Configures, builds and installs the ParaView plugin (ParaView/) from
# scratch; the install prefix is <BINARY>/install:
#   cmake -DSOURCE=... -DBINARY=... -DGENERATOR=... -DPYTHON_ROOT=... -P BuildPlugin.cmake
file(REMOVE_RECURSE "${BINARY}")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE}" -B "${BINARY}" -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE=Release "-DDEEPGI_PARAVIEW_PYTHON_ROOT=${PYTHON_ROOT}"
  RESULT_VARIABLE result)
if (result)
  message(FATAL_ERROR "configuring the ParaView plugin failed (is paraview-dev installed? "
    "scripts/setup.sh --paraview installs it)")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BINARY}" RESULT_VARIABLE result)
if (result)
  message(FATAL_ERROR "building the ParaView plugin failed")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BINARY}" --prefix "${BINARY}/install"
  RESULT_VARIABLE result)
if (result)
  message(FATAL_ERROR "installing the ParaView plugin failed")
endif ()
