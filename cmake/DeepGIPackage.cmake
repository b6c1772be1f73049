# The Debian package (cpack -G DEB in the build tree): the libraries, the
# Python package, deepgi-render and the CMake package under /usr, for
# Debian's VTK 9.1. Shared-library dependencies are computed by
# dpkg-shlibdeps; VTK's Python is named explicitly (the wrapped modules
# import it at run time).
set(CPACK_PACKAGE_NAME "deepgi")
set(CPACK_PACKAGE_VENDOR "DeepGI developers")
set(CPACK_PACKAGE_CONTACT "DeepGI developers <deepgi@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Deep G-buffer global illumination render passes for VTK")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libvtk9.1 (>= 9.1), python3-vtk9 (>= 9.1)")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "Deep G-buffer global illumination render passes for VTK
 Render passes for VTK 9.1 that add stable approximate global illumination
 to any VTK scene (Mara et al., HPG 2016): a two-layer deep G-buffer,
 ambient obscurance, screen-space radiosity and mirror reflections, put on
 a renderer in one line (vtkDeepGIPass), with the Python package vtkdeepgi
 and the command-line renderer deepgi-render.")
include(CPack)
