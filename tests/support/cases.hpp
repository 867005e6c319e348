// Test inputs: random and near-touching query generators, the exact answer, and printing a case as
// copy-pasteable C++ (hex-float literals, so the printed case is bit-exact).
#pragma once

#include <algorithm> // std::max
#include <cmath>     // std::ldexp, std::nextafter, std::cos, std::sin, std::ilogb, std::scalbn
#include <cstddef>   // std::size_t
#include <cstdint>   // std::uint64_t
#include <cstdio>    // std::snprintf
#include <cstring>   // std::memcpy
#include <limits>    // std::numeric_limits
#include <random>    // std::mt19937_64 and distributions
#include <string>    // describe()
#include <utility>   // std::pair
#include <vector>    // boundary_pairs()

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/oracle/oracle.hpp"

namespace boxcyl::testing {

enum class BoxKind { aligned, oriented, canonical };

struct Case {
    BoxKind kind = BoxKind::aligned;
    AlignedBox<double> aligned;     // used when kind == aligned
    OrientedBox<double> oriented;   // used when kind == oriented
    CanonicalBox<double> canonical; // used when kind == canonical (cylinder in the box frame)
    Cylinder<double> cylinder;
};

inline std::string hex(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}
inline std::string hex(const Vec3<double>& v) { return "{" + hex(v[0]) + ", " + hex(v[1]) + ", " + hex(v[2]) + "}"; }

// A C++ snippet that rebuilds the case exactly: paste it into a regression test.
inline std::string describe(const Case& c) {
    std::string s = "Case{";
    switch (c.kind) {
        case BoxKind::aligned:
            s += "BoxKind::aligned, AlignedBox<double>{" + hex(c.aligned.min) + ", " + hex(c.aligned.max) + "}, {}, {}";
            break;
        case BoxKind::oriented:
            s += "BoxKind::oriented, {}, OrientedBox<double>{" + hex(c.oriented.center) + ", {Vec3<double>" +
                 hex(c.oriented.axes[0]) + ", Vec3<double>" + hex(c.oriented.axes[1]) + ", Vec3<double>" +
                 hex(c.oriented.axes[2]) + "}, " + hex(c.oriented.extents) + "}, {}";
            break;
        case BoxKind::canonical:
            s += "BoxKind::canonical, {}, {}, CanonicalBox<double>{" + hex(c.canonical.extents) + "}";
            break;
    }
    s += ", Cylinder<double>{" + hex(c.cylinder.center) + ", " + hex(c.cylinder.axis) + ", " +
         hex(c.cylinder.radius) + ", " + hex(c.cylinder.height) + "}}";
    return s;
}

// f(box, cylinder) with the case's box of its kind (any query: f is called with each box type).
template <class F>
auto with_box(const Case& c, F&& f) {
    switch (c.kind) {
        case BoxKind::aligned: return f(c.aligned, c.cylinder);
        case BoxKind::oriented: return f(c.oriented, c.cylinder);
        case BoxKind::canonical: break;
    }
    return f(c.canonical, c.cylinder);
}

// The exact answer for the inputs as given.
inline bool oracle_answer(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return oracle::intersects(box, cyl); });
}

// A right-handed orthonormal frame (rounded) from a random unit quaternion.
inline std::array<Vec3<double>, 3> random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    double w = n(rng), x = n(rng), y = n(rng), z = n(rng);
    const double len = std::sqrt(w * w + x * x + y * y + z * z);
    w /= len, x /= len, y /= len, z /= len;
    return {Vec3<double>{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
            Vec3<double>{2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
            Vec3<double>{2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
}

// Mixed random queries: box kinds, scales 1e-6…1e6, thin boxes, long and short cylinders, zero and tiny
// (1e-12, 1e-300, subnormal) axis components, random rotations. Sizes are set so roughly half hit.
// A signed permutation: an exactly orthonormal frame (rotations rounded to double never are).
inline std::array<Vec3<double>, 3> random_signed_permutation(std::mt19937_64& rng) {
    std::array<int, 3> p{0, 1, 2};
    std::shuffle(p.begin(), p.end(), rng);
    std::array<Vec3<double>, 3> axes{};
    for (int i = 0; i < 3; ++i) axes[i][p[i]] = (rng() & 1) ? 1.0 : -1.0;
    return axes;
}

// Profiles: `mixed` is the standard set; `degenerate` stresses magnitudes (scales 2^-600…2^600,
// sizes that are zero or differ by 2^±40 within a case) on top of the mixed choices; `uniform` is
// plain data, unlike the mixed set's choices: scales 2^±4, box extents uniform in [0.05, 2], radius
// and height in [0.1, 3], axis components uniform in [−1, 1] (no zero sizes, no tiny components).
// `georeferenced`: coordinates as geo-referenced data has them — shapes of 1e-3 to 10 (log-uniform)
// far from the origin (UTM-like eastings 1e5–1e6, northings 1e6–1e7, elevations 0–5e3, each position
// rounded to 1e-3 like surveyed data half of the time), rounded rotations, axes of plain directions.
// `magnitudes`: sizes of very different magnitudes in one query — a box of 1e-3 against a cylinder of
// 1e4 and the reverse, a radius or extent of 1e-300 or a subnormal beside ordinary ones, axis components
// up to 300 binary orders apart — at positions near the origin or offset as in `georeferenced`.
enum class Profile { mixed, degenerate, uniform, georeferenced, magnitudes };

class CaseGenerator {
public:
    explicit CaseGenerator(std::uint64_t seed, Profile profile = Profile::mixed) : rng_(seed), profile_(profile) {}

    std::mt19937_64& rng() { return rng_; }

    Case next() {
        if (profile_ == Profile::georeferenced || profile_ == Profile::magnitudes) return far_or_mixed();
        Case c;
        const int range = profile_ == Profile::degenerate ? 600 : profile_ == Profile::uniform ? 4 : 20;
        const double scale = std::ldexp(1.0, static_cast<int>(uniform(-range, range)));  // 2^±20 ≈ 1e-6 … 1e6
        const int kind = static_cast<int>(uniform(0, 3));
        c.kind = kind == 0 ? BoxKind::aligned : kind == 1 ? BoxKind::oriented : BoxKind::canonical;

        Vec3<double> ext;
        for (int i = 0; i < 3; ++i) ext[i] = scale * extent_factor();
        const Vec3<double> origin{scale * uniform(-4, 4), scale * uniform(-4, 4), scale * uniform(-4, 4)};

        switch (c.kind) {
            case BoxKind::aligned:
                for (int i = 0; i < 3; ++i) {
                    c.aligned.min[i] = origin[i] - ext[i];
                    c.aligned.max[i] = origin[i] + ext[i];
                }
                break;
            case BoxKind::oriented:
                c.oriented.center = origin;
                // A quarter get an exactly orthonormal frame, so the exact LCP/linear-inequalities methods
                // are tested on oriented boxes too.
                c.oriented.axes = uniform(0, 1) < 0.25 ? random_signed_permutation(rng_) : random_rotation(rng_);
                c.oriented.extents = ext;
                break;
            case BoxKind::canonical:
                c.canonical.extents = ext;
                break;
        }
        const Vec3<double> box_center = c.kind == BoxKind::canonical ? Vec3<double>{0, 0, 0} : origin;
        const double box_size = ext[0] + ext[1] + ext[2];
        c.cylinder.axis = random_axis();
        c.cylinder.radius = scale * length_factor() * 0.5;
        c.cylinder.height = scale * length_factor();
        // Centre near the box so that hits and misses are both common.
        const double reach = box_size + c.cylinder.radius + c.cylinder.height * 0.5;
        for (int i = 0; i < 3; ++i) c.cylinder.center[i] = box_center[i] + reach * uniform(-0.45, 0.45);
        return c;
    }

    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }

private:
    double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
    // A surveyed coordinate: rounded to a millimetre half of the time.
    double survey(double x) { return uniform(0, 1) < 0.5 ? std::nearbyint(x * 1000) / 1000 : x; }
    Vec3<double> offset() {
        if (profile_ == Profile::magnitudes && uniform(0, 1) < 0.5) return {0, 0, 0};
        return {survey(sign() * uniform(1e5, 1e6)), survey(sign() * uniform(1e6, 1e7)), survey(uniform(0, 5e3))};
    }
    // A size of the `magnitudes` profile: ordinary, or one of the extremes.
    double mixed_size(double ordinary) {
        switch (static_cast<int>(uniform(0, 8))) {
            case 0: return ordinary * 1e-7;   // 1e-3 beside 1e4
            case 1: return ordinary * 1e7;
            case 2: return 1e-300;
            case 3: return std::numeric_limits<double>::denorm_min() * uniform(1, 1e6);
            default: return ordinary;
        }
    }
    Vec3<double> plain_axis() {
        Vec3<double> a{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        if (profile_ == Profile::magnitudes && uniform(0, 1) < 0.5) a[static_cast<int>(uniform(0, 3))] *= std::ldexp(1.0, -static_cast<int>(uniform(100, 300)));
        if (a[0] == 0 && a[1] == 0 && a[2] == 0) a[2] = 1;
        return a;
    }
    Case far_or_mixed() {
        Case c;
        c.kind = uniform(0, 1) < 0.5 ? BoxKind::aligned : BoxKind::oriented;
        const double size = log_uniform(1e-3, 10);
        Vec3<double> ext{size * uniform(0.2, 1), size * uniform(0.2, 1), size * uniform(0.2, 1)};
        double radius = log_uniform(1e-3, 10) * 0.5, height = log_uniform(1e-3, 10);
        if (profile_ == Profile::magnitudes) {
            for (int i = 0; i < 3; ++i) ext[i] = mixed_size(ext[i]);
            radius = mixed_size(radius);
            height = mixed_size(height);
        }
        const Vec3<double> k = offset();
        if (c.kind == BoxKind::aligned) {
            for (int i = 0; i < 3; ++i) c.aligned.min[i] = survey(k[i] - ext[i]), c.aligned.max[i] = survey(k[i] + ext[i]);
            for (int i = 0; i < 3; ++i)
                if (c.aligned.max[i] < c.aligned.min[i]) std::swap(c.aligned.min[i], c.aligned.max[i]);
        } else {
            c.oriented.center = k;
            c.oriented.axes = random_rotation(rng_);
            c.oriented.extents = ext;
        }
        c.cylinder.axis = plain_axis();
        c.cylinder.radius = radius;
        c.cylinder.height = height;
        const double reach = ext[0] + ext[1] + ext[2] + radius + height * 0.5;
        for (int i = 0; i < 3; ++i) c.cylinder.center[i] = k[i] + reach * uniform(-0.45, 0.45);
        return c;
    }
    double extent_factor() {
        if (profile_ == Profile::uniform) return uniform(0.05, 2.0);
        if (profile_ == Profile::degenerate && uniform(0, 1) < 0.3) return std::ldexp(uniform(0.5, 1.0), uniform(0, 1) < 0.5 ? -40 : 40);
        switch (static_cast<int>(uniform(0, 10))) {
            case 0: return 0.0;                       // flat
            case 1: return std::ldexp(1.0, -30);      // thin
            default: return uniform(0.05, 2.0);
        }
    }
    double length_factor() {
        if (profile_ == Profile::uniform) return uniform(0.1, 3.0);
        if (profile_ == Profile::degenerate && uniform(0, 1) < 0.3) return std::ldexp(uniform(0.5, 1.0), uniform(0, 1) < 0.5 ? -40 : 40);
        switch (static_cast<int>(uniform(0, 12))) {
            case 0: return 0.0;                       // segment / disk
            case 1: return uniform(5.0, 40.0);        // long
            case 2: return uniform(0.001, 0.05);      // short
            default: return uniform(0.1, 3.0);
        }
    }
    double component() {
        if (profile_ == Profile::uniform) return uniform(-1.0, 1.0);
        switch (static_cast<int>(uniform(0, 16))) {
            case 0: case 1: return 0.0;
            case 2: return 1e-12 * sign();
            case 3: return 1e-300 * sign();
            case 4: return std::numeric_limits<double>::denorm_min() * 3 * sign();
            default: return uniform(-1.0, 1.0);
        }
    }
    double sign() { return uniform(0, 1) < 0.5 ? -1.0 : 1.0; }
    Vec3<double> random_axis() {
        for (;;) {
            Vec3<double> a{component(), component(), component()};
            if (a[0] != 0 || a[1] != 0 || a[2] != 0) {
                const double s = std::ldexp(1.0, static_cast<int>(uniform(-3, 4)));  // non-unit on purpose
                return {a[0] * s, a[1] * s, a[2] * s};
            }
        }
    }

    std::mt19937_64 rng_;
    Profile profile_;
};

// An oriented case whose frame is a rounded random rotation with one component perturbed by up to 2e-6
// (still valid: |AᵢᵀAⱼ − δᵢⱼ| ≤ 1e-4): far from orthonormal compared with rounding, so the filters
// must widen for it (η).
inline Case perturbed_frame(CaseGenerator& gen) {
    for (;;) {
        Case c = gen.next();
        if (c.kind != BoxKind::oriented) continue;
        c.oriented.axes = random_rotation(gen.rng());
        const int axis = static_cast<int>(gen.uniform(0, 3)), comp = static_cast<int>(gen.uniform(0, 3));
        c.oriented.axes[axis][comp] += gen.uniform(-2e-6, 2e-6);
        if (validate(c.oriented).ok()) return c;
    }
}

// ---- Boundary (one-ulp) generation ----

// Doubles as ordered integers, so that "adjacent doubles" is "adjacent integers".
inline std::int64_t ordered_bits(double x) {
    std::int64_t i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
}
inline double from_ordered_bits(std::int64_t i) {
    if (i < 0) i = std::numeric_limits<std::int64_t>::min() - i;
    double x;
    std::memcpy(&x, &i, sizeof x);
    return x;
}

// Which parameter a boundary search moves.
enum class Parameter { radius, height, center_x, center_y, center_z, box_shift, rotation };

inline const char* name(Parameter p) {
    switch (p) {
        case Parameter::radius: return "radius";
        case Parameter::height: return "height";
        case Parameter::center_x: return "center_x";
        case Parameter::center_y: return "center_y";
        case Parameter::center_z: return "center_z";
        case Parameter::box_shift: return "box_shift";
        case Parameter::rotation: return "rotation";
    }
    return "?";
}

// The case with parameter p set to v (rotation: the cylinder axis turned by angle v about a fixed
// perpendicular; box_shift: the box translated by v along x).
inline Case with_parameter(Case c, Parameter p, double v, const Vec3<double>& axis0 = {}) {
    switch (p) {
        case Parameter::radius: c.cylinder.radius = v; break;
        case Parameter::height: c.cylinder.height = v; break;
        case Parameter::center_x: c.cylinder.center[0] = v; break;
        case Parameter::center_y: c.cylinder.center[1] = v; break;
        case Parameter::center_z: c.cylinder.center[2] = v; break;
        case Parameter::box_shift:
            if (c.kind == BoxKind::aligned) {
                const double w = c.aligned.max[0] - c.aligned.min[0];
                c.aligned.min[0] = v;
                c.aligned.max[0] = v + w;
            } else if (c.kind == BoxKind::oriented) {
                c.oriented.center[0] = v;
            } else {
                c.cylinder.center[0] = -v;
            }
            break;
        case Parameter::rotation: {
            // Rotate axis0 in the plane spanned by axis0 and a perpendicular by angle v. Prescale by a
            // power of two so that tiny (subnormal) axes do not underflow in the norms.
            const double m = std::max({std::abs(axis0[0]), std::abs(axis0[1]), std::abs(axis0[2])});
            const int ex = std::ilogb(m);
            const Vec3<double> a{std::scalbn(axis0[0], -ex), std::scalbn(axis0[1], -ex), std::scalbn(axis0[2], -ex)};
            Vec3<double> perp = std::abs(a[0]) < std::abs(a[1]) ? Vec3<double>{0, a[2], -a[1]} : Vec3<double>{a[2], 0, -a[0]};
            if (perp[0] == 0 && perp[1] == 0 && perp[2] == 0) perp = {a[1], -a[0], 0};
            const double la = std::sqrt(dot(a, a)), lp = std::sqrt(dot(perp, perp));
            const double cs = std::cos(v), sn = std::sin(v);
            for (int i = 0; i < 3; ++i) c.cylinder.axis[i] = cs * a[i] / la + sn * perp[i] / lp;
            break;
        }
    }
    return c;
}

// Bisection over adjacent doubles: given lo < hi with oracle answers that differ, returns the two
// adjacent doubles x < next(x) in [lo, hi] where the answer flips (first = case at x).
template <class Answer>
std::pair<double, double> bisect_ulp(double lo, double hi, Answer&& answer) {
    std::int64_t a = ordered_bits(lo), b = ordered_bits(hi);
    const bool at_a = answer(lo);
    // b − a may exceed INT64_MAX when [lo, hi] straddles 0: take the difference in uint64 (exact, as
    // 0 < b − a < 2^64) and step by half of it, which always fits.
    auto gap = [&] { return static_cast<std::uint64_t>(b) - static_cast<std::uint64_t>(a); };
    while (gap() > 1) {
        const std::int64_t m = a + static_cast<std::int64_t>(gap() / 2);
        if (answer(from_ordered_bits(m)) == at_a) a = m;
        else b = m;
    }
    return {from_ordered_bits(a), from_ordered_bits(b)};
}

// A near-touching pair: a random case and a parameter moved until two inputs one ulp apart get opposite
// exact answers. Returns false when this random start had no flip in the scanned range (caller retries).
inline bool boundary_pair(CaseGenerator& gen, Case& first, Case& second, Parameter& which) {
    Case c = gen.next();
    const int pick = static_cast<int>(gen.uniform(0, 7));
    which = static_cast<Parameter>(pick);
    if (which == Parameter::rotation && c.kind == BoxKind::canonical) which = Parameter::radius;
    const Vec3<double> axis0 = c.cylinder.axis;
    double lo = 0, hi = 0;
    const double s = std::abs(c.cylinder.radius) + std::abs(c.cylinder.height) + 1e-300;
    const double span = 8 * (s + std::abs(c.cylinder.center[0]) + std::abs(c.cylinder.center[1]) +
                             std::abs(c.cylinder.center[2]));
    switch (which) {
        case Parameter::radius:
        case Parameter::height: lo = 0; hi = span; break;
        case Parameter::center_x: case Parameter::center_y: case Parameter::center_z: {
            const int i = static_cast<int>(which) - static_cast<int>(Parameter::center_x);
            lo = c.cylinder.center[i] - span;
            hi = c.cylinder.center[i];
            break;
        }
        case Parameter::box_shift: {
            const double x0 = c.kind == BoxKind::aligned ? c.aligned.min[0]
                              : c.kind == BoxKind::oriented ? c.oriented.center[0] : -c.cylinder.center[0];
            lo = x0 - span;
            hi = x0 + span;
            break;
        }
        case Parameter::rotation: lo = 0; hi = 3.14159; break;
    }
    auto answer = [&](double v) { return oracle_answer(with_parameter(c, which, v, axis0)); };
    if (answer(lo) == answer(hi)) {
        // Try the half-way point as the other end: a flip inside [lo, hi] is common for hits.
        const double mid = lo + (hi - lo) / 2;
        if (answer(mid) == answer(lo)) return false;
        hi = mid;
    }
    auto [x, y] = bisect_ulp(lo, hi, answer);
    first = with_parameter(c, which, x, axis0);
    second = with_parameter(c, which, y, axis0);
    return true;
}

// `pairs` boundary pairs of the generator's cases, both members of each in turn.
inline std::vector<Case> boundary_pairs(CaseGenerator& gen, std::size_t pairs) {
    std::vector<Case> cases;
    cases.reserve(2 * pairs);
    while (cases.size() < 2 * pairs) {
        Case a, b;
        Parameter which{};
        if (!boundary_pair(gen, a, b, which)) continue;
        cases.push_back(a);
        cases.push_back(b);
    }
    return cases;
}

}  // namespace boxcyl::testing
