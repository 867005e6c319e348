// Exactly touching queries, built so that no finite-precision filter can decide them: integer (or
// binary-fraction) coordinates, and a cylinder that touches the box exactly — its side tangent to a
// face, an edge or a vertex, a cap or a disk flush with a face, a rim through a vertex, a segment
// (r = 0) or a disk (h = 0) ending on a face, flat boxes — with axes along a box axis, oblique with a
// rational unit vector ((3,4,0), (1,2,2), (2,3,6)) or an irrational one ((1,1,0), (1,1,1), (1,2,3)).
// Every case is then scaled by a random power of two and moved by a binary fraction (both exact), and
// given as an aligned box, a canonical box or an oriented box with a signed-permutation frame; a
// share are oriented boxes turned about one axis by a rotation rounded to double (their frame is
// orthonormal only up to rounding) with a cap flush with a face. The answers are the oracle's.
#pragma once

#include <array>    // frames
#include <cmath>    // std::ldexp, std::cos, std::sin
#include <cstdint>  // seeds
#include <random>   // std::mt19937_64

#include "support/cases.hpp"

namespace boxcyl::testing {

class TouchingGenerator {
public:
    explicit TouchingGenerator(std::uint64_t seed) : rng_(seed) {}

    Case next() {
        Case c;
        // A box [lo, hi] with integer corners in [−8, 8] (some sides zero-width).
        Vec3<double> lo, hi;
        for (int i = 0; i < 3; ++i) {
            lo[i] = static_cast<double>(pick(-8, 4));
            hi[i] = lo[i] + (pick(0, 9) == 0 ? 0.0 : static_cast<double>(pick(1, 6)));
        }
        Cylinder<double>& cyl = c.cylinder;
        const int kind = pick(0, 9);
        const int i = pick(0, 2), j = (i + 1) % 3, k = (i + 2) % 3;
        const double side = pick(0, 1) ? 1.0 : -1.0;
        const double face = side > 0 ? hi[i] : lo[i];  // the touched face x_i = face, outer normal side·e_i
        auto inside = [&](int n) { return lo[n] + (hi[n] - lo[n]) * static_cast<double>(pick(0, 4)) / 4.0; };
        switch (kind) {
            case 0: {  // a cap (or a disk, h = 0) flush with a face: axis ∥ e_i
                cyl.axis = unit(i, side * static_cast<double>(pick(1, 3)));
                cyl.radius = static_cast<double>(pick(0, 3));
                cyl.height = 2.0 * static_cast<double>(pick(0, 3));
                cyl.center[i] = face + side * cyl.height / 2;
                cyl.center[j] = inside(j) + static_cast<double>(pick(-2, 2));
                cyl.center[k] = inside(k) + static_cast<double>(pick(-2, 2));
                break;
            }
            case 1: {  // the side tangent to a face: axis ⊥ e_i, oblique in the face's plane
                static constexpr std::array<std::array<double, 2>, 5> dirs{{{1, 0}, {3, 4}, {1, 1}, {4, -3}, {1, 2}}};
                const auto& dv = dirs[static_cast<std::size_t>(pick(0, 4))];
                cyl.axis = {};
                cyl.axis[j] = dv[0];
                cyl.axis[k] = dv[1];
                cyl.radius = static_cast<double>(pick(0, 3));
                cyl.height = static_cast<double>(pick(0, 8));
                cyl.center[i] = face + side * cyl.radius;
                cyl.center[j] = inside(j);
                cyl.center[k] = inside(k);
                break;
            }
            case 2: {  // the side through a box edge ∥ e_k: axis ∥ e_k, centre (3,4)·s from the edge, r = 5s
                const double s = static_cast<double>(pick(1, 2));
                const double sj = pick(0, 1) ? 1.0 : -1.0;
                cyl.axis = unit(k, 1.0);
                cyl.radius = 5 * s;
                cyl.height = static_cast<double>(pick(0, 6));
                cyl.center[i] = face + side * 3 * s;
                cyl.center[j] = (sj > 0 ? hi[j] : lo[j]) + sj * 4 * s;
                cyl.center[k] = inside(k);
                break;
            }
            case 3: {  // a rim or a cap through a box vertex: axis ∥ e_i, vertex on the cap plane
                const double sj = pick(0, 1) ? 1.0 : -1.0, sk = pick(0, 1) ? 1.0 : -1.0;
                const bool rim = pick(0, 1) != 0;
                cyl.axis = unit(i, -side);
                cyl.radius = rim ? 5.0 : 2.0;
                cyl.height = 2.0 * static_cast<double>(pick(0, 3));
                cyl.center[i] = face + side * cyl.height / 2;
                cyl.center[j] = (sj > 0 ? hi[j] : lo[j]) + sj * (rim ? 3.0 : 1.0);
                cyl.center[k] = (sk > 0 ? hi[k] : lo[k]) + sk * (rim ? 4.0 : 1.0);
                break;
            }
            case 4: {  // a segment (r = 0) or a thin cylinder whose end lies on a face, oblique axis
                static constexpr std::array<std::array<double, 3>, 4> dirs{{{2, 1, 2}, {6, 3, 2}, {1, 1, 1}, {3, 1, 2}}};
                const auto& dv = dirs[static_cast<std::size_t>(pick(0, 3))];
                Vec3<double> a{};
                a[i] = side * dv[0], a[j] = dv[1], a[k] = dv[2];
                cyl.axis = a;
                cyl.radius = 0.0;
                // End point on the face at an inside point; the segment leaves the box outward. With a
                // rational unit axis ((2,1,2)/3, (6,3,2)/7) its centre is exact: centre = end + (h/2)·u.
                const double n = dv[0] == 2 ? 3 : dv[0] == 6 ? 7 : 0;
                Vec3<double> end{};
                end[i] = face, end[j] = inside(j), end[k] = inside(k);
                if (n != 0) {
                    const double m = static_cast<double>(pick(1, 3));
                    cyl.height = 2 * n * m;
                    for (int q = 0; q < 3; ++q) cyl.center[q] = end[q] + m * a[q];
                } else {  // irrational |D|: a zero-height segment (a point) on the face
                    cyl.height = 0.0;
                    cyl.center = end;
                }
                break;
            }
            case 5: {  // the side tangent to a box edge, axis (1,1,0)-like in the plane ⊥ e_k: offset (2,−2,1)·s, r = 3s
                const double s = static_cast<double>(pick(1, 2));
                Vec3<double> a{};
                a[i] = 1, a[j] = 1;
                cyl.axis = a;
                cyl.radius = 3 * s;
                cyl.height = static_cast<double>(pick(0, 6));
                // The box vertex V = (hi_i, lo_j, hi_k); centre = V + (−2, 2, 1)·s... lies at distance 3s
                // from V, perpendicular to the axis: (−2,2,1)·(1,1,0) = 0.
                Vec3<double> v{};
                v[i] = hi[i], v[j] = lo[j], v[k] = hi[k];
                cyl.center = v;
                cyl.center[i] += 2 * s, cyl.center[j] -= 2 * s, cyl.center[k] += s;
                break;
            }
            case 6: {  // a disk (h = 0) in a face's plane, overlapping or touching the face's edge
                cyl.axis = unit(i, static_cast<double>(pick(1, 2)));
                cyl.height = 0.0;
                cyl.radius = static_cast<double>(pick(0, 3));
                cyl.center[i] = face;
                cyl.center[j] = hi[j] + cyl.radius;
                cyl.center[k] = inside(k);
                break;
            }
            case 7: {  // a cap plane through a box vertex, oblique rational axis (2,3,6)/7: D·(V − C) = (h/2)·7
                Vec3<double> a{};
                a[i] = 2, a[j] = 3, a[k] = 6;
                cyl.axis = a;
                cyl.radius = static_cast<double>(pick(0, 4));
                const double m = static_cast<double>(pick(1, 2));
                cyl.height = 2 * 7 * m;
                Vec3<double> v{};  // the vertex least along a
                v[i] = lo[i], v[j] = lo[j], v[k] = lo[k];
                for (int q = 0; q < 3; ++q) cyl.center[q] = v[q] - m * a[q];
                break;
            }
            default: {  // the side tangent to a face, axis ∥ a box axis
                cyl.axis = unit(j, 1.0);
                cyl.radius = static_cast<double>(pick(1, 3));
                cyl.height = static_cast<double>(pick(0, 8));
                cyl.center[i] = face + side * cyl.radius;
                cyl.center[j] = inside(j);
                cyl.center[k] = inside(k);
                break;
            }
        }
        // Exact changes of the whole scene: a power-of-two scale and a binary-fraction shift.
        const int e = pick(-20, 20);
        const double shift = std::ldexp(static_cast<double>(pick(-64, 64)), pick(-4, 4));
        auto place = [&](double x) { return std::ldexp(x, e) + std::ldexp(shift, e); };
        auto size = [&](double x) { return std::ldexp(x, e); };
        for (int n = 0; n < 3; ++n) lo[n] = place(lo[n]), hi[n] = place(hi[n]), cyl.center[n] = place(cyl.center[n]);
        cyl.radius = size(cyl.radius), cyl.height = size(cyl.height);
        const int ea = pick(-3, 3);  // the axis' length does not matter
        for (int n = 0; n < 3; ++n) cyl.axis[n] = std::ldexp(cyl.axis[n], ea);
        return finish(c, lo, hi, kind == 0 ? i : -1);
    }

private:
    int pick(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
    static Vec3<double> unit(int i, double v) {
        Vec3<double> a{};
        a[i] = v;
        return a;
    }
    // The box as an aligned, canonical or signed-permutation oriented box — or, for a cap flush with
    // the face x_i (turn ≥ 0), an oriented box turned about e_i by a rounded rotation (A_i = e_i
    // exactly, so the face planes x_i = K_i ± e_i stay exact and the cap stays flush).
    Case finish(Case c, const Vec3<double>& lo, const Vec3<double>& hi, int turn) {
        Vec3<double> mid, ext;
        for (int n = 0; n < 3; ++n) mid[n] = (lo[n] + hi[n]) / 2, ext[n] = (hi[n] - lo[n]) / 2;
        const int how = pick(0, 9);
        if (how < 4 || (how >= 8 && turn < 0)) {
            c.kind = BoxKind::aligned;
            c.aligned = {lo, hi};
        } else if (how < 6) {
            c.kind = BoxKind::canonical;
            c.canonical.extents = ext;
            for (int n = 0; n < 3; ++n) c.cylinder.center[n] -= mid[n];  // exact: binary fractions
        } else if (how < 8) {
            c.kind = BoxKind::oriented;
            c.oriented.axes = random_signed_permutation(rng_);
            c.oriented.center = mid;
            for (int m = 0; m < 3; ++m)
                for (int n = 0; n < 3; ++n)
                    if (c.oriented.axes[m][n] != 0) c.oriented.extents[m] = ext[n];
        } else {
            c.kind = BoxKind::oriented;
            const int j = (turn + 1) % 3, k = (turn + 2) % 3;
            const double angle = std::uniform_real_distribution<double>(0.1, 1.4)(rng_);
            const double cs = std::cos(angle), sn = std::sin(angle);
            std::array<Vec3<double>, 3> axes{};
            axes[static_cast<std::size_t>(turn)][turn] = 1;
            axes[static_cast<std::size_t>(j)][j] = cs, axes[static_cast<std::size_t>(j)][k] = sn;
            axes[static_cast<std::size_t>(k)][j] = -sn, axes[static_cast<std::size_t>(k)][k] = cs;
            c.oriented.axes = axes;
            c.oriented.center = mid;
            c.oriented.extents = ext;
            // The cap's centre over the box centre, moved within the face.
            c.cylinder.center[j] = mid[j] + ext[j] * 0.25;
            c.cylinder.center[k] = mid[k] - ext[k] * 0.25;
        }
        return c;
    }

    std::mt19937_64 rng_;
};

}  // namespace boxcyl::testing
