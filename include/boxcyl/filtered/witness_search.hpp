// A searched hit certificate (issue #4), the filtered query's last try before exact arithmetic.
//
// Where stage 1's certificates fail on a hit, the intersection of box and cylinder is usually still
// far from degenerate — typically a flat box (a rectangle) cutting the cylinder off its centre and
// central cross-sections, where no fixed candidate point lies. A point of it is found by alternating
// projections (von Neumann) between the box and the cylinder shrunk to a fraction s ∈ {0.75, 0.97,
// 0.999} of its radius and half-height (a deep point first, a thin intersection last): each step
// projects onto the cylinder (clamp the axial coordinate to [−H', H'], scale the radial offset down
// to r') and then onto the box (clamp each coordinate), so the iterate is always a box point exactly
// (clamped in world coordinates for aligned boxes, in box coordinates otherwise). When the two
// convex sets meet, the iterates approach their intersection; once one lies in the full cylinder
// with margin, stage 0's witness test (semi_static.hpp: plain double, error bound computed at compile
// time) certifies the hit. The search itself is plain double and need not be accurate: only the
// final test has to be sound. Misses and near-touching hits stay undecided (the exact path answers);
// they cost the search's 3 × 256 steps, small beside the exact path.
#pragma once

#include <algorithm>  // std::clamp
#include <cmath>      // std::sqrt

#include "boxcyl/filtered/semi_static.hpp"

namespace boxcyl::filtered::witness_search {

namespace detail {

using semi_static::Kappas;
using semi_static::Problem;

// One projection onto the cylinder (centre c, unit axis d, half-height h, radius r) in the box frame.
inline Vec3<double> onto_cylinder(const Vec3<double>& x, const Problem& p, double h, double r) {
    const Vec3<double> y = x - p.c;
    const double t = dot(p.d, y);
    Vec3<double> w = y - t * p.d;
    const double rho = std::sqrt(dot(w, w));
    if (rho > r) w = (rho > 0 ? r / rho : 0.0) * w;
    return p.c + std::clamp(t, -h, h) * p.d + w;
}
inline Vec3<double> onto_box(const Vec3<double>& x, const Vec3<double>& e) {
    return {std::clamp(x[0], -e[0], e[0]), std::clamp(x[1], -e[1], e[1]), std::clamp(x[2], -e[2], e[2])};
}

// True when a searched box point certainly lies in the cylinder. `offset(x)` turns the box-frame
// iterate x into the witness offset v = Q − C of an exact box point Q (the clamp that makes it exact).
// The effort of a search: the shrink fractions tried, and the steps per fraction.
struct Effort {
    const double* shrinks;
    int shrink_count;
    int steps;
};
inline constexpr double quick_shrinks[] = {0.75};
inline constexpr double thorough_shrinks[] = {0.75, 0.97, 0.999};

template <class Offset>
bool search(const Problem& p, const Kappas& k, Effort effort, Offset&& offset) {
    if (!p.has_inner || !(p.r_in > 0) || !(p.h_in > 0)) return false;  // no room for a margin
    auto certain = [&](const Vec3<double>& x) {
        const Vec3<double> v = offset(x);
        return semi_static::witness_height_margin(v, p.d, p.h_in) > k.height.eps * p.e1 + k.height.g * p.g1 &&
               semi_static::witness_radial_margin(v, p.d, p.r_in) > k.radial.eps * p.e2 + k.radial.g * p.g2;
    };
    for (int n = 0; n < effort.shrink_count; ++n) {
        const double h = p.h_in * effort.shrinks[n], r = p.r_in * effort.shrinks[n];
        Vec3<double> x = onto_box(p.c, p.e);
        for (int step = 1; step <= effort.steps; ++step) {
            x = onto_box(onto_cylinder(x, p, h, r), p.e);
            if ((step & (step - 1)) == 0 && certain(x)) return true;  // after steps 1, 2, 4, …, 256
        }
    }
    return false;
}

}  // namespace detail

// The witness search for each box kind (false: no certificate found, the query stays undecided).
// quick: 8 steps at one shrink (0.75), for the queries stage 0 leaves undecided, before stage 1;
// thorough: 256 steps at each of three shrinks, the last try before exact arithmetic.
enum class Mode { quick, thorough };
inline detail::Effort effort(Mode m) {
    return m == Mode::quick ? detail::Effort{detail::quick_shrinks, 1, 8} : detail::Effort{detail::thorough_shrinks, 3, 256};
}

// On a problem computed by semi_static::problem() for the same box and cylinder.
inline bool certain_hit(const semi_static::Problem& p, const CanonicalBox<double>&, const Cylinder<double>&, Mode mode) {
    return detail::search(p, semi_static::canonical_kappas, effort(mode), [&p](const Vec3<double>& x) {
        return detail::onto_box(x, p.e) - p.c;
    });
}
inline bool certain_hit(const semi_static::Problem& p, const AlignedBox<double>& b, const Cylinder<double>& cyl, Mode mode) {
    return detail::search(p, semi_static::aligned_kappas, effort(mode), [&](const Vec3<double>& x) {
        Vec3<double> v;  // Q = the world point K + x clamped to [min, max]: exactly in the box
        for (int i = 0; i < 3; ++i) v[i] = std::clamp(p.k[i] + x[i], b.min[i], b.max[i]) - cyl.center[i];
        return v;
    });
}
inline bool certain_hit(const semi_static::Problem& p, const OrientedBox<double>&, const Cylinder<double>&, Mode mode) {
    return detail::search(p, semi_static::oriented_kappas, effort(mode), [&p](const Vec3<double>& x) {
        return detail::onto_box(x, p.e) - p.c;  // box coordinates x with |x_m| ≤ e_m: exact
    });
}

template <class Box>
bool certain_hit(const Box& b, const Cylinder<double>& cyl, Mode mode = Mode::thorough) {
    semi_static::Problem p;
    return semi_static::problem(b, cyl, p) && certain_hit(p, b, cyl, mode);
}

}  // namespace boxcyl::filtered::witness_search
