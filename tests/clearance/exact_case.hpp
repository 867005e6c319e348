// A test case's box as the exact parallelepiped the clearance oracle judges (every box kind).
#pragma once

#include "boxcyl/exact/convert.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/number/rational.hpp"
#include "support/cases.hpp"

namespace boxcyl::testing {

inline Parallelepiped<Rational> exact_box(const Case& c) {
    const OrientedBox<Rational> o = c.kind == BoxKind::aligned    ? as_oriented_box(to_exact(c.aligned))
                                    : c.kind == BoxKind::oriented ? to_exact(c.oriented)
                                                                  : as_oriented_box(to_exact(c.canonical));
    return {o.center, o.axes, o.extents};
}

}  // namespace boxcyl::testing
