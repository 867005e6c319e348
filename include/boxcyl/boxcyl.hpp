// Everything a user needs: the shapes, validation and the query front door.
//
// Two forms, as the target linked chooses (like {fmt}'s compiled and header-only builds):
//   boxcyl::boxcyl (the compiled library, libboxcyl): the double and float queries (scalar, batch and
//     grid) are declared here (boxcyl/compiled.hpp) and compiled in the library, so this header is
//     light to compile and needs no GMP headers.
//   boxcyl::header_only / boxcyl::exact (they define BOXCYL_HEADER_ONLY): the templates themselves,
//     for any number type (boxcyl/query.hpp; the batch and grid queries in boxcyl/batch.hpp and
//     boxcyl/grid.hpp).
#pragma once

#if defined(BOXCYL_HEADER_ONLY) || defined(BOXCYL_HAS_EXACT)
#include "boxcyl/clearance.hpp"
#include "boxcyl/distance.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/pose.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/query.hpp"
#include "boxcyl/signed_distance.hpp"
#include "boxcyl/version.hpp"
#else
#include "boxcyl/compiled.hpp"
#endif
