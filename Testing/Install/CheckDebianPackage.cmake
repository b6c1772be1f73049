# Builds the Debian package with CPack and checks its metadata and
# contents; where the test may change the system (CI set, as root), installs
# it, runs deepgi-render and `import vtkdeepgi` with no environment, and
# removes it again.
#   cmake -DBUILD=<build> -DWORK=<dir> -DPYTHON=/usr/bin/python3 -P CheckDebianPackage.cmake
set(DEEPGI_CHECK_NAME "package check")
include("${CMAKE_CURRENT_LIST_DIR}/CheckHelpers.cmake")

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
run(cpack --config "${BUILD}/CPackConfig.cmake" -G DEB -B "${WORK}")
file(GLOB packages "${WORK}/deepgi_*.deb")
list(LENGTH packages count)
if (NOT count EQUAL 1)
  fail("expected one deepgi_*.deb in ${WORK}, found: ${packages}")
endif ()

run(dpkg-deb -I "${packages}")
set(info "${out}")
foreach (expected IN ITEMS "Package: deepgi" "Architecture: amd64" "libvtk9.1" "python3-vtk9")
  if (NOT info MATCHES "${expected}")
    fail("the package's control data lack '${expected}':\n${info}")
  endif ()
endforeach ()

run(dpkg-deb -c "${packages}")
set(contents "${out}")
foreach (expected IN ITEMS
    " ./usr/bin/deepgi-render"
    " ./usr/lib/libvtkDeepGIRendering.so.[0-9.]+"
    " ./usr/lib/python3/dist-packages/vtkdeepgi/__init__.py"
    " ./usr/lib/python3/dist-packages/vtkdeepgi/vtkDeepGIRendering.so"
    " ./usr/lib/cmake/DeepGI/DeepGIConfig.cmake"
    " ./usr/include/DeepGI/vtkDeepGIPass.h"
    " ./usr/libexec/deepgi/deepgi-benchmark-gbuffer")
  if (NOT contents MATCHES "${expected}")
    fail("the package lacks '${expected}':\n${contents}")
  endif ()
endforeach ()

execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if (NOT "$ENV{CI}" STREQUAL "" AND uid STREQUAL "0")
  run(dpkg -i "${packages}")
  set(clean_env "${CMAKE_COMMAND}" -E env --unset=LD_LIBRARY_PATH --unset=PYTHONPATH)
  execute_process(COMMAND ${clean_env} /usr/bin/deepgi-render --help
    RESULT_VARIABLE render_rc OUTPUT_VARIABLE render_out ERROR_VARIABLE render_err)
  execute_process(COMMAND ${clean_env} "${PYTHON}" -c
    "import vtkdeepgi; print(vtkdeepgi.__file__); vtkdeepgi.vtkDeepGIPass()"
    WORKING_DIRECTORY /
    RESULT_VARIABLE python_rc OUTPUT_VARIABLE python_out ERROR_VARIABLE python_err)
  run(dpkg --purge deepgi)
  if (render_rc OR NOT render_out MATCHES "Usage: deepgi-render")
    fail("/usr/bin/deepgi-render --help failed (${render_rc}):\n${render_out}\n${render_err}")
  endif ()
  if (python_rc OR NOT python_out MATCHES "^/usr/lib/python3/dist-packages/vtkdeepgi/")
    fail("import vtkdeepgi from the package failed (${python_rc}):\n${python_out}\n${python_err}")
  endif ()
  message(STATUS "package check: installed, ran deepgi-render and import vtkdeepgi, removed")
else ()
  message(STATUS "package check: contents checked; not installed (set CI and run as root)")
endif ()
