# FindGmsh: the Gmsh SDK (C++ API, gmsh.h) as the imported target Gmsh::Gmsh.
# Debian 12's libgmsh-dev ships no CMake config.
find_path(GMSH_INCLUDE_DIR gmsh.h)
find_library(GMSH_LIBRARY gmsh)
if(GMSH_INCLUDE_DIR AND EXISTS ${GMSH_INCLUDE_DIR}/gmsh.h)
  file(STRINGS ${GMSH_INCLUDE_DIR}/gmsh.h _v REGEX "#define GMSH_API_VERSION \"")
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" Gmsh_VERSION "${_v}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Gmsh REQUIRED_VARS GMSH_LIBRARY GMSH_INCLUDE_DIR
  VERSION_VAR Gmsh_VERSION)
if(Gmsh_FOUND AND NOT TARGET Gmsh::Gmsh)
  add_library(Gmsh::Gmsh UNKNOWN IMPORTED)
  set_target_properties(Gmsh::Gmsh PROPERTIES
    IMPORTED_LOCATION ${GMSH_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${GMSH_INCLUDE_DIR})
endif()
mark_as_advanced(GMSH_INCLUDE_DIR GMSH_LIBRARY)
