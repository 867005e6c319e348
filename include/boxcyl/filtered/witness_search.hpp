// Searched certificates: stage 0b of the filtered query, and its last try before
// exact arithmetic. Where stage 0's fixed candidates fail, the certificate is usually still far from
// degenerate, just not at a fixed place: a box corner cutting into the cylinder's side or a cap, a
// flat box crossing it off centre, a miss separated only by a direction through the rim. A search in
// plain double finds a candidate, and stage 0's tests (semi_static.hpp: error bounds computed at
// compile time) certify it; the search itself need not be accurate, only the final test is sound.
//
// Stage 0b, `decide` (after stage 0, before stage 1's linear inequalities on enclosures):
//   1. the axis-segment point P nearest to the box (Newton on the derivative of the squared distance,
//      which is monotone and piecewise linear in the axial parameter) and the box point Q nearest to P:
//      P − Q is the separating direction of most misses the face, axis and d × E_i tests leave (the
//      closest pair lies on the side, P − Q is its normal), and Q a box point deep in most side hits;
//   2. alternating projections (von Neumann) from Q between the box and the cylinder, both shrunk to
//      0.97 of their sizes (16 steps), then to 0.9995 (4 steps: shallow overlaps): for meeting sets the
//      iterates approach their intersection, whose points then lie inside the full solids with margin —
//      each box iterate (a box point exactly, by the clamp) and each cylinder iterate (a cylinder point
//      X = C + t·d + (z − (d·z)d) with |t| ≤ H) is tested; for apart sets they approach a nearest pair,
//      and y − x is tested as a separating direction. Each iterate is also tested as the middle of a
//      pair for the two-point certificates (semi_static::box_segment_inside, cylinder_segment_inside):
//      the hits of disks, segments and flat boxes, whose intersection has no interior point, so that
//      no single point has a margin. Certificates are tested after steps 1, 2, 4, 8, 16 of each phase.
// Box points of a rotated box are tested in world coordinates (WorldPoints: the parallelepiped as
// given against the cylinder as given), so a disk needs no inner cylinder there.
// What it leaves (segments against rotated flat boxes, thin overlaps, near-touching pairs) goes on.
//
// The thorough search, `certain_hit` (after stage 1, before exact arithmetic): alternating projections
// from the box point nearest to C with the cylinder shrunk by the depth (1 − s)·min(H, r) along and
// across the axis, s ∈ {0.75, 0.97, 0.999} (a deep point first, a thin intersection last), 256 steps
// each, testing box points. Misses and near-touching hits
// stay undecided (the exact path answers); they cost the search's 3 × 256 steps, small beside it.
#pragma once

#include <algorithm>  // std::min, std::max
#include <cmath>      // std::sqrt, std::fabs
#include <optional>   // undecided
#include <type_traits>  // per box kind

#include "boxcyl/filtered/semi_static.hpp"

namespace boxcyl::filtered::witness_search {

namespace detail {

using semi_static::Kappas;
using semi_static::Problem;
using semi_static::clamp_to;  // branch-free std::clamp

// One projection onto the cylinder (centre c, unit axis d, half-height h, radius r; h, r ≥ 0) in the
// box frame.
BOXCYL_FORCE_INLINE inline Vec3<double> onto_cylinder(const Vec3<double>& x, const Problem& p, double h, double r) {
    const Vec3<double> y = x - p.c;
    const double t = dot(p.d, y);
    Vec3<double> w = y - t * p.d;
    const double rho = std::sqrt(dot(w, w));
    if (rho > r) w = (rho > 0 ? r / rho : 0.0) * w;
    return p.c + clamp_to(t, -h, h) * p.d + w;
}
// Onto the box of extents e ≥ 0.
BOXCYL_FORCE_INLINE inline Vec3<double> onto_box(const Vec3<double>& x, const Vec3<double>& e) {
    return {clamp_to(x[0], -e[0], e[0]), clamp_to(x[1], -e[1], e[1]), clamp_to(x[2], -e[2], e[2])};
}

// The axial parameter t ∈ [−h, h] of the axis point c + t·d nearest to the box: the root of
// f'(t) = Σ_i d_i·(x_i − clamp(x_i, ±e_i)), x = c + t·d, which is non-decreasing and linear between
// the six parameters where x crosses a face plane. Newton's step is exact on the current piece, so
// a few steps (safeguarded by bisection of the bracket) reach it; any t is sound, this one is good.
inline double nearest_axis_parameter(const Problem& p, double h) {
    double lo = -h, hi = h, t = clamp_to(-dot(p.d, p.c), -h, h);
    for (int it = 0; it < 8; ++it) {
        double slope = 0, curvature = 0;
        for (int i = 0; i < 3; ++i) {
            const double x = p.c[i] + t * p.d[i], outside = x - clamp_to(x, -p.e[i], p.e[i]);
            slope += p.d[i] * outside;
            curvature += outside != 0 ? p.d[i] * p.d[i] : 0.0;
        }
        if (slope == 0) break;
        (slope > 0 ? hi : lo) = t;
        double next = curvature > 0 ? t - slope / curvature : (slope > 0 ? lo : hi);
        if (!(next > lo && next < hi)) next = lo * 0.5 + hi * 0.5;
        if (next == t) break;
        t = next;
    }
    return t;
}

// The search's phases: the solids shrunk to `shrink`, `steps` alternating projections.
struct Phase {
    double shrink;
    int steps;
};
inline constexpr Phase search_phases[] = {{0.97, 16}, {0.9995, 4}};

// How a box point's offset v = Q − C is certified to lie in the cylinder, alone or as one of a pair:
// in the box frame against the inner cylinder (r_in, h_in: for a rotated box, the cylinder shrunk by
// γ), or — oriented boxes — in world coordinates against the cylinder as given (no γ: disks and thin
// cylinders keep their box-point certificates in rotated boxes). `radius` is the radius the search
// aims for (≤ 0: no box pairs).
struct FramePoints {
    const Problem& p;
    const Kappas& k;
    double radius() const { return p.has_inner ? p.r_in : 0.0; }
    bool inside(const Vec3<double>& v) const { return semi_static::box_point_inside(p, k, v); }
    bool pair(const Vec3<double>& v1, const Vec3<double>& v2) const { return semi_static::box_segment_inside(p, k, v1, v2); }
};
struct WorldPoints {
    const Problem& p;
    const semi_static::WorldKappas& k;
    double radius() const { return p.r; }
    bool inside(const Vec3<double>& v) const { return semi_static::world_point_inside(p, k, v); }
    bool pair(const Vec3<double>& v1, const Vec3<double>& v2) const { return semi_static::world_segment_inside(p, k, v1, v2); }
};

// Stage 0b. `offset(x)` turns a box-frame point x into the witness offset v = Q − C of an exact box
// point Q (the clamp that makes it exact), in the frame that `points` tests it in.
template <class Offset, class Points>
std::optional<bool> search_nearest(const Problem& p, const Kappas& k, Offset&& offset, const Points& points) {
    // Cylinder points need |t| ≤ H exactly: H' = H(1 − 2^-40) < H, as for stage 0's (no H' when
    // H is subnormal: then no cylinder points are tested).
    const std::optional<double> axial = semi_static::axial_parameter(p);
    const double h = axial ? p.h * (1 - 0x1p-40) : 0.0;
    // A box-frame point y as a cylinder point's (t, z), |t| ≤ H' exactly; false when |z_i| > 2L (the
    // model's bound). A segment's points are its axis points: z = 0 exactly, no radial check.
    const bool radial = p.r != 0;
    auto split = [&](const Vec3<double>& y, double& t, Vec3<double>& z) {
        const Vec3<double> yc = y - p.c;
        t = clamp_to(dot(p.d, yc), -h, h);
        z = radial ? yc - t * p.d : Vec3<double>{0, 0, 0};
        const double reach = 2 * p.l;
        return std::fabs(z[0]) <= reach && std::fabs(z[1]) <= reach && std::fabs(z[2]) <= reach;
    };
    auto cylinder_witness = [&](const Vec3<double>& y) {
        double t = 0;
        Vec3<double> z;
        return axial && split(y, t, z) && semi_static::cylinder_point_inside(p, k, t, z, radial);
    };
    // Two-point certificates around the iterates (semi_static::box_segment_inside and
    // cylinder_segment_inside): the box iterate x moved both ways along the axis by half its radial
    // room, then clamped (a projection: the axial coordinate moves monotonically, the point by ≤ δ);
    // the cylinder iterate y moved both ways along the box axis E_m where it has the least room, by
    // half the room of the other two, then projected onto the cylinder (r 0.97, |t| ≤ H': again the
    // coordinate moves monotonically, the point by ≤ δ).
    auto box_pair = [&](const Vec3<double>& x) {
        const Vec3<double> w = x - p.c, across = w - dot(p.d, w) * p.d;
        const double delta = 0.5 * (points.radius() - std::sqrt(dot(across, across)));
        if (!(delta > 0)) return false;
        return points.pair(offset(onto_box(x + delta * p.d, p.e)), offset(onto_box(x - delta * p.d, p.e)));
    };
    auto cylinder_pair = [&](const Vec3<double>& y) {
        // Only where box pairs cannot work (a segment; a disk or a thin cylinder against a rotated box
        // in the box frame): elsewhere it found almost nothing the box pair did not, for two more
        // projections per test (6% of stage 0b's instructions on bench_query's set).
        if (!axial || points.radius() > 0) return false;
        double room[3];
        int m = 0;
        for (int i = 0; i < 3; ++i) {
            room[i] = p.e_in[i] - std::fabs(y[i]);
            if (room[i] < room[m]) m = i;
        }
        const double delta = 0.5 * std::min(room[(m + 1) % 3], room[(m + 2) % 3]);
        if (!(delta > 0)) return false;
        Vec3<double> step{0, 0, 0};
        step[m] = delta;
        const double r = radial ? p.r * search_phases[0].shrink : 0.0;
        double t1 = 0, t2 = 0;
        Vec3<double> z1, z2;
        return split(onto_cylinder(y + step, p, h, r), t1, z1) && split(onto_cylinder(y - step, p, h, r), t2, z2) &&
               semi_static::cylinder_segment_inside(p, k, t1, z1, t2, z2, radial);
    };

    const double t = nearest_axis_parameter(p, p.h);
    const Vec3<double> axis_point = p.c + t * p.d, q = onto_box(axis_point, p.e);
    if (semi_static::separated_along(p, k, axis_point - q)) return false;
    if (points.inside(offset(q))) return true;

    // Two phases: the sets shrunk to 0.97 (iterates deep inside the full solids), then, from where the
    // first phase ended, to 0.9995 (shallow overlaps, a corner or an edge just inside: the solids
    // shrunk to 0.97 no longer meet there).
    Vec3<double> x = q;
    for (const auto [shrink, steps] : search_phases) {
        const Vec3<double> e{std::max(p.e_in[0], 0.0) * shrink, std::max(p.e_in[1], 0.0) * shrink,
                             std::max(p.e_in[2], 0.0) * shrink};
        const double hs = std::max(p.h_in, 0.0) * shrink, rs = std::max(p.r_in, 0.0) * shrink;
        for (int step = 1; step <= steps; ++step) {
            const Vec3<double> y = onto_cylinder(x, p, hs, rs);
            x = onto_box(y, e);
            if ((step & (step - 1)) != 0) continue;  // after steps 1, 2, 4, 8, 16
            if (points.inside(offset(x)) || cylinder_witness(y)) return true;
            if (semi_static::separated_along(p, k, y - x)) return false;
            if (box_pair(x) || cylinder_pair(y)) return true;
        }
    }
    return std::nullopt;
}
template <class Offset>
std::optional<bool> search_nearest(const Problem& p, const Kappas& k, Offset&& offset) {
    return search_nearest(p, k, offset, FramePoints{p, k});
}

// The thorough search: true when a searched box point certainly lies in the cylinder.
inline constexpr double thorough_shrinks[] = {0.75, 0.97, 0.999};
inline constexpr int thorough_steps = 256;

template <class Offset>
bool search_thorough(const Problem& p, const Kappas& k, Offset&& offset) {
    if (!p.has_inner || !(p.r_in > 0) || !(p.h_in > 0)) return false;  // no room for a margin
    for (const double s : thorough_shrinks) {
        // Shrunk by the same absolute depth along the axis and across it (not by the factor s on each):
        // a flat disk (r ≫ H) or a needle (H ≫ r) keeps room in its long direction, and the points
        // sought are those at depth δ, whichever way is shallow.
        const double delta = (1 - s) * std::min(p.h_in, p.r_in);
        const double h = p.h_in - delta, r = p.r_in - delta;
        Vec3<double> x = onto_box(p.c, p.e);
        for (int step = 1; step <= thorough_steps; ++step) {
            x = onto_box(onto_cylinder(x, p, h, r), p.e);
            if ((step & (step - 1)) == 0 && semi_static::box_point_inside(p, k, offset(x))) return true;
        }
    }
    return false;
}

// The exact box point offsets for each box kind: Q = clamp(x) − C in the box frame (canonical and
// oriented boxes: box coordinates |x_m| ≤ e_m, exact), or the world point K + x clamped to [min, max]
// (aligned boxes: exactly in the box).
inline auto offset_in(const Problem& p) {
    return [&p](const Vec3<double>& x) { return onto_box(x, p.e) - p.c; };
}
inline auto offset_in(const Problem& p, const AlignedBox<double>& b, const Cylinder<double>& cyl) {
    return [&p, &b, &cyl](const Vec3<double>& x) {
        Vec3<double> v;
        for (int i = 0; i < 3; ++i) v[i] = clamp_to(p.k[i] + x[i], b.min[i], b.max[i]) - cyl.center[i];
        return v;
    };
}

// Oriented boxes, world coordinates: P = K + Σ x_m·A_m − C with x the box coordinates clamped to
// |x_m| ≤ e_m (exact), tested with WorldPoints.
inline auto offset_in_world(const Problem& p, const OrientedBox<double>& b, const Cylinder<double>& cyl) {
    return [&p, &b, &cyl](const Vec3<double>& x) {
        return semi_static::world_offset(b.center - cyl.center, b.axes, onto_box(x, p.e));
    };
}

}  // namespace detail

// A hint for the order of the later stages (never for an answer): whether the query looks within
// about 2^-30 of its scale of touching — a separating-axis test of stage 0 near its bound
// (semi_static::near_touching: a face or cap against a face, an edge against the side), or the axis
// segment's distance from the box near r (the side or the rim against a vertex or an edge: the
// distance from the nearest axis point to the box, in plain double).
inline bool near_touching(const semi_static::Problem& p, const semi_static::Kappas& k) {
    if (semi_static::near_touching(p, k)) return true;
    const double t = detail::nearest_axis_parameter(p, p.h);
    Vec3<double> gap;
    for (int i = 0; i < 3; ++i) {
        const double x = p.c[i] + t * p.d[i];
        gap[i] = x - semi_static::clamp_to(x, -p.e[i], p.e[i]);
    }
    return std::fabs(dot(gap, gap) - p.r * p.r) <= 0x1p-30 * p.l * p.l;
}

// Stage 0b on a problem computed by semi_static::problem() for the same box and cylinder: the answer,
// or nullopt when undecided. Box points of a rotated box are tested in world coordinates.
template <class Box>
std::optional<bool> decide(const semi_static::Problem& p, const Box& b, const Cylinder<double>& cyl) {
    const semi_static::Kappas& k = semi_static::kappas_of<Box>;
    if constexpr (std::is_same_v<Box, OrientedBox<double>>)
        return detail::search_nearest(p, k, detail::offset_in_world(p, b, cyl), detail::WorldPoints{p, semi_static::world_kappas});
    else if constexpr (std::is_same_v<Box, AlignedBox<double>>)
        return detail::search_nearest(p, k, detail::offset_in(p, b, cyl));
    else
        return detail::search_nearest(p, k, detail::offset_in(p));
}

// The thorough hit search on a computed problem (false: no certificate found).
template <class Box>
bool certain_hit(const semi_static::Problem& p, const Box& b, const Cylinder<double>& cyl) {
    if constexpr (std::is_same_v<Box, AlignedBox<double>>)
        return detail::search_thorough(p, semi_static::aligned_kappas, detail::offset_in(p, b, cyl));
    else
        return detail::search_thorough(p, semi_static::kappas_of<Box>, detail::offset_in(p));
}

}  // namespace boxcyl::filtered::witness_search
