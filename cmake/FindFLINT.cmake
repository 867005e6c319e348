# FindFLINT: FLINT, the library of exact polynomial arithmetic (Debian: libflint-dev), for boxcyl::exact
# (the clearance query counts polynomial roots with it).
#
# Defines FLINT_FOUND, FLINT_VERSION (from flint/flint.h, when readable) and the imported target
# FLINT::flint. Installed beside boxcylConfig.cmake so that a consumer finds FLINT the same way boxcyl's
# own build did; -DCMAKE_DISABLE_FIND_PACKAGE_FLINT=ON simulates its absence.
include(FindPackageHandleStandardArgs)

find_path(FLINT_INCLUDE_DIR flint/fmpz_poly.h)
find_library(FLINT_LIBRARY flint)

if(FLINT_INCLUDE_DIR AND EXISTS "${FLINT_INCLUDE_DIR}/flint/flint.h")
  file(STRINGS "${FLINT_INCLUDE_DIR}/flint/flint.h" _flint_version_lines
       REGEX "^#define __FLINT_VERSION(_MINOR|_PATCHLEVEL)? +[0-9]+")
  foreach(_part "" _MINOR _PATCHLEVEL)
    string(REGEX REPLACE ".*#define __FLINT_VERSION${_part} +([0-9]+).*" "\\1" _flint_v${_part}
           "${_flint_version_lines}")
  endforeach()
  if(_flint_v MATCHES "^[0-9]+$" AND _flint_v_MINOR MATCHES "^[0-9]+$" AND _flint_v_PATCHLEVEL MATCHES "^[0-9]+$")
    set(FLINT_VERSION "${_flint_v}.${_flint_v_MINOR}.${_flint_v_PATCHLEVEL}")
  endif()
  unset(_flint_version_lines)
endif()

find_package_handle_standard_args(FLINT REQUIRED_VARS FLINT_LIBRARY FLINT_INCLUDE_DIR VERSION_VAR FLINT_VERSION)
mark_as_advanced(FLINT_INCLUDE_DIR FLINT_LIBRARY)

if(FLINT_FOUND AND NOT TARGET FLINT::flint)
  add_library(FLINT::flint UNKNOWN IMPORTED)
  set_target_properties(FLINT::flint PROPERTIES
    IMPORTED_LOCATION "${FLINT_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${FLINT_INCLUDE_DIR}")
endif()
