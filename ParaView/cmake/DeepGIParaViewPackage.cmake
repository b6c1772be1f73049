# Finding Debian's ParaView 5.11 CMake package next to Debian's VTK 9.1.
#
# paraview-dev's CMake package declares files of python3-paraview (pvpython,
# the Python modules, and the wrapping hierarchies the plugin's client-server
# wrapping reads) and stops with "references the file ... but this file does
# not exist" when they are absent. python3-paraview cannot be installed
# beside python3-vtk9 (both ship `vtkmodules`); scripts/setup.sh unpacks it
# into a folder of its own instead (DEEPGI_PARAVIEW_PYTHON_ROOT, the root of
# the unpacked package). deepgi_find_paraview() then makes a copy of the CMake
# package in the build tree that differs in three ways only:
# - every file that computes the install prefix from its own location
#   (targets, module properties, VTK-m's package) computes it from the
#   original package's location, so every target still points at the
#   installed files;
# - the imported files are not checked for existence (pvpython and the
#   Python modules stay absent);
# - the wrapping hierarchies are read from the unpacked python3-paraview.
# Everywhere else (a ParaView built from source, ParaView_DIR given, or
# python3-paraview installed) ParaView is found as usual.

function (_deepgi_copy_paraview_package source destination python_root)
  file(GLOB_RECURSE files RELATIVE "${source}" "${source}/*")
  foreach (file IN LISTS files)
    get_filename_component(directory "${file}" DIRECTORY)
    file(READ "${source}/${file}" text)
    # The prefix computations start from the original file's directory.
    set(original_directory "${source}")
    if (directory)
      string(APPEND original_directory "/${directory}")
    endif ()
    string(REPLACE
      "set(_vtk_module_import_prefix \"\${CMAKE_CURRENT_LIST_DIR}\")"
      "set(_vtk_module_import_prefix \"${original_directory}\")"
      text "${text}")
    string(REPLACE
      "get_filename_component(PACKAGE_PREFIX_DIR \"\${CMAKE_CURRENT_LIST_DIR}/"
      "get_filename_component(PACKAGE_PREFIX_DIR \"${original_directory}/"
      text "${text}")
    string(REPLACE
      "\${_vtk_module_import_prefix}/lib/x86_64-linux-gnu/vtk/hierarchy/"
      "${python_root}/usr/lib/x86_64-linux-gnu/vtk/hierarchy/"
      text "${text}")
    if (file MATCHES "targets(-[a-z]+)?\\.cmake$")
      string(REPLACE
        "get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)"
        "set(_IMPORT_PREFIX \"${original_directory}\")"
        text "${text}")
    endif ()
    if (file MATCHES "targets-[a-z]+\\.cmake$")
      # python3-paraview's files (pvpython, the Python modules) are absent:
      # the imported files are not checked for existence.
      string(REGEX REPLACE "list\\(APPEND _cmake_import_check_files_for_[^\n]*\n" "" text "${text}")
      string(REGEX REPLACE "list\\(APPEND _IMPORT_CHECK_FILES_FOR_[^\n]*\n" "" text "${text}")
    endif ()
    file(WRITE "${destination}/${file}" "${text}")
  endforeach ()
endfunction ()

# Only the components the plugin uses: without a list, every component is
# required, and with it the Qt 5 development packages of ParaView's GUI
# modules, which the plugin does not use.
set(_deepgi_paraview_components RemotingCore RemotingServerManager RemotingViews)

macro (deepgi_find_paraview)
  set(_deepgi_debian_paraview "/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11")
  # A Python module of python3-paraview that the package checks for.
  set(_deepgi_paraview_python "/usr/lib/python3/dist-packages/vtkmodules/vtkCommonCore.so")
  if (ParaView_DIR OR NOT EXISTS "${_deepgi_debian_paraview}/paraview-config.cmake"
      OR EXISTS "${_deepgi_paraview_python}")
    find_package(ParaView 5.11 REQUIRED COMPONENTS ${_deepgi_paraview_components})
  else ()
    set(_deepgi_overlay "${CMAKE_BINARY_DIR}/paraview-cmake-package")
    if (NOT EXISTS "${_deepgi_overlay}/paraview-config.cmake")
      message(STATUS "ParaView's Python modules (python3-paraview) are not installed: "
        "finding ParaView through a copy of Debian's CMake package in ${_deepgi_overlay}")
      if (NOT IS_DIRECTORY "${DEEPGI_PARAVIEW_PYTHON_ROOT}/usr/lib/x86_64-linux-gnu/vtk/hierarchy")
        message(FATAL_ERROR "DEEPGI_PARAVIEW_PYTHON_ROOT (${DEEPGI_PARAVIEW_PYTHON_ROOT}) is not "
          "an unpacked python3-paraview (scripts/setup.sh makes one).")
      endif ()
      _deepgi_copy_paraview_package("${_deepgi_debian_paraview}" "${_deepgi_overlay}"
        "${DEEPGI_PARAVIEW_PYTHON_ROOT}")
    endif ()
    find_package(ParaView 5.11 REQUIRED CONFIG NO_DEFAULT_PATH PATHS "${_deepgi_overlay}"
      COMPONENTS ${_deepgi_paraview_components})
  endif ()
endmacro ()
