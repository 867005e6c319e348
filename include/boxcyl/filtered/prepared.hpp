// The prepared query: what every row of the pipeline (filtered/schedule.hpp) needs to know about one
// box and one cylinder, computed once. Stage 0's problem is computed at once (nearly every query ends
// there); the facts of the later rows on first use (facts()), and the speed hints (near touching,
// narrow inputs) each on first use, since a query that stage 0 decides must not pay for them.
//
// Queries beyond stage 0's range of scales (a length above 2^200 or all below 2^-200) are first
// scaled by a power of two to about 1 when that is exact for every length: the same question, whose
// answer is the same, and then the cheap rows apply.
#pragma once

#include <algorithm>  // std::max
#include <array>      // a translation
#include <bit>        // std::bit_cast: powers of two
#include <cmath>      // std::fabs, std::ilogb
#include <cstdint>    // std::uint64_t, std::int8_t
#include <limits>     // infinity
#include <optional>   // the frame's signed permutation
#include <type_traits>  // std::is_same_v
#include <utility>      // std::pair

#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/filtered/semi_static.hpp"
#include "boxcyl/filtered/witness_search.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/number/double_double.hpp"  // round_to_nearest

namespace boxcyl::filtered {

// ---- Lengths and scales ----

// f(x) for every length of a box kind or a cylinder (by reference: f may scale it); not the axes,
// which carry no length.
template <class F>
void for_each_length(AlignedBox<double>& b, F&& f) {
    for (int i = 0; i < 3; ++i) f(b.min[i]), f(b.max[i]);
}
template <class F>
void for_each_length(CanonicalBox<double>& b, F&& f) {
    for (int i = 0; i < 3; ++i) f(b.extents[i]);
}
template <class Box, class F>  // OrientedBox, Parallelepiped
void for_each_length(Box& b, F&& f) {
    for (int i = 0; i < 3; ++i) f(b.center[i]), f(b.extents[i]);
}
template <class F>
void for_each_length(Cylinder<double>& c, F&& f) {
    for (int i = 0; i < 3; ++i) f(c.center[i]);
    f(c.radius), f(c.height);
}
// The largest length of a query: every box length, the cylinder's centre, radius and height.
template <class Box>
double largest_length(Box b, Cylinder<double> c) {
    double m = 0;
    auto update = [&m](double& x) { m = std::max(m, std::fabs(x)); };
    for_each_length(b, update);
    for_each_length(c, update);
    return m;
}
inline void update_max(double& m, const Vec3<double>& v) {
    for (int i = 0; i < 3; ++i) m = std::max(m, std::fabs(v[i]));
}

// x·2^k rounded as any product is (so exact unless it leaves the normal range), for |k| ≤ 2044: by
// one or two products with normal powers of two, not a libm call (std::ldexp was two fifths of the
// time of random queries at extreme scales).
inline double times_two_to(double x, int k) {
    auto power = [](int e) { return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52); };
    if (k >= -1022 && k <= 1023) return x * power(k);
    const int half = k / 2;
    return x * power(half) * power(k - half);
}

// The query with every length times 2^k, k bringing the largest to [1, 2), when that is exact for
// every length: scaled back, a value comes back exactly only when its scaling rounded nothing (the way
// back only grows values, or shrinks them again by what they grew), in every rounding mode alike.
template <class Box>
bool rescaled_exactly(Box& box, Cylinder<double>& cyl, double m) {
    if (!(m > 0) || !(m < std::numeric_limits<double>::infinity())) return false;
    const int k = -std::ilogb(m);
    bool exact = true;
    auto scale = [k, &exact](double& x) {
        const double y = times_two_to(x, k);
        exact &= times_two_to(y, -k) == x;
        x = y;
    };
    Box b = box;
    Cylinder<double> c = cyl;
    for_each_length(b, scale);
    for_each_length(c, scale);
    if (!exact) return false;
    box = b, cyl = c;
    return true;
}

// ---- Positions far from the origin ----

// The exponent of x's lowest set bit: x ≠ 0 is an integer multiple of 2^that (INT_MAX for 0).
inline int granularity(double x) {
    if (x == 0) return std::numeric_limits<int>::max();
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
    const std::uint64_t mantissa = (bits & ((std::uint64_t{1} << 52) - 1)) | (biased != 0 ? std::uint64_t{1} << 52 : 0);
    return (biased != 0 ? biased : 1) - 1075 + std::countr_zero(mantissa);
}
// The positions of a query (box corners or centre, the cylinder's centre) on one axis.
template <class F>
void for_each_position(AlignedBox<double>& b, Cylinder<double>& c, int i, F&& f) {
    f(b.min[i]), f(b.max[i]), f(c.center[i]);
}
template <class Box, class F>  // OrientedBox, Parallelepiped
void for_each_position(Box& b, Cylinder<double>& c, int i, F&& f) {
    f(b.center[i]), f(c.center[i]);
}
// translated_exactly's common case, in one pass without branches (the axes computed together): every
// position within a factor 2 of the box's first one (Sterbenz's lemma; the test is translated_exactly's).
inline bool moved_within_a_factor_2(AlignedBox<double>& b, Cylinder<double>& c) {
    Vec3<double> hi, centre;
    int ok = 1;
    for (int i = 0; i < 3; ++i) {
        const double t = b.min[i], at = std::fabs(t);
        hi[i] = b.max[i] - t;
        centre[i] = c.center[i] - t;
        ok &= static_cast<int>(std::fabs(hi[i]) < std::min(std::fabs(b.max[i]), at)) &
              static_cast<int>(std::fabs(centre[i]) < std::min(std::fabs(c.center[i]), at));
    }
    if (!ok) return false;
    b.min = {0, 0, 0}, b.max = hi, c.center = centre;
    return true;
}
template <class Box>  // OrientedBox, Parallelepiped
bool moved_within_a_factor_2(Box& b, Cylinder<double>& c) {
    Vec3<double> centre;
    int ok = 1;
    for (int i = 0; i < 3; ++i) {
        centre[i] = c.center[i] - b.center[i];
        ok &= std::fabs(centre[i]) < std::min(std::fabs(c.center[i]), std::fabs(b.center[i]));
    }
    if (!ok) return false;
    b.center = {0, 0, 0}, c.center = centre;
    return true;
}
// The same question with every position moved by −t on each axis (t: the box's first position there),
// when every difference is exact: shapes small and far from the origin (a block model in UTM
// coordinates, a part in machine coordinates) then get error bounds of their own size. x and t are
// integer multiples of 2^g (g: the least granularity of the axis' values), so x − t is, and it is a
// double exactly when |x − t| < 2^(g+53): rounding is monotone and 2^(g+53) a double, so the computed
// difference tells, in every rounding mode.
template <class Box>
bool translated_exactly(Box& box, Cylinder<double>& cyl) {
    if (moved_within_a_factor_2(box, cyl)) return true;
    std::array<double, 3> t{};
    for (int i = 0; i < 3; ++i) {
        bool first = true, sterbenz = true;
        for_each_position(box, cyl, i, [&](double& x) {
            if (first) t[i] = x, first = false;
            // Sterbenz's lemma: x − t is exact when x and t have one sign and lie within a factor 2 of
            // each other (positions close together far from the origin: nearly always), which is when
            // |x − t| < min(|x|, |t|). Computed, the test is sound in every rounding mode: rounding is
            // monotone and ±min a double, so a computed |x − t| below min means an exact one below it.
            sterbenz &= std::fabs(x - t[i]) < std::min(std::fabs(x), std::fabs(t[i]));
        });
        if (t[i] == 0 || sterbenz) continue;  // nothing to move, or exact
        int g = std::numeric_limits<int>::max();
        for_each_position(box, cyl, i, [&](double& x) { g = std::min(g, granularity(x)); });
        // 2^(g+53), built from its bits (g ≥ −1074 makes it normal), +∞ beyond the double range.
        const double limit = g + 53 >= 1024 ? std::numeric_limits<double>::infinity()
                                            : std::bit_cast<double>(static_cast<std::uint64_t>(g + 53 + 1023) << 52);
        bool exact = true;
        for_each_position(box, cyl, i, [&](double& x) { exact &= std::fabs(x - t[i]) < limit; });
        if (!exact) return false;
    }
    for (int i = 0; i < 3; ++i)
        if (t[i] != 0) for_each_position(box, cyl, i, [&](double& x) { x -= t[i]; });
    return true;
}

// Stage 1's exponent: lengths times 2^k bring the largest m to [1, 2) when m is beyond 2^±200 (the
// linear-inequalities method forms products of up to four lengths), else k = 0.
inline int scale_exponent(double m) {
    if (!(m > 0) || !(m < std::numeric_limits<double>::infinity())) return 0;
    const int e = std::ilogb(m);
    return (e < -200 || e > 200) ? -e : 0;
}

// The cylinder axis with its non-zero components below 2^exponent of the largest set to 0; false when
// there is none. Such components are exact in the input but lost in any enclosure of the unit axis.
inline bool tiny_components_zeroed(const Vec3<double>& a, Vec3<double>& zeroed, int exponent) {
    double m = 0;
    update_max(m, a);
    const double limit = std::ldexp(m, exponent);
    bool any = false;
    zeroed = a;
    for (int i = 0; i < 3; ++i)
        if (a[i] != 0 && std::fabs(a[i]) <= limit) zeroed[i] = 0, any = true;
    return any;
}

// ---- The box kinds' frames ----

template <class Box>
inline constexpr bool is_oriented = std::is_same_v<Box, OrientedBox<double>>;

// Whether a size is 0: a flat box, a disk or a segment (their hits have no interior point to certify).
inline bool has_zero_size(const AlignedBox<double>& b, const Cylinder<double>& c) {
    return b.min[0] == b.max[0] || b.min[1] == b.max[1] || b.min[2] == b.max[2] || c.radius == 0 || c.height == 0;
}
template <class Box>
bool has_zero_size(const Box& b, const Cylinder<double>& c) {
    return b.extents[0] == 0 || b.extents[1] == 0 || b.extents[2] == 0 || c.radius == 0 || c.height == 0;
}

// ---- Speed hints: they choose the order of rows, never an answer. ----

// The plain-double linear-inequalities answer: wrong near touching, a hint only.
template <class Box>
bool plain_answer(const Box& box, const Cylinder<double>& cyl) {
    const CanonicalQuery<double> q = to_canonical(box, to_unit(cyl));
    return algo::linear_inequalities(q.box, q.cylinder);
}

// Whether the plain-double linear-inequalities answer changes between the cylinder grown and shrunk by
// 2^-30 of the query's scale m (radius and half-height ± δ). It catches the contacts whose gap no single
// separating axis or axis distance shows (a cap's rim on a box edge, a side on a vertex).
template <class Box>
bool answer_moves(const Box& box, const Cylinder<double>& cyl, double m) {
    const double delta = 0x1p-30 * m;
    if (!(delta > 0) || !(m < std::numeric_limits<double>::max() / 4)) return true;
    const CanonicalQuery<double> q = to_canonical(box, to_unit(cyl));
    CanonicalQuery<double> grown = q, shrunk = q;
    grown.cylinder.radius += delta;
    grown.cylinder.half_height += delta;
    shrunk.cylinder.radius = std::max(0.0, q.cylinder.radius - delta);
    shrunk.cylinder.half_height = std::max(0.0, q.cylinder.half_height - delta);
    return algo::linear_inequalities(grown.box, grown.cylinder) != algo::linear_inequalities(shrunk.box, shrunk.cylinder);
}

// ---- The prepared query ----

// A fact computed on first use: slot is −1 until then, else 0 or 1.
template <class F>
bool memo(std::int8_t& slot, F&& compute) {
    if (slot < 0) slot = compute() ? 1 : 0;
    return slot != 0;
}

template <class Box>
class Prepared {
public:
    using box_type = Box;
    // The facts of the later rows (computed together on first use).
    struct Facts {
        double scale;     // the largest length
        int k;            // stage 1's exponent (scale_exponent)
        bool flat;        // a zero size (has_zero_size)
        bool two_scale_axis;  // an axis component below 2^-200 of the largest (and non-zero)
        std::optional<SignedPermutation> frame;  // an oriented box's frame, when a signed permutation
        bool turned;      // an oriented box whose frame is not a signed permutation
    };

    // The query is not copied (the rows read the caller's box and cylinder), unless it is moved or
    // rescaled. A query far from the origin for its size is moved near it, exactly where that can be
    // (told from the input as given, so that stage 0's problem is computed once); one beyond stage 0's
    // range of scales is scaled to about 1, exactly where that can be.
    // Off that direct path, `before_preparing()` is asked first (the pipeline's rows on the query as
    // given): when it decides, its answer is `early` and nothing more is prepared.
    template <class BeforePreparing>
    BOXCYL_FORCE_INLINE Prepared(const Box& b, const Cylinder<double>& c, BeforePreparing&& before_preparing)
        : in_range(near_origin(b, c, p, far_)),
          early(in_range ? std::nullopt : before_preparing()),
          scaled_(in_range || early ? std::nullopt : prepare(b, c, p, far_, in_range, rescaled_)),
          box(scaled_ ? scaled_->first : b),
          cyl(scaled_ ? scaled_->second : c) {}
    BOXCYL_FORCE_INLINE Prepared(const Box& b, const Cylinder<double>& c)
        : Prepared(b, c, [] { return std::optional<bool>{}; }) {}
    Prepared(const Prepared&) = delete;
    Prepared& operator=(const Prepared&) = delete;

    semi_static::Problem p;  // stage 0's problem; valid when in_range
private:
    bool far_ = false;       // the query as given looks far from the origin (looks_far; before in_range: set by it)
public:
    bool in_range;           // within stage 0's range of scales
    std::optional<bool> early;  // the answer of before_preparing(), off the direct path

private:
    // Stage 0's scale L (twice the largest length) more than 2^6 times the largest size (a half extent,
    // the radius, the half height): its error bounds would be those of the positions, not of the shapes.
    static bool far_from_origin(double l, double size) { return l > 0x1p7 * size; }
    static bool far_from_origin(const semi_static::Problem& q) {
        return far_from_origin(q.l, std::max(std::max(std::max(q.e[0], q.e[1]), std::max(q.e[2], q.r)), q.h));
    }
    // The same test on the input as given (L and the sizes as the problem computes them, less rounding).
    static bool looks_far(const AlignedBox<double>& b, const Cylinder<double>& c) {
        double position = 0, size = std::max(c.radius, c.height * 0.5);
        update_max(position, b.min), update_max(position, b.max), update_max(position, c.center);
        for (int i = 0; i < 3; ++i) size = std::max(size, b.max[i] * 0.5 - b.min[i] * 0.5);
        return far_from_origin(2 * std::max(std::max(position, c.radius), c.height), size);
    }
    static bool looks_far(const OrientedBox<double>& b, const Cylinder<double>& c) {
        double position = 0, size = std::max(c.radius, c.height * 0.5);
        update_max(position, b.center), update_max(position, c.center);
        update_max(size, b.extents);
        return far_from_origin(2 * std::max(std::max(position, c.radius), c.height), size);
    }

    static constexpr bool movable = !std::is_same_v<Box, CanonicalBox<double>>;  // (a canonical box is at the origin)


    // Nearly every query: in stage 0's range and near the origin for its size, taken as given. Kept
    // inline (prepare() below is not), since it is most of stage 0's path.
    BOXCYL_FORCE_INLINE static bool near_origin(const Box& b, const Cylinder<double>& c, semi_static::Problem& p,
                                                bool& far) {
        if constexpr (movable) {
            far = looks_far(b, c);
            if (far) return false;
        }
        return semi_static::problem(b, c, p) && !far_from_origin(p);
    }

    // Stage 0's problem for the query as the rows will see it (in_range: whether it has one), and that
    // query when it is not the caller's: moved where it looks far from the origin (`far`, as
    // near_origin found), else as given, and then moved or rescaled where its problem says so.
    // One object returned on every path (no copy of it on the way out).
    static std::optional<std::pair<Box, Cylinder<double>>> prepare(const Box& b, const Cylinder<double>& c,
                                                                   semi_static::Problem& p, bool far, bool& in_range,
                                                                   bool& rescaled) {
        std::optional<std::pair<Box, Cylinder<double>>> s;
        if constexpr (movable) {
            if (far) {
                s.emplace(b, c);
                // Moved whenever the query as given is in range, even where the moved one is not (the
                // later rows are better conditioned near the origin); out of range both ways, rescaled.
                if (translated_exactly(s->first, s->second)) {
                    const bool moved_in_range = semi_static::problem(s->first, s->second, p);
                    if (moved_in_range || semi_static::problem(b, c, p)) {
                        in_range = moved_in_range;
                        return s;
                    }
                }
                s.reset();
            }
        }
        in_range = semi_static::problem(b, c, p);
        if (in_range && (far || !far_from_origin(p))) return s;  // as given (far: moving it failed above)
        s.emplace(b, c);
        bool exact = false;
        if (!in_range) exact = rescaled_exactly(s->first, s->second, largest_length(b, c));
        else if constexpr (movable) exact = translated_exactly(s->first, s->second);
        if (!exact) {
            s.reset();
            return s;
        }
        rescaled = !in_range;
        in_range = semi_static::problem(s->first, s->second, p);
        return s;
    }
    bool rescaled_ = false;  // (before scaled_: prepare() sets it)
    std::optional<std::pair<Box, Cylinder<double>>> scaled_;

public:
    // Whether the lengths were scaled by a power of two (not only moved): the sizes in p are then not
    // the cylinder's as given.
    bool rescaled() const { return rescaled_; }
    // The query (scaled by an exact power of two when it was beyond stage 0's range).
    const Box& box;
    const Cylinder<double>& cyl;

    const Facts& facts() {
        if (!facts_) {
            Facts f{};
            f.scale = largest_length(box, cyl);
            f.k = scale_exponent(f.scale);
            f.flat = has_zero_size(box, cyl);
            Vec3<double> zeroed;
            f.two_scale_axis = tiny_components_zeroed(cyl.axis, zeroed, -200);
            if constexpr (is_oriented<Box>) {
                f.frame = signed_permutation(box.axes);
                f.turned = !f.frame;
            }
            facts_ = f;
        }
        return *facts_;
    }
    // The arithmetic rounds to nearest (a probe of the arithmetic itself: it sees every control word).
    bool nearest() { return memo(nearest_, [] { return boxcyl::detail::round_to_nearest(); }); }
    // Near touching by two plain-double hints: one of stage 0's separating-axis tests near its bound, and
    // a rounded answer that changes when the cylinder grows or shrinks by 2^-30 of the scale.
    bool near() {
        return memo(near_, [this] {
            return in_range && semi_static::near_touching(p, semi_static::kappas_of<Box>) && answer_moves(box, cyl, facts().scale);
        });
    }
    // Looks near touching by either hint (the axis's distance from the box near r counts too); a query
    // out of stage 0's range (one that could not be rescaled exactly) counts as near.
    bool looks_near() {
        return memo(looks_near_, [this] {
            return !in_range || witness_search::near_touching(p, semi_static::kappas_of<Box>) ||
                   answer_moves(box, cyl, facts().scale);
        });
    }

    // The tiny sizes' row (filtered/sandwich.hpp) asked a pair that the exact stage answered.
    bool exact_in_pairs = false;

private:
    std::optional<Facts> facts_;
    std::int8_t nearest_ = -1, near_ = -1, looks_near_ = -1;
};

}  // namespace boxcyl::filtered
