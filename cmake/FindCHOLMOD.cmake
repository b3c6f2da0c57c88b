# FindCHOLMOD: SuiteSparse's CHOLMOD (and UMFPACK) as imported targets.
# Debian 12's libsuitesparse-dev ships headers in include/suitesparse and no CMake config.
#   CHOLMOD::CHOLMOD   CHOLMOD with its SuiteSparse dependencies
#   UMFPACK::UMFPACK   UMFPACK (optional, when found)
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
foreach(lib cholmod amd camd colamd ccolamd suitesparseconfig umfpack)
  string(TOUPPER ${lib} LIB)
  find_library(${LIB}_LIBRARY ${lib})
endforeach()
find_package(BLAS QUIET)
find_package(LAPACK QUIET)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR
  AMD_LIBRARY COLAMD_LIBRARY SUITESPARSECONFIG_LIBRARY)

if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
    IMPORTED_LOCATION ${CHOLMOD_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${CHOLMOD_INCLUDE_DIR})
  set(_deps ${AMD_LIBRARY} ${COLAMD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})
  foreach(opt CAMD CCOLAMD)
    if(${opt}_LIBRARY)
      list(APPEND _deps ${${opt}_LIBRARY})
    endif()
  endforeach()
  if(LAPACK_FOUND)
    list(APPEND _deps ${LAPACK_LIBRARIES})
  endif()
  if(BLAS_FOUND)
    list(APPEND _deps ${BLAS_LIBRARIES})
  endif()
  set_property(TARGET CHOLMOD::CHOLMOD PROPERTY INTERFACE_LINK_LIBRARIES "${_deps}")
endif()
if(CHOLMOD_FOUND AND UMFPACK_LIBRARY AND NOT TARGET UMFPACK::UMFPACK)
  add_library(UMFPACK::UMFPACK UNKNOWN IMPORTED)
  set_target_properties(UMFPACK::UMFPACK PROPERTIES
    IMPORTED_LOCATION ${UMFPACK_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${CHOLMOD_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES CHOLMOD::CHOLMOD)
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY AMD_LIBRARY CAMD_LIBRARY COLAMD_LIBRARY
  CCOLAMD_LIBRARY SUITESPARSECONFIG_LIBRARY UMFPACK_LIBRARY)
