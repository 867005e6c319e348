# FindGMP: GMP and its C++ interface gmpxx (Debian: libgmp-dev), for boxcyl::exact.
#
# Defines GMP_FOUND, GMP_VERSION (from gmp.h, when readable) and the imported targets GMP::gmp and
# GMP::gmpxx (which links GMP::gmp). Installed beside boxcylConfig.cmake so that a consumer finds GMP
# the same way boxcyl's own build did; -DCMAKE_DISABLE_FIND_PACKAGE_GMP=ON simulates its absence.
include(FindPackageHandleStandardArgs)

find_path(GMP_INCLUDE_DIR gmp.h)
find_path(GMPXX_INCLUDE_DIR gmpxx.h)
find_library(GMP_LIBRARY gmp)
find_library(GMPXX_LIBRARY gmpxx)

# gmp.h may sit in a multiarch directory (Debian: /usr/include/x86_64-linux-gnu); read its version.
if(GMP_INCLUDE_DIR AND EXISTS "${GMP_INCLUDE_DIR}/gmp.h")
  file(STRINGS "${GMP_INCLUDE_DIR}/gmp.h" _gmp_version_lines
       REGEX "^#define __GNU_MP_VERSION(_MINOR|_PATCHLEVEL)? +[0-9]+")
  foreach(_part "" _MINOR _PATCHLEVEL)
    string(REGEX REPLACE ".*#define __GNU_MP_VERSION${_part} +([0-9]+).*" "\\1" _gmp_v${_part}
           "${_gmp_version_lines}")
  endforeach()
  if(_gmp_v MATCHES "^[0-9]+$" AND _gmp_v_MINOR MATCHES "^[0-9]+$" AND _gmp_v_PATCHLEVEL MATCHES "^[0-9]+$")
    set(GMP_VERSION "${_gmp_v}.${_gmp_v_MINOR}.${_gmp_v_PATCHLEVEL}")
  endif()
  unset(_gmp_version_lines)
endif()

find_package_handle_standard_args(GMP
  REQUIRED_VARS GMPXX_LIBRARY GMP_LIBRARY GMPXX_INCLUDE_DIR GMP_INCLUDE_DIR
  VERSION_VAR GMP_VERSION)
mark_as_advanced(GMP_INCLUDE_DIR GMPXX_INCLUDE_DIR GMP_LIBRARY GMPXX_LIBRARY)

if(GMP_FOUND)
  if(NOT TARGET GMP::gmp)
    add_library(GMP::gmp UNKNOWN IMPORTED)
    set_target_properties(GMP::gmp PROPERTIES
      IMPORTED_LOCATION "${GMP_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${GMP_INCLUDE_DIR}")
  endif()
  if(NOT TARGET GMP::gmpxx)
    add_library(GMP::gmpxx UNKNOWN IMPORTED)
    set_target_properties(GMP::gmpxx PROPERTIES
      IMPORTED_LOCATION "${GMPXX_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${GMPXX_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES GMP::gmp)
  endif()
endif()
