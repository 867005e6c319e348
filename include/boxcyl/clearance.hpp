// The clearance question: boxcyl::within_distance(box, cylinder, margin) — does the box come within
// distance `margin` of the cylinder? Equivalently: does the box meet the cylinder rounded by the
// margin (every point within `margin` of it: Jolt's cylinder with a convex radius, Bullet's with a
// collision margin). margin = 0 is intersects(). EXACT for the inputs as given, both solids closed:
// a distance of exactly `margin` counts. Every box kind; float inputs are widened exactly.
// Invalid input throws std::invalid_argument naming the field (validate(); the margin must be finite
// and ≥ 0); within_distance_unchecked() skips that check. Needs the exact backend (boxcyl::exact).
//
// How: three probes with the exact intersection query decide most pairs (a cylinder that holds the
// rounded one — a miss answers no; two that it holds — a hit answers yes); the rim tori's tests in
// interval arithmetic (filtered/rim.hpp) most of the rest; the exact clearance decision
// (exact/clearance.hpp) what remains. docs/clearance.md has the method and its figures.
#pragma once

#include <algorithm>    // std::max
#include <array>        // the probe table
#include <cmath>        // std::nextafter, std::isfinite
#include <limits>       // infinity
#include <optional>     // the interval stage's "undecided"
#include <stdexcept>    // std::invalid_argument
#include <type_traits>  // std::type_identity_t

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/margin.hpp"
#include "boxcyl/query.hpp"
#if defined(BOXCYL_HAS_EXACT)
#include "boxcyl/exact/clearance.hpp"
#include "boxcyl/exact/convert.hpp"
#include "boxcyl/filtered/rim.hpp"
#endif

namespace boxcyl {

namespace detail::clearance {

// Doubles lo ≤ a + b ≤ hi (a, b ≥ 0 finite), equal when the sum is exact; hi = +∞ past the range.
// Holds in every rounding mode: the sum is within one ulp of a + b, and s − max(a, b) is exact by
// Sterbenz's lemma (max ≤ s ≤ 2·max), so it equals min(a, b) exactly when s is exact.
struct Bounds {
    double lo, hi;
};
inline Bounds sum_bounds(double a, double b) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double s = a + b;
    if (!std::isfinite(s)) return {std::numeric_limits<double>::max(), inf};
    if (s - std::max(a, b) == std::min(a, b)) return {s, s};
    return {std::nextafter(s, -inf), std::nextafter(s, inf)};
}

// One probe: the exact query on a cylinder; when its answer is `decides_when`, it is the answer.
struct Probe {
    Cylinder<double> cylinder;
    bool decides_when;
};

// The probes, in order: the cylinder holding the rounded one (radius ≥ r + m, height ≥ h + 2m: a miss
// is a miss), then the fat and tall cylinders it holds (radius ≤ r + m; height ≤ h + 2m: a hit is a
// hit). A probe whose sizes overflow is left out (`valid` false).
struct Probes {
    std::array<Probe, 3> probe;
    std::array<bool, 3> valid;
};
inline Probes probes(const Cylinder<double>& c, double m) {
    const Bounds r = sum_bounds(c.radius, m);
    const Bounds h = sum_bounds(c.height, 2 * m);  // 2m is exact, or +∞ (then h.hi = ∞)
    return {{Probe{{c.center, c.axis, r.hi, h.hi}, false}, Probe{{c.center, c.axis, r.lo, c.height}, true},
             Probe{{c.center, c.axis, c.radius, h.lo}, true}},
            {std::isfinite(r.hi) && std::isfinite(h.hi), true, true}};
}

#if defined(BOXCYL_HAS_EXACT)
template <class Box>
bool within(const Box& box, const Cylinder<double>& cyl, double m) {
    if (m == 0) return intersects_unchecked(box, cyl);
    const Probes p = probes(cyl, m);
    for (std::size_t i = 0; i < p.probe.size(); ++i)
        if (p.valid[i] && intersects_unchecked(box, p.probe[i].cylinder) == p.probe[i].decides_when)
            return p.probe[i].decides_when;
    // The rim tori in intervals. A "no" needs the box to miss the exact fat and tall cylinders: proved
    // by missing the fat and tall cylinders with their sizes rounded up.
    filtered::rim::Proved proved;
    const std::optional<bool> rim = filtered::rim::decide(box, cyl, m, &proved);
    if (rim == true) return true;
    const Bounds r = sum_bounds(cyl.radius, m);
    const Bounds h = sum_bounds(cyl.height, 2 * m);
    const exact::clearance::Known known{std::isfinite(r.hi) && std::isfinite(h.hi) &&
                                      !intersects_unchecked(box, Cylinder<double>{cyl.center, cyl.axis, r.hi, cyl.height}) &&
                                      !intersects_unchecked(box, Cylinder<double>{cyl.center, cyl.axis, cyl.radius, h.hi}),
                                  proved.edge_far, proved.facet_far};
    // "No" needs the box to miss fat and tall (the rim tests' completeness); without that proof the
    // exact decision asks them itself, and skips only the edges and facets proved far (facts alone).
    if (rim == false && known.misses_fat_and_tall) return false;
    return exact::clearance::within(exact::clearance::as_parallelepiped(to_exact(box)), to_exact(cyl),
                                    to_rational(m), known);
}
#endif

}  // namespace detail::clearance

// Whether dist(box, cyl) ≤ margin, exactly. Preconditions: valid box and cylinder, margin finite ≥ 0.
template <class Box, class T>
bool within_distance_unchecked(const Box& box, const Cylinder<T>& cyl, std::type_identity_t<T> margin) {
#if defined(BOXCYL_HAS_EXACT)
    if constexpr (std::is_same_v<T, double>)
        return detail::clearance::within(box, cyl, margin);
    else
        return detail::clearance::within(detail::cast<double>(box), detail::cast<double>(cyl),
                                         static_cast<double>(margin));
#else
    static_assert(detail::dependent_false<T>, "boxcyl::within_distance is exact and needs the exact backend: "
                                              "link boxcyl::exact (GMP, FLINT)");
    return false;
#endif
}

template <class Box, class T>
bool within_distance(const Box& box, const Cylinder<T>& cyl, std::type_identity_t<T> margin) {
    detail::require_valid(box, cyl);
    if (!is_valid_margin(margin)) [[unlikely]]
        throw std::invalid_argument(validate_margin(margin).message());
    return within_distance_unchecked(box, cyl, margin);
}

}  // namespace boxcyl
