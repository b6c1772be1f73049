# Test registration shared by the project's CMake files.

# VTK's Python: Debian's /usr/bin/python3, which python3-vtk9 is built for
# (another python3 first on PATH may have no VTK).
find_program(DEEPGI_VTK_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)

# deepgi_add_python_test(NAME <test> SCRIPT <file.py> [ARGS <arg>...])
# Runs SCRIPT with VTK's Python against the vtkdeepgi package of this build,
# labelled DeepGI.
function(deepgi_add_python_test)
  cmake_parse_arguments(PARSE_ARGV 0 test "" "NAME;SCRIPT" "ARGS")
  add_test(NAME "${test_NAME}" COMMAND "${DEEPGI_VTK_PYTHON}" "${test_SCRIPT}" ${test_ARGS})
  set_tests_properties("${test_NAME}" PROPERTIES
    ENVIRONMENT "PYTHONPATH=${DEEPGI_PYTHONPATH}"
    LABELS "DeepGI")
endfunction()
