// Exact decisions in plain double for inputs of few bits. First, a cylinder whose axis lies along a
// coordinate axis beside an aligned or canonical box (a drill hole, a voxel, a tool along z): both are
// products of an interval along that axis and a plane shape across it, so they meet exactly when the
// intervals overlap and the box's cross-section rectangle comes within r of the axis — a complete
// decision, hits and misses alike (decide_along_an_axis). Then one point tested exactly in plain double:
// whether a point of doubles lies in the closed cylinder,
// decided without rounding where the inputs are integers of few bits times one power of two (voxels,
// integer and binary-fraction coordinates). There every operation of the test is exact, in every
// rounding mode, so a point ON the surface is decided too — the case of shapes that touch exactly,
// where no error-bounded certificate can decide and the exact stage costs about a µs.
//
// Why exact: first v = p − C, exact where p and C together span at most 52 bits (each difference is
// then an integer below 2^53 in their common unit), so far from the origin only the offsets count.
// Then the lengths v, r, h are integers below 2^L times 2^e, the axis components integers below 2^A
// times 2^f, and with a the axis as given the test is
//     (2 a·v)² ≤ h²|a|²   and   |a|²|v|² − (a·v)² ≤ r²|a|²,
// whose every intermediate value is an integer multiple of 2^(2e+2f) (or of a coarser power) below
// 2^(2A+2L+6) of that unit: |a·v| < 3·2^(A+L), (2a·v)² < 36·2^(2A+2L), |a|²|v|² < 9·2^(2A+2L). With
// A + L ≤ 22 that is below 2^53 units, and such a value is a double, so no operation rounds; the
// exponents are kept where no product's unit is below 2^-1074 and none overflows (in_range).
#pragma once

#include <algorithm>  // std::min, std::max
#include <bit>        // std::bit_cast, std::bit_width
#include <climits>    // INT_MAX
#include <cmath>      // std::sqrt
#include <cstdint>    // std::int64_t
#include <optional>   // not decided
#include <type_traits>  // std::is_same_v

#include "boxcyl/exact/integer_inequalities.hpp"  // dyadic
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl::exact {

namespace point_detail {

// The binary span of a set of doubles: the smallest exponent of their odd integer forms (m·2^e) and the
// top of the largest magnitude; zeros are left out.
struct Span {
    int low = INT_MAX;
    int top = INT_MIN;
    void add(double x) {
        const integer::Dyadic d = integer::dyadic(x);
        if (d.m == 0) return;
        const auto mag = static_cast<std::uint64_t>(d.m < 0 ? -d.m : d.m);
        low = std::min(low, d.e);
        top = std::max(top, d.e + static_cast<int>(std::bit_width(mag)));
    }
    bool empty() const { return low == INT_MAX; }
    int bits() const { return empty() ? 0 : top - low; }
};

inline constexpr int kMaxBits = 22;  // A + L: every value of the test below 2^53 of its unit

// Every product the test forms — of two lengths (< 2^(2·top+4)), two axis components (< 2^(2·top+2)),
// one of each, and four — with its unit (2^(2·low) and so on) not below 2^-1074 and its bound not above
// 2^1023: with a tiny axis beside large lengths, |a|² may underflow while |v|² overflows.
inline bool in_range(const Span& lengths, const Span& axis) {
    const int tl = lengths.top, ta = axis.top, ll = lengths.low, la = axis.low;
    return 2 * tl + 4 <= 1023 && 2 * ta + 2 <= 1023 && tl + ta + 2 <= 1023 && 2 * tl + 2 * ta + 6 <= 1023 &&
           2 * ll >= -1074 && 2 * la >= -1074 && ll + la >= -1074 && 2 * ll + 2 * la >= -1074;
}

// 2^k as a double, for |k| ≤ 1000 (normal).
inline double power_of_two(int k) { return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52); }

// A double in [lo, hi] (lo ≤ hi, doubles) near y, of no finer grain than lo and hi: y rounded toward
// zero to a multiple of their grain 2^g (lo and hi are such multiples, so the result stays between
// them), or the nearer end where y is not strictly inside. Any value in [lo, hi] would be a box point;
// this one keeps the test's operands short.
inline double snap(double y, double lo, double hi) {
    if (!(y > lo)) return lo;  // NaN too
    if (!(y < hi)) return hi;
    const integer::Dyadic a = integer::dyadic(lo), b = integer::dyadic(hi);
    const int g = a.m == 0 ? b.e : b.m == 0 ? a.e : std::min(a.e, b.e);
    point_detail::Span ends;
    ends.add(lo), ends.add(hi);
    // |y|·2^-g < 2^(top − g): an integer that fits (and is exact) while top − g ≤ 53.
    if (g < -1000 || g > 1000 || ends.top - g > 53) return lo;
    const double scaled = y * power_of_two(-g);
    return static_cast<double>(static_cast<std::int64_t>(scaled)) * power_of_two(g);
}

// An aligned or canonical box's bounds; nullopt for a turned box.
struct Bounds {
    Vec3<double> lo, hi;
};
template <class Box>
std::optional<Bounds> bounds_of(const Box& b) {
    if constexpr (std::is_same_v<Box, AlignedBox<double>>) return Bounds{b.min, b.max};
    else if constexpr (std::is_same_v<Box, CanonicalBox<double>>) return Bounds{-b.extents, b.extents};
    else return std::nullopt;
}

}  // namespace point_detail

// Whether p lies in the closed cylinder c, when the operands' spans make the test exact (see the top);
// nullopt otherwise. Exact in every rounding mode, contraction into FMAs included (an exact product
// stays exact inside one).
inline std::optional<bool> inside_exactly(const Vec3<double>& p, const Cylinder<double>& c) {
    using point_detail::Span;
    Span ends, lengths, axis;
    for (int i = 0; i < 3; ++i) ends.add(p[i]), ends.add(c.center[i]);
    if (ends.bits() > 52) return std::nullopt;
    const Vec3<double> v = p - c.center;  // exact (see the top)
    for (int i = 0; i < 3; ++i) lengths.add(v[i]), axis.add(c.axis[i]);
    lengths.add(c.radius), lengths.add(c.height);
    if (axis.empty() || lengths.bits() + axis.bits() > point_detail::kMaxBits) return std::nullopt;
    if (!lengths.empty() && !point_detail::in_range(lengths, axis)) return std::nullopt;
    const Vec3<double>& a = c.axis;
    const double av = a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
    const double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    const double twice = 2 * av;
    return twice * twice <= (c.height * c.height) * aa && aa * vv - av * av <= (c.radius * c.radius) * aa;
}

// An exact hit from one box point (aligned and canonical boxes, whose points of doubles are exactly box
// points): the axis point nearest the box's centre (clamped to the segment), moved into the box and
// snapped to the grain of its bounds. On shapes that touch exactly on a cap, a side or a rim (a voxel
// beside the cylinder) that point is a touching point. False: not proved (never a miss).
template <class Box>
bool hit_at_a_point(const Box& b, const Cylinder<double>& c) {
    const std::optional<point_detail::Bounds> bounds = point_detail::bounds_of(b);
    if (!bounds) return false;  // a turned box's points are not doubles
    const auto& [lo, hi] = *bounds;
    const Vec3<double> mid{0.5 * lo[0] + 0.5 * hi[0], 0.5 * lo[1] + 0.5 * hi[1], 0.5 * lo[2] + 0.5 * hi[2]};
    const double aa = dot(c.axis, c.axis);
    const double half = 0.5 * c.height / std::sqrt(aa);
    double s = dot(c.axis, mid - c.center) / aa;
    s = s > half ? half : s < -half ? -half : s == s ? s : 0.0;
    Vec3<double> p;
    for (int i = 0; i < 3; ++i) p[i] = point_detail::snap(c.center[i] + s * c.axis[i], lo[i], hi[i]);
    const std::optional<bool> in = inside_exactly(p, c);
    return in && *in;
}

// The decision for an aligned or canonical box and a cylinder whose axis has one nonzero component z:
// they meet iff [lo_z, hi_z] meets [C_z − h/2, C_z + h/2] and the rectangle's point nearest the axis,
// q = clamp(C, lo, hi) − C across z, has |q|² ≤ r². Exact where, on each coordinate, lo, hi and C span at
// most 52 bits (the differences d = lo − C, hi − C are then doubles: integers below 2^53 in their unit),
// the doubling 2d is exact (|d| below 2^1021), and q and r together span at most 25 bits, so that
// q_x² + q_y² and r² are integers below 2^52 in the square of their unit (kept above 2^-1074 and below
// 2^1023). nullopt otherwise (another axis, another box kind, operands too wide).
template <class Box>
std::optional<bool> decide_along_an_axis(const Box& b, const Cylinder<double>& c) {
    const std::optional<point_detail::Bounds> bounds = point_detail::bounds_of(b);
    if (!bounds) return std::nullopt;  // a turned box is no product along the axis
    const auto& [lo, hi] = *bounds;
    int z = -1;
    for (int i = 0; i < 3; ++i)
        if (c.axis[i] != 0) {
            if (z >= 0) return std::nullopt;
            z = i;
        }
    if (z < 0) return std::nullopt;
    using point_detail::Span;
    Vec3<double> dlo, dhi;
    for (int i = 0; i < 3; ++i) {
        Span s;
        s.add(lo[i]), s.add(hi[i]), s.add(c.center[i]);
        if (s.bits() > 52 || s.top > 1020 || (!s.empty() && s.low < -1074)) return std::nullopt;
        dlo[i] = lo[i] - c.center[i], dhi[i] = hi[i] - c.center[i];
    }
    if (!(2 * dlo[z] <= c.height && 2 * dhi[z] >= -c.height)) return false;  // apart along the axis
    Span across;
    double q[2];
    int n = 0;
    for (int i = 0; i < 3; ++i)
        if (i != z) {
            q[n] = dlo[i] > 0 ? dlo[i] : dhi[i] < 0 ? dhi[i] : 0.0;
            across.add(q[n++]);
        }
    across.add(c.radius);
    if (across.empty()) return true;  // q = 0 and r = 0: the axis passes through the box
    if (across.bits() > 25 || 2 * across.top + 2 > 1023 || 2 * across.low < -1074) return std::nullopt;
    return q[0] * q[0] + q[1] * q[1] <= c.radius * c.radius;
}

}  // namespace boxcyl::exact
