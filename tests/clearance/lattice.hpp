// Small integer shapes for the tests judged by the clearance oracle: boxes that touch cylinders
// exactly, and distances that are often rational (faces, edges and vertices against caps and sides).
#pragma once

#include <algorithm>  // std::min, std::max
#include <random>     // the generator

#include "support/cases.hpp"

namespace boxcyl::testing {

// Uniform integers in [lo, hi], as doubles.
struct Integers {
    std::mt19937_64& rng;
    double operator()(int lo, int hi) const { return static_cast<double>(std::uniform_int_distribution<int>(lo, hi)(rng)); }
};

// Case i's box: for even i an aligned box with integer bounds in [−7, 7]; for odd i an oriented box
// with integer centre, integer axes of any length and angle (dependent ones too: the case is judged as
// the parallelepiped they span) and extents 0, 1/2 or 1.
inline void lattice_box(Case& c, int i, const Integers& integer) {
    if (i % 2 == 0) {
        c.kind = BoxKind::aligned;
        for (int k = 0; k < 3; ++k) {
            const double a = integer(-7, 7), b = integer(-7, 7);
            c.aligned.min[k] = std::min(a, b);
            c.aligned.max[k] = std::max(a, b);
        }
    } else {
        c.kind = BoxKind::oriented;
        c.oriented.center = {integer(-6, 6), integer(-6, 6), integer(-6, 6)};
        for (auto& axis : c.oriented.axes) axis = {integer(-2, 2), integer(-2, 2), integer(-2, 2)};
        c.oriented.extents = {integer(0, 2) / 2, integer(0, 2) / 2, integer(0, 2) / 2};
    }
}

}  // namespace boxcyl::testing
