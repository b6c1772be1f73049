# The ParaView plugin's tests, registered by the main project
# (Testing/CMakeLists.txt) when DEEPGI_ENABLE_PARAVIEW is on. They need
# Debian's ParaView 5.11 and the unpacked python3-paraview that
# `scripts/setup.sh --paraview` provides (scripts/test.sh runs it).
#
# - deepgi-paraview-plugin: builds the plugin (ParaView/) from scratch in
#   <build>/paraview-plugin against ParaView's VTK 9.2 and installs it into
#   <build>/paraview-plugin/install (the fixture of the others, which load
#   the installed plugin);
# - deepgi-paraview-shader-tokens: the VTK shader text the G-buffer relies on
#   exists in ParaView's VTK;
# - deepgi-paraview-view: pvbatch loads the plugin; the view's properties,
#   set from Python, change the image as documented
#   (CheckDeepGIRenderView.py);
# - deepgi-paraview-gui: ParaView's GUI (Qt, under the suite's X display)
#   loads the plugin and renders its view in the main window's layout
#   (CheckDeepGIGui.py);
# - deepgi-paraview-example: the Python example of
#   Documentation/paraview.md runs;
# - deepgi-paraview-ranks-1, -2, -4: `mpiexec -n N pvbatch` renders a scene
#   split across the ranks with the view (CheckDeepGIRanks.py), each run
#   ending within a bounded time; deepgi-paraview-client-server-2: the same
#   scene from a client connected to pvserver on 2 ranks
#   (RunClientServer.sh); deepgi-paraview-ranks-equal: the four stills are
#   equal within 1/255 (CompareRanks.py).

set(DEEPGI_PARAVIEW_PYTHON_ROOT "${CMAKE_BINARY_DIR}/python3-paraview")
set(_plugin_build "${CMAKE_BINARY_DIR}/paraview-plugin")
set(_plugin "${_plugin_build}/install/lib/paraview-5.11/plugins/DeepGI/DeepGI.so")
set(_testing "${CMAKE_SOURCE_DIR}/ParaView/Testing")
find_program(DEEPGI_PVBATCH NAMES pvbatch)

add_test(NAME deepgi-paraview-plugin
  COMMAND "${CMAKE_COMMAND}"
    "-DSOURCE=${CMAKE_SOURCE_DIR}/ParaView"
    "-DBINARY=${_plugin_build}"
    "-DGENERATOR=${CMAKE_GENERATOR}"
    "-DPYTHON_ROOT=${DEEPGI_PARAVIEW_PYTHON_ROOT}"
    -P "${_testing}/BuildPlugin.cmake")
set_tests_properties(deepgi-paraview-plugin PROPERTIES
  FIXTURES_SETUP DeepGIParaViewPlugin
  LABELS "DeepGI;ParaView")

add_test(NAME deepgi-paraview-shader-tokens
  COMMAND "${_plugin_build}/bin/DeepGIParaViewShaderTokens")
set_tests_properties(deepgi-paraview-shader-tokens PROPERTIES
  FIXTURES_REQUIRED DeepGIParaViewPlugin
  LABELS "DeepGI;ParaView")

# The pvbatch tests fail on any error or warning that VTK or ParaView
# prints (their loguru lines "ERR|" and "WARN|"), besides their own checks.
#
# pvbatch's Python: ParaView's modules from the unpacked python3-paraview
# (first on the path, before python3-vtk9's `vtkmodules`).
set(_pvbatch_environment
  "PYTHONPATH=${DEEPGI_PARAVIEW_PYTHON_ROOT}/usr/lib/python3/dist-packages")

add_test(NAME deepgi-paraview-view
  COMMAND "${DEEPGI_PVBATCH}" "${_testing}/CheckDeepGIRenderView.py" "${_plugin}"
    "${CMAKE_CURRENT_BINARY_DIR}/ParaViewView")
set_tests_properties(deepgi-paraview-view PROPERTIES
  FIXTURES_REQUIRED DeepGIParaViewPlugin
  ENVIRONMENT "${_pvbatch_environment}"
  FAIL_REGULAR_EXPRESSION "ERR\\||WARN\\||Traceback"
  LABELS "DeepGI;ParaView")

find_program(DEEPGI_PARAVIEW_GUI NAMES paraview)
add_test(NAME deepgi-paraview-gui
  COMMAND "${DEEPGI_PARAVIEW_GUI}" --dr "--script=${_testing}/CheckDeepGIGui.py" --exit)
set_tests_properties(deepgi-paraview-gui PROPERTIES
  FIXTURES_REQUIRED DeepGIParaViewPlugin
  ENVIRONMENT "${_pvbatch_environment};DEEPGI_PARAVIEW_PLUGIN=${_plugin}"
  PASS_REGULAR_EXPRESSION "DeepGI GUI: all checks passed"
  FAIL_REGULAR_EXPRESSION "ERR\\||WARN\\||Traceback|FAILED"
  LABELS "DeepGI;ParaView")

add_test(NAME deepgi-paraview-example
  COMMAND "${DEEPGI_PVBATCH}" "${CMAKE_SOURCE_DIR}/ParaView/Examples/deepgi_paraview.py"
    "${_plugin}" "${DEEPGI_DATA_DIR}/meshes/bunny.ply" "${CMAKE_CURRENT_BINARY_DIR}")
set_tests_properties(deepgi-paraview-example PROPERTIES
  FIXTURES_REQUIRED DeepGIParaViewPlugin
  ENVIRONMENT "${_pvbatch_environment}"
  PASS_REGULAR_EXPRESSION "effects: [A-Z_|]*RADIOSITY"
  FAIL_REGULAR_EXPRESSION "ERR\\||WARN\\||Traceback"
  LABELS "DeepGI;ParaView")

# The same still on 1, 2 and 4 ranks (4 oversubscribe the cores), each run
# bounded in time, then compared.
foreach (ranks IN ITEMS 1 2 4)
  add_test(NAME deepgi-paraview-ranks-${ranks}
    COMMAND "${CMAKE_COMMAND}"
      "-DMPIEXEC=${MPIEXEC_EXECUTABLE}"
      "-DPVBATCH=${DEEPGI_PVBATCH}"
      "-DSCRIPT=${_testing}/CheckDeepGIRanks.py"
      "-DPLUGIN=${_plugin}"
      "-DOUTPUT=${CMAKE_CURRENT_BINARY_DIR}/ParaViewRanks"
      -DRANKS=${ranks}
      -DTIMEOUT=240
      -P "${_testing}/RunRanks.cmake")
  set_tests_properties(deepgi-paraview-ranks-${ranks} PROPERTIES
    FIXTURES_REQUIRED DeepGIParaViewPlugin
    FIXTURES_SETUP DeepGIParaViewRanks
    ENVIRONMENT "${_pvbatch_environment}"
    FAIL_REGULAR_EXPRESSION "ERR\\||WARN\\||Traceback"
    LABELS "DeepGI;ParaView")
endforeach ()
# ParaView's client-server mode: a client (Python with ParaView's modules)
# connected to pvserver on 2 ranks.
add_test(NAME deepgi-paraview-client-server-2
  COMMAND "${_testing}/RunClientServer.sh" "${MPIEXEC_EXECUTABLE}" 2 240
    "${_testing}/CheckDeepGIRanks.py" "${_plugin}" "${CMAKE_CURRENT_BINARY_DIR}/ParaViewRanks" 2)
set_tests_properties(deepgi-paraview-client-server-2 PROPERTIES
  FIXTURES_REQUIRED DeepGIParaViewPlugin
  FIXTURES_SETUP DeepGIParaViewRanks
  ENVIRONMENT "${_pvbatch_environment}"
  FAIL_REGULAR_EXPRESSION "ERR\\||WARN\\||Traceback"
  LABELS "DeepGI;ParaView")
add_test(NAME deepgi-paraview-ranks-equal
  COMMAND "${DEEPGI_VTK_PYTHON}" "${_testing}/CompareRanks.py"
    "${CMAKE_CURRENT_BINARY_DIR}/ParaViewRanks" ranks-2 ranks-4 client-server-2)
set_tests_properties(deepgi-paraview-ranks-equal PROPERTIES
  FIXTURES_REQUIRED DeepGIParaViewRanks
  LABELS "DeepGI;ParaView")
