# Installs the build tree into a fresh prefix and checks that the installed
# tree runs from there with no environment: deepgi-render --help, the Python
# package (import and a pass from it), run paths relative to $ORIGIN,
# versioned shared libraries (SONAME), and the benchmarks out of bin/.
#   cmake -DBUILD=<build> -DPREFIX=<dir> -DPYTHON=/usr/bin/python3
#         -DPYTHON_DIR=<python destination> -P CheckInstall.cmake
set(DEEPGI_CHECK_NAME "install check")
include("${CMAKE_CURRENT_LIST_DIR}/CheckHelpers.cmake")

file(REMOVE_RECURSE "${PREFIX}")
run("${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${PREFIX}")

# Programs: the user command in bin/, the benchmarks as helpers.
if (NOT EXISTS "${PREFIX}/bin/deepgi-render")
  fail("${PREFIX}/bin/deepgi-render is missing")
endif ()
file(GLOB benchmarks_in_bin "${PREFIX}/bin/deepgi-benchmark-*")
if (benchmarks_in_bin)
  fail("benchmarks installed as user commands: ${benchmarks_in_bin}")
endif ()
if (NOT EXISTS "${PREFIX}/libexec/deepgi/deepgi-benchmark-gbuffer")
  fail("the benchmarks are not in ${PREFIX}/libexec/deepgi")
endif ()

# Nothing may point into the build tree: the environment is emptied and the
# build tree's libraries are not on any path.
set(clean_env "${CMAKE_COMMAND}" -E env --unset=LD_LIBRARY_PATH --unset=PYTHONPATH)
run(${clean_env} "${PREFIX}/bin/deepgi-render" --help)
if (NOT out MATCHES "Usage: deepgi-render")
  fail("deepgi-render --help printed no usage:\n${out}")
endif ()
run(ldd "${PREFIX}/bin/deepgi-render")
string(REGEX MATCHALL "libvtkDeepGI[A-Za-z]*\\.so[^\n]*" resolved "${out}")
foreach (line IN LISTS resolved)
  if (NOT line MATCHES "=> ${PREFIX}/")
    fail("deepgi-render resolves a DeepGI library outside ${PREFIX}: ${line}")
  endif ()
endforeach ()
if (NOT resolved)
  fail("ldd lists no DeepGI library for deepgi-render:\n${out}")
endif ()

# Shared libraries: versioned, with $ORIGIN-relative run paths.
file(GLOB libraries "${PREFIX}/lib*/libvtkDeepGI*.so.*.*.*")
list(LENGTH libraries count)
if (count LESS 3)
  fail("expected 3 versioned libraries under ${PREFIX}/lib, found: ${libraries}")
endif ()
foreach (binary IN LISTS libraries ITEMS "${PREFIX}/bin/deepgi-render")
  run(readelf -d "${binary}")
  if (NOT out MATCHES "R(UN)?PATH[^\n]*\\$ORIGIN")
    fail("${binary} has no $ORIGIN run path:\n${out}")
  endif ()
  if (out MATCHES "${BUILD}")
    fail("${binary} refers to the build tree ${BUILD}")
  endif ()
endforeach ()
foreach (library IN LISTS libraries)
  run(readelf -d "${library}")
  if (NOT out MATCHES "SONAME[^\n]*libvtkDeepGI[A-Za-z]*\\.so\\.[0-9]+\\.[0-9]+\\]")
    fail("${library} has no versioned SONAME:\n${out}")
  endif ()
endforeach ()

# The Python package from the prefix alone (a program without semicolons:
# run()'s arguments are a CMake list).
run(${clean_env} "PYTHONPATH=${PREFIX}/${PYTHON_DIR}" "${PYTHON}" -c
  "import os, vtkdeepgi\np = vtkdeepgi.vtkDeepGIPass()\np.SetPreset('high_quality')\n\
assert p.GetPreset() == p.HIGH_QUALITY\nprint(os.path.dirname(vtkdeepgi.__file__))")
if (NOT out MATCHES "^${PREFIX}/")
  fail("vtkdeepgi was imported from ${out}, not from ${PREFIX}")
endif ()
message(STATUS "install check: ${PREFIX} runs (deepgi-render, vtkdeepgi, run paths, SONAMEs)")
