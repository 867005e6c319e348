// The clearance question: boxcyl::within_distance(box, cylinder, margin) — does the box come within
// distance `margin` of the cylinder? Equivalently: does the box meet the cylinder rounded by the
// margin (every point within `margin` of it: Jolt's cylinder with a convex radius, Bullet's with a
// collision margin). margin = 0 is intersects(). EXACT for the inputs as given, both solids closed:
// a distance of exactly `margin` counts. Every box kind; float inputs are widened exactly.
// Invalid input throws std::invalid_argument naming the field (validate(); the margin must be finite
// and ≥ 0); within_distance_unchecked() skips that check. Needs the exact backend (boxcyl::exact).
//
// How: a table of stages, each answering only what it proves: three probes with the exact intersection
// query (a cylinder inside the rounded one — a hit answers yes; one that holds it — a miss answers
// no) and three more cylinders inside it (the shoulders) in that query's first two stages, certified
// distance bounds from an approximate closest pair (filtered/separation.hpp), the same refined in
// double-double (filtered/separation_refined.hpp), the rim tori's tests in interval arithmetic
// (filtered/rim.hpp), and the exact clearance decision (exact/clearance.hpp) for what remains.
// docs/clearance.md has the method and its figures.
#pragma once

#include <algorithm>    // std::max
#include <array>        // the probe table
#include <bit>          // std::bit_cast: a sum's neighbours
#include <cmath>        // std::isfinite
#include <cstdint>      // std::uint64_t
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
#include "boxcyl/filtered/prepared.hpp"
#include "boxcyl/filtered/rim.hpp"
#include "boxcyl/filtered/separation.hpp"
#include "boxcyl/filtered/separation_refined.hpp"
#include "boxcyl/filtered/witness_search.hpp"
#endif

namespace boxcyl {

namespace detail::clearance {

// Doubles lo ≤ a + b ≤ hi (a, b ≥ 0 finite), equal when the sum is exact; hi = +∞ past the range.
// Holds in every rounding mode: the sum is within one ulp of a + b, and s − max(a, b) is exact by
// Sterbenz's lemma (max ≤ s ≤ 2·max), so it equals min(a, b) exactly when s is exact.
struct Bounds {
    double lo, hi;
};
// The neighbours of an inexact s > 0 are its bit pattern ∓ 1 (the pattern after DBL_MAX is +∞): no
// libm call, which was a tenth of the query's time on random pairs.
inline Bounds sum_bounds(double a, double b) {
    const double s = a + b;
    if (!std::isfinite(s)) return {std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity()};
    if (s - std::max(a, b) == std::min(a, b)) return {s, s};
    const auto bits = std::bit_cast<std::uint64_t>(s);  // s > 0: an exact sum 0 + 0 returned above
    return {std::bit_cast<double>(bits - 1), std::bit_cast<double>(bits + 1)};
}

// A double ≤ m·f (m, f ≥ 0 finite): the computed product's neighbour below, or 0. The exact product
// lies between the computed one and a neighbour of it, in every rounding mode.
inline double product_below(double m, double f) {
    const double p = m * f;
    if (!(p > 0)) return 0;
    if (!std::isfinite(p)) return std::numeric_limits<double>::max();
    return std::bit_cast<double>(std::bit_cast<std::uint64_t>(p) - 1);
}

// The rounded cylinder's shoulders: it holds every cylinder of radius r + m·cos θ and half height
// h/2 + m·sin θ (a point within both is at most √((m cos θ)² + (m sin θ)²) = m from the cylinder). These
// factors (cos θ, sin θ) for θ of 30°, 45° and 60°, rounded so that cos² + sin² ≤ 1 exactly, give three
// cylinders between fat and tall: a box that cuts the rounded cylinder's rim region meets one of them.
inline constexpr std::array<std::array<double, 2>, 3> kShoulders{{{0.866, 0.4999}, {0.7071, 0.7071}, {0.4999, 0.866}}};
static_assert(0.866 * 0.866 + 0.4999 * 0.4999 < 1 && 2 * 0.7071 * 0.7071 < 1);

// The cylinders the probes ask, sharing the cylinder's centre and axis: `outer` holds the rounded
// cylinder (radius ≥ r + m, height ≥ h + 2m: a miss is a miss; left out, `outer_valid` false, when
// those sizes overflow), `fat` and `tall` lie inside it (radius ≤ r + m; height ≤ h + 2m: a hit is a
// hit).
struct Grown {
    Cylinder<double> outer, fat, tall;
    bool outer_valid;
    double m;
};
inline Grown grown(const Cylinder<double>& c, double m) {
    const Bounds r = sum_bounds(c.radius, m);
    const Bounds h = sum_bounds(c.height, 2 * m);  // 2m is exact, or +∞ (then h.hi = ∞)
    return {{c.center, c.axis, r.hi, h.hi}, {c.center, c.axis, r.lo, c.height}, {c.center, c.axis, c.radius, h.lo},
            std::isfinite(r.hi) && std::isfinite(h.hi), m};
}
// Shoulder k, inside the rounded cylinder: its sizes rounded down (g.tall has the radius as given,
// g.fat the height).
inline Cylinder<double> shoulder(const Grown& g, std::size_t k) {
    return {g.fat.center, g.fat.axis, sum_bounds(g.tall.radius, product_below(g.m, kShoulders[k][0])).lo,
            sum_bounds(g.fat.height, 2 * product_below(g.m, kShoulders[k][1])).lo};
}

// One probe: the exact intersection query on a cylinder; when its answer is `decides_when`, that is
// the answer. `valid` is false for the outer cylinder whose sizes overflow (left out).
struct Probe {
    Cylinder<double> cylinder;
    bool decides_when;
    bool valid;
};
// The probes in the order the query asks them (the batch filter asks the same, in the same order): fat
// (a hit is a hit), outer (a miss is a miss), tall (a hit is a hit).
inline std::array<Probe, 3> probes(const Grown& g) {
    return {{{g.fat, true, true}, {g.outer, false, g.outer_valid}, {g.tall, true, true}}};
}

// Stage 0's cylinders: the three probes, then the shoulders (a hit is a hit). The shoulders get stage
// 0 and its search, no whole query: what those leave in the rim region, the distance bounds answer.
inline constexpr std::size_t kStage0Cylinders = 3 + kShoulders.size();

#if defined(BOXCYL_HAS_EXACT)
// One query on its way through the stages, with what earlier stages proved for later ones.
template <class Box>
struct Pair {
    // A constructor, not an aggregate: aggregate initialisation cleared the whole Pair first (half a
    // kilobyte, `rep stos`), a tenth of a query's time on random pairs.
    Pair(const Box& b, const Cylinder<double>& c, double margin) : box(b), cyl(c), m(margin), g(grown(c, margin)) {}

    const Box& box;
    const Cylinder<double>& cyl;
    double m;
    Grown g;
    // The distance bounds' search, for the refined stage (constructed there: it is most of a Pair).
    std::optional<filtered::separation::Approximate> search;
    filtered::rim::Proved proved{};
    std::array<std::optional<bool>, kStage0Cylinders> stage0{};  // each answer stage 0 or the search gave
};

// A stage answers (true: within, false: not) or passes (nullopt) to the next.
template <class Box>
using Stage = std::optional<bool> (*)(Pair<Box>&);

// The shoulders' verdicts (after the probes': few queries get here), on the probes' problem. Not
// inlined: as part of the probes' loop, it made the common path slower.
template <bool all, class Box>
[[gnu::noinline]] void shoulder_verdicts(filtered::Prepared<Box>& prep, const Grown& g,
                                         std::array<std::optional<bool>, kStage0Cylinders>& verdicts) {
    for (std::size_t k = 0; k < kShoulders.size(); ++k) {
        const Cylinder<double> s = shoulder(g, k);
        const Cylinder<double> c{prep.cyl.center, prep.cyl.axis, s.radius, s.height};
        filtered::semi_static::set_sizes_of<Box>(prep.p, c.radius, c.height);
        verdicts[3 + k] = filtered::semi_static::decide(prep.p, prep.box, c);
        if (!all && verdicts[3 + k] == true) return;
    }
}

// Stage 0 of the exact intersection query (filtered/semi_static.hpp) on stage 0's cylinders at once:
// one problem, computed for the outer cylinder — the largest, so its length scale bounds the others —
// with each cylinder's sizes set in turn (the reduction to the box's frame, most of stage 0's cost, is
// shared). Each cylinder's verdict, probes() then the shoulders (nullopt: undecided, or not asked: the
// outer one left out, a query that stage 0 takes only rescaled, a parallelepiped); unless `all`, it
// stops at the first one answered with its deciding answer.
template <bool all, class Box>
std::array<std::optional<bool>, kStage0Cylinders> stage0_verdicts(const Box& box, const Grown& g) {
    std::array<std::optional<bool>, kStage0Cylinders> verdicts{};
#if !(defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT)
    if constexpr (!std::is_same_v<Box, Parallelepiped<double>>) {  // a parallelepiped's query has no stage 0
        const std::array<Probe, 3> ps = probes(g);
        if (!ps[1].valid) return verdicts;
        filtered::Prepared<Box> prep(box, ps[1].cylinder);
        if (!prep.in_range || prep.rescaled()) return verdicts;
        for (std::size_t k = 0; k < ps.size(); ++k) {
            const Cylinder<double> c{prep.cyl.center, prep.cyl.axis, ps[k].cylinder.radius, ps[k].cylinder.height};
            filtered::semi_static::set_sizes_of<Box>(prep.p, c.radius, c.height);
            verdicts[k] = filtered::semi_static::decide(prep.p, prep.box, c);
            if (!all && verdicts[k] == ps[k].decides_when) return verdicts;
        }
        shoulder_verdicts<all>(prep, g, verdicts);
    }
#endif
    return verdicts;
}
// A cylinder that stage 0 answered with its deciding answer is the answer; a probe answered otherwise
// is skipped below; one left undecided asks the whole query.
template <class Box>
std::optional<bool> probes_stage0(Pair<Box>& q) {
    q.stage0 = stage0_verdicts<false>(q.box, q.g);
    const std::array<Probe, 3> ps = probes(q.g);
    for (std::size_t k = 0; k < ps.size(); ++k)
        if (q.stage0[k] == ps[k].decides_when) return ps[k].decides_when;
    for (std::size_t k = ps.size(); k < kStage0Cylinders; ++k)
        if (q.stage0[k] == true) return true;  // a shoulder's hit
    return std::nullopt;
}
// Stage 0b of the exact intersection query (filtered/witness_search.hpp: a search in double for a
// point or a direction that stage 0's certificates then prove) on each shoulder that stage 0 left
// undecided, on the probes' problem again: hits in the rim region that no fixed witness shows. Sound in
// every rounding mode, as in the intersection query. (The probes' own whole queries search too.)
template <class Box>
std::optional<bool> shoulders_search(Pair<Box>& q) {
#if !(defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT)
    if constexpr (!std::is_same_v<Box, Parallelepiped<double>>) {
        if (!q.g.outer_valid) return std::nullopt;
        filtered::Prepared<Box> prep(q.box, q.g.outer);
        if (!prep.in_range || prep.rescaled()) return std::nullopt;
        for (std::size_t k = 0; k < kShoulders.size(); ++k) {
            std::optional<bool>& verdict = q.stage0[3 + k];
            if (verdict) continue;
            const Cylinder<double> s = shoulder(q.g, k);
            const Cylinder<double> c{prep.cyl.center, prep.cyl.axis, s.radius, s.height};
            filtered::semi_static::set_sizes_of<Box>(prep.p, c.radius, c.height);
            verdict = filtered::witness_search::decide(prep.p, prep.box, c);
            if (verdict == true) return true;
        }
    }
#endif
    return std::nullopt;
}
// Probe k of probes(), unless stage 0 or the search answered it.
template <class Box, std::size_t k>
std::optional<bool> probe(Pair<Box>& q) {
    const Probe p = probes(q.g)[k];
    if (q.stage0[k] || !p.valid) return std::nullopt;
    if (intersects_unchecked(q.box, p.cylinder) == p.decides_when) return p.decides_when;
    return std::nullopt;
}
// Certified distance bounds from an approximate closest pair (filtered/separation.hpp).
template <class Box>
std::optional<bool> separation(Pair<Box>& q) {
    const filtered::separation::Bounds b = filtered::separation::bounds(q.box, q.cyl, q.m, &q.search.emplace());
    if (b.upper <= q.m) return true;
    if (b.lower > q.m) return false;
    return std::nullopt;
}
// The same bounds after Newton refinement, in double-double (filtered/separation_refined.hpp): the
// pairs within rounding of the margin.
template <class Box>
std::optional<bool> refined_separation(Pair<Box>& q) {
    if (!q.search) return std::nullopt;
    return filtered::separation::refined_within(q.box, q.cyl, q.m, *q.search);
}
// Whether the box misses the exact fat and tall cylinders, proved by missing them with their sizes
// rounded up.
template <class Box>
bool misses_fat_and_tall(const Pair<Box>& q) {
    const Bounds r = sum_bounds(q.cyl.radius, q.m);
    const Bounds h = sum_bounds(q.cyl.height, 2 * q.m);
    return std::isfinite(r.hi) && std::isfinite(h.hi) &&
           !intersects_unchecked(q.box, Cylinder<double>{q.cyl.center, q.cyl.axis, r.hi, q.cyl.height}) &&
           !intersects_unchecked(q.box, Cylinder<double>{q.cyl.center, q.cyl.axis, q.cyl.radius, h.hi});
}
// The rim tori in intervals (filtered/rim.hpp). Its "no" needs the box to miss the exact fat and tall
// cylinders: proved by missing them with their sizes rounded up. What it proves far, the exact stage
// skips.
template <class Box>
std::optional<bool> rim(Pair<Box>& q) {
    const std::optional<bool> r = filtered::rim::decide(q.box, q.cyl, q.m, &q.proved);
    if (r == true) return true;
    if (r == false && misses_fat_and_tall(q)) return false;
    return std::nullopt;
}
// The exact decision (exact/clearance.hpp): always answers. Without a proof that the box misses fat
// and tall it asks them itself, and skips only the edges and facets proved far.
template <class Box>
std::optional<bool> exact_stage(Pair<Box>& q) {
    const exact::clearance::Known known{misses_fat_and_tall(q), q.proved.edge_far, q.proved.facet_far};
    return exact::clearance::within(exact::clearance::as_parallelepiped(to_exact(q.box)), to_exact(q.cyl),
                                    to_rational(q.m), known);
}

// The order is policy: on random pairs most are decided by the probes' stage 0 (the fat cylinder's hit
// or the outer one's miss, certified in plain double, or a shoulder's hit), and the shoulders' search
// and the distance bounds in double decide nearly all of the rest. The refined bounds come before the
// probes' whole queries: at the margin they decide the pairs whose distance is within rounding of it
// but not equal (most contacts with the side or a cap among them), where the probes' queries, on
// shapes within rounding of touching, cost as much and decide fewer. The probes then decide the
// side and cap contacts at exactly the margin; the rim tests and the exact decision what is left:
// rim contacts at exactly the margin, and queries in a directed rounding mode that the earlier stages
// leave (docs/clearance.md gives the measured shares).
template <class Box>
inline constexpr std::array<Stage<Box>, 9> stages{&probes_stage0<Box>, &shoulders_search<Box>, &separation<Box>,
                                                  &refined_separation<Box>, &probe<Box, 0>,  &probe<Box, 1>,
                                                  &probe<Box, 2>,      &rim<Box>,            &exact_stage<Box>};
inline constexpr std::array<const char*, 9> stage_names{"probes' stage 0", "shoulders' search", "distance bounds",
                                                        "refined bounds",  "fat probe",      "outer probe",
                                                        "tall probe",      "rim intervals",  "exact"};

// The index of the stage that answers, for the benchmark's per-stage shares (margin > 0).
template <class Box>
std::size_t answering_stage(const Box& box, const Cylinder<double>& cyl, double m) {
    Pair<Box> q(box, cyl, m);
    for (std::size_t i = 0; i < stages<Box>.size(); ++i)
        if (stages<Box>[i](q)) return i;
    return stages<Box>.size();
}

template <class Box>
bool within(const Box& box, const Cylinder<double>& cyl, double m) {
    if (m == 0) return intersects_unchecked(box, cyl);
    Pair<Box> q(box, cyl, m);
    for (const Stage<Box> stage : stages<Box>)
        if (const std::optional<bool> answer = stage(q)) return *answer;
    return false;  // not reached: the exact stage always answers
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
