// Everything a user needs: the shapes, validation and the query front door.
#pragma once

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/pose.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/query.hpp"
#include "boxcyl/version.hpp"
