// Near-touching query generators (fixed seeds; used by tests and benchmarks):
//  * touching_case: shapes that touch exactly — faces, edges and vertices of aligned, canonical and
//    signed-permutation boxes met by a cylinder's side, cap or rim; zero sizes (flat boxes, segments
//    r = 0, disks h = 0); axis-aligned and oblique axes whose unit vector is rational ((3,0,4)/5, …);
//    integer and binary-fraction coordinates — and, for a third of them, a one-ulp neighbour (one
//    parameter moved by one double either way: a hit overlapping by an ulp or a miss by an ulp).
//  * adversarial_case: a near-touching mix — rounded rotations with a cylinder placed at the rounded
//    contact, magnitudes 2^±1000 in one query, segments and disks ending at box vertices and edges,
//    denormal axis components beside 1, sub-ulp cylinders on boxes near 1e15 — each then moved by up to
//    two ulps in one parameter.
// Every case is valid input (validate() holds); the exact answer is the oracle's.
#pragma once

#include <array>   // frames
#include <cmath>   // std::ldexp, std::nextafter
#include <random>  // std::mt19937_64

#include "support/cases.hpp"

namespace boxcyl::testing {

namespace touching_detail {

inline double pick(std::mt19937_64& rng, std::initializer_list<double> v) {
    return *(v.begin() + static_cast<std::ptrdiff_t>(rng() % v.size()));
}
inline int integer(std::mt19937_64& rng, int lo, int hi) {
    return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1));
}
// x moved by n doubles (n may be negative).
inline double ulps(double x, int n) {
    const double to = n > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < (n > 0 ? n : -n); ++i) x = std::nextafter(x, to);
    return x;
}

// One parameter of the case moved by n doubles: a centre coordinate, the radius, the height or a box
// bound (sizes stay ≥ 0, boxes stay min ≤ max).
inline void nudge(Case& c, std::mt19937_64& rng, int n) {
    switch (rng() % 4) {
        case 0: {
            double& x = c.cylinder.center[rng() % 3];
            x = ulps(x, n);
            return;
        }
        case 1: c.cylinder.radius = std::max(0.0, ulps(c.cylinder.radius, n)); return;
        case 2: c.cylinder.height = std::max(0.0, ulps(c.cylinder.height, n)); return;
        default: break;
    }
    const int i = static_cast<int>(rng() % 3);
    switch (c.kind) {
        case BoxKind::aligned:
            if (rng() & 1) c.aligned.max[i] = std::max(c.aligned.min[i], ulps(c.aligned.max[i], n));
            else c.aligned.min[i] = std::min(c.aligned.max[i], ulps(c.aligned.min[i], n));
            return;
        case BoxKind::oriented: c.oriented.extents[i] = std::max(0.0, ulps(c.oriented.extents[i], n)); return;
        case BoxKind::canonical: c.canonical.extents[i] = std::max(0.0, ulps(c.canonical.extents[i], n)); return;
    }
}

// Unit directions with rational components (Pythagorean triples), scaled by a power of two (the
// query's axis need not be unit length), and the exact reach of a cylinder along a box axis for them.
struct Direction {
    Vec3<double> axis;  // a multiple of the unit direction
    Vec3<double> unit_num;  // the unit direction ·5 (or ·1 for a coordinate axis), exactly
    double den;
};
inline Direction direction(std::mt19937_64& rng) {
    static constexpr int triples[][3] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {3, 0, 4}, {4, 3, 0}, {0, 4, 3}, {3, 4, 0}};
    const auto& t = triples[rng() % 7];
    Vec3<double> u{double(t[0]), double(t[1]), double(t[2])};
    for (int i = 0; i < 3; ++i)
        if (rng() & 1) u[i] = -u[i];
    const double den = (t[0] + t[1] + t[2] == 1) ? 1.0 : 5.0;
    const double s = std::ldexp(1.0, integer(rng, -2, 3));
    return {{u[0] * s, u[1] * s, u[2] * s}, u, den};
}

}  // namespace touching_detail

// A case whose solids touch exactly (or, with neighbour = ±1, one parameter one ulp off).
inline Case touching_case(std::mt19937_64& rng) {
    using namespace touching_detail;
    Case c;
    const double unit = std::ldexp(1.0, integer(rng, -8, 8));  // integer or binary-fraction coordinates
    // The box, [lo, hi] per axis (hi − lo may be 0), around an integer origin.
    Vec3<double> lo, hi;
    for (int i = 0; i < 3; ++i) {
        const int o = integer(rng, -20, 20), w = (rng() % 6 == 0) ? 0 : integer(rng, 1, 8);
        lo[i] = o * unit;
        hi[i] = (o + w) * unit;
    }
    // Sizes: a multiple of 5 units (so that 3/5 and 4/5 of them are exact), zero sometimes.
    auto size = [&](int zero_one_in) { return (rng() % zero_one_in == 0) ? 0.0 : 5.0 * integer(rng, 1, 4) * unit; };
    const touching_detail::Direction dir = direction(rng);
    c.cylinder.axis = dir.axis;
    c.cylinder.radius = size(6);
    c.cylinder.height = size(6);
    const double r = c.cylinder.radius, H = c.cylinder.height / 2;
    // The cylinder's reach from its centre along coordinate axis k: H|u_k| + r√(1 − u_k²), exact for
    // these directions (√(1 − u_k²) ∈ {0, 3/5, 4/5, 1}).
    auto reach = [&](int k) {
        const double uk = std::fabs(dir.unit_num[k]) / dir.den;
        const double rest = dir.den == 1 ? (uk == 1 ? 0.0 : 1.0) : (uk == 0 ? 1.0 : uk == 0.6 ? 0.8 : 0.6);
        return H * uk + r * rest;
    };
    const int k = static_cast<int>(rng() % 3);  // the face normal
    const bool upper = rng() & 1;
    Vec3<double> center;
    const int contact = static_cast<int>(rng() % 3);  // 0: a face's interior, 1: a face's edge, 2: a vertex
    for (int i = 0; i < 3; ++i) {
        if (i == k) continue;
        const bool to_edge = contact == 2 || (contact == 1 && i == (k + 1) % 3);
        // On the face's extent (its interior, or a bound for an edge/vertex contact).
        center[i] = to_edge ? ((rng() & 1) ? hi[i] : lo[i]) : lo[i] + (hi[i] - lo[i]) * 0.5;
    }
    center[k] = upper ? hi[k] + reach(k) : lo[k] - reach(k);
    // Edge contact of a cylinder side ∥ the edge (axis along k' ≠ k): a Pythagorean offset (3, 4)·s
    // from the edge, radius 5·s, touches the edge line itself.
    if (contact == 1 && dir.den == 1 && std::fabs(dir.unit_num[k]) == 0 && r > 0 && (rng() & 1)) {
        const int a = static_cast<int>(std::fabs(dir.unit_num[0]) == 1 ? 0 : std::fabs(dir.unit_num[1]) == 1 ? 1 : 2);
        const int b = 3 - a - k;  // the third axis
        const double s = r / 5;
        center[k] = upper ? hi[k] + 3 * s : lo[k] - 3 * s;
        center[b] = (rng() & 1) ? hi[b] + 4 * s : lo[b] - 4 * s;
    }
    c.cylinder.center = center;
    switch (rng() % 4) {
        case 0:
        case 1:
            c.kind = BoxKind::aligned;
            c.aligned = {lo, hi};
            break;
        case 2: {
            // The same box as a signed-permutation frame (exactly orthonormal): axes[j] = ±e_{p(j)}.
            c.kind = BoxKind::oriented;
            c.oriented.axes = random_signed_permutation(rng);
            Vec3<double> mid, half;
            for (int i = 0; i < 3; ++i) mid[i] = lo[i] + (hi[i] - lo[i]) * 0.5, half[i] = (hi[i] - lo[i]) * 0.5;
            c.oriented.center = mid;
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i)
                    if (c.oriented.axes[j][i] != 0) c.oriented.extents[j] = half[i];
            break;
        }
        default: {
            // Canonical: the box centred at the origin, the cylinder moved with it.
            c.kind = BoxKind::canonical;
            for (int i = 0; i < 3; ++i) {
                const double mid = lo[i] + (hi[i] - lo[i]) * 0.5;
                c.canonical.extents[i] = (hi[i] - lo[i]) * 0.5;
                c.cylinder.center[i] -= mid;
            }
            break;
        }
    }
    if (rng() % 3 == 0) nudge(c, rng, (rng() & 1) ? 1 : -1);
    return c;
}

// A near-touching adversarial case (see the header comment).
inline Case adversarial_case(std::mt19937_64& rng) {
    using namespace touching_detail;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Case c;
    switch (rng() % 5) {
        case 0: {
            // A rounded rotation; the cylinder's side placed at the rounded contact with a face.
            c.kind = BoxKind::oriented;
            c.oriented.axes = random_rotation(rng);
            c.oriented.center = {unit(rng) * 8 - 4, unit(rng) * 8 - 4, unit(rng) * 8 - 4};
            c.oriented.extents = {0.5 + unit(rng), 0.5 + unit(rng), 0.5 + unit(rng)};
            const int k = static_cast<int>(rng() % 3), a = (k + 1) % 3;
            c.cylinder.radius = 0.25 + unit(rng);
            c.cylinder.height = 0.5 + unit(rng);
            c.cylinder.axis = c.oriented.axes[a];  // side parallel to the face
            const double d = c.oriented.extents[k] + c.cylinder.radius;
            for (int i = 0; i < 3; ++i) c.cylinder.center[i] = c.oriented.center[i] + d * c.oriented.axes[k][i];
            break;
        }
        case 1: {
            // 2^±1000 in one query: a huge box and a tiny cylinder on its face, or the reverse.
            const double big = std::ldexp(1.0 + unit(rng), 1000), small = std::ldexp(1.0 + unit(rng), -1000);
            c.kind = BoxKind::aligned;
            const bool huge_box = rng() & 1;
            const double e = huge_box ? big : small, r = huge_box ? small : big;
            c.aligned = {{-e, -e, -e}, {e, e, e}};
            c.cylinder.axis = {0, 0, 1};
            c.cylinder.radius = r;
            c.cylinder.height = huge_box ? small : big;
            c.cylinder.center = {e + r, huge_box ? 0.0 : e, 0};
            break;
        }
        case 2: {
            // r = 0 (a segment) or h = 0 (a disk) ending at a box vertex or on an edge.
            c.kind = BoxKind::aligned;
            c.aligned = {{0, 0, 0}, {pick(rng, {1, 2, 0.5, 3}), pick(rng, {1, 2, 0.25}), pick(rng, {1, 4, 0.5})}};
            const Vec3<double> v{c.aligned.max[0], c.aligned.max[1], (rng() & 1) ? c.aligned.max[2] : 0.5 * c.aligned.max[2]};
            if (rng() & 1) {
                c.cylinder.radius = 0;  // a segment from the vertex outward along (3, 4, 0)/5·L
                c.cylinder.height = 10;
                c.cylinder.axis = {3, 4, 0};
                c.cylinder.center = {v[0] + 3, v[1] + 4, v[2]};
            } else {
                c.cylinder.height = 0;  // a disk in the plane z = v_z whose rim passes through the vertex
                c.cylinder.radius = 5;
                c.cylinder.axis = {0, 0, 1};
                c.cylinder.center = {v[0] + 3, v[1] + 4, v[2]};
            }
            break;
        }
        case 3: {
            // A denormal axis component beside 1: the side touches the face y = 1 up to the tilt.
            c.kind = BoxKind::aligned;
            c.aligned = {{-1, -1, -1}, {1, 1, 1}};
            const double tilt = std::numeric_limits<double>::denorm_min() * double(1 + rng() % 1000) * ((rng() & 1) ? 1 : -1);
            c.cylinder.axis = {1, tilt, 0};
            c.cylinder.radius = 0.5;
            c.cylinder.height = 1;
            c.cylinder.center = {0, 1.5, 0};
            break;
        }
        default: {
            // A box near 1e15 (ulp 0.125) and a cylinder far below that ulp touching its face.
            c.kind = BoxKind::aligned;
            const double x0 = 1e15 + 0.125 * double(rng() % 64);
            c.aligned = {{x0, -1, -1}, {x0 + 0.125 * double(1 + rng() % 8), 1, 1}};
            c.cylinder.radius = std::ldexp(1.0, -integer(rng, 4, 20));
            c.cylinder.height = 1;
            c.cylinder.axis = {0, 0, 1};
            c.cylinder.center = {c.aligned.max[0] + c.cylinder.radius, 0.5 * unit(rng), 0};
            break;
        }
    }
    nudge(c, rng, integer(rng, -2, 2));
    return c;
}

}  // namespace boxcyl::testing
