# Install layout helpers: run paths relative to each installed file, so that
# `cmake --install build --prefix P` works for any P chosen at install time,
# and the Debian package made by CPack (`cpack -G DEB` in the build tree).

# Sets the install run path of `targets`, installed into `destination`
# (relative to the prefix), to the project's library folder relative to
# that destination ($ORIGIN-based).
function(deepgi_set_relative_install_rpath destination)
  file(RELATIVE_PATH to_libdir "/prefix/${destination}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
  if (to_libdir STREQUAL "")
    set(rpath "$ORIGIN")
  else ()
    set(rpath "$ORIGIN/${to_libdir}")
  endif ()
  set_target_properties(${ARGN} PROPERTIES INSTALL_RPATH "${rpath}")
endfunction()

# Helper programs (benchmarks) are not user commands: they go to
# libexec/deepgi, the command-line renderer to bin.
set(DEEPGI_INSTALL_HELPERDIR "${CMAKE_INSTALL_LIBEXECDIR}/deepgi")
