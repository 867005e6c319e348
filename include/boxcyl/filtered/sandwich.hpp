// Sizes far below the query's scale, decided by containment: a box extent, an aligned box's width, a
// radius or a height that is not zero but below τ = 2^-120 of the largest length (a subnormal extent
// beside ordinary ones, a disk of 2^-997 against a block of 1). Such a size makes the query two-scale:
// the enclosures cannot hold it, and the exact stage's integers grow to the full exponent range (50 to
// 400 µs). But the answer rarely hangs on it. Set every tiny size to 0 and the solids shrink; set it to
// τ and they grow, each containing the one before:
//
//   inner ⊆ given ⊆ outer   (box and cylinder alike),
//
// so a hit of the inner pair is a hit of the given one, and a miss of the outer pair is a miss. Both
// pairs have one scale, and the rows before the exact stage decide them (a flat shape, a size of τ).
// They differ from the given pair by at most τ·√3 in every point, so only a pair within about that of
// touching is left to the exact stage. Sound in every rounding mode: τ is built from its bits, the sizes
// are compared, never computed, and each pair is asked of the rows before the exact stage in the
// caller's mode.
#pragma once

#include <bit>       // std::bit_cast: τ from its bits
#include <cmath>     // std::fabs, std::ilogb
#include <cstdint>   // std::uint64_t
#include <limits>    // infinity
#include <optional>  // no tiny size

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"

namespace boxcyl::filtered::sandwich {

// Sizes below 2^-120 of the largest length are tiny. Far enough below the double-double enclosures'
// 2^-100 that growing them to τ changes no answer they decide; chosen on the magnitudes boundary set,
// where 2^-60 left a third of these pairs to the exact stage and 2^-90 to 2^-200 about one in ten.
inline constexpr int kTinyBelow = 120;

// τ = 2^(⌊log2 scale⌋ − 120), or nullopt where that is not a normal double (a scale below 2^-902).
inline std::optional<double> tiny_limit(double scale) {
    if (!(scale > 0) || !(scale < std::numeric_limits<double>::infinity())) return std::nullopt;
    const int e = std::ilogb(scale) - kTinyBelow;
    if (e < -1022) return std::nullopt;
    return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

// The inner and outer pairs.
template <class Box>
struct Pairs {
    Box inner_box, outer_box;
    Cylinder<double> inner_cyl, outer_cyl;
};

namespace detail {

// An aligned box's axis is tiny when min < max and both lie within (−τ, τ): then [min, min] ⊆ [min, max]
// ⊆ [−τ, τ]. (A width below τ far from the origin is impossible: it is at least an ulp of the
// coordinates.) [−τ, τ] itself is not tiny, so the pairs have no tiny size left.
inline bool shrink_and_grow(const AlignedBox<double>& b, AlignedBox<double>& inner, AlignedBox<double>& outer, double tau) {
    bool any = false;
    for (int i = 0; i < 3; ++i) {
        if (b.min[i] < b.max[i] && std::fabs(b.min[i]) < tau && std::fabs(b.max[i]) < tau) {
            inner.max[i] = b.min[i];
            outer.min[i] = -tau, outer.max[i] = tau;
            any = true;
        }
    }
    return any;
}
// Extents (canonical and oriented boxes: a larger extent spans a larger box, whatever the axes).
template <class Box>
bool shrink_and_grow(const Box& b, Box& inner, Box& outer, double tau) {
    bool any = false;
    for (int i = 0; i < 3; ++i) {
        if (b.extents[i] > 0 && b.extents[i] < tau) {
            inner.extents[i] = 0, outer.extents[i] = tau;
            any = true;
        }
    }
    return any;
}
inline bool shrink_and_grow(const Cylinder<double>& c, Cylinder<double>& inner, Cylinder<double>& outer, double tau) {
    bool any = false;
    if (c.radius > 0 && c.radius < tau) inner.radius = 0, outer.radius = tau, any = true;
    if (c.height > 0 && c.height < tau) inner.height = 0, outer.height = tau, any = true;
    return any;
}

}  // namespace detail

// The inner and outer pairs of a query whose largest length is `scale`; nullopt when no size is tiny.
template <class Box>
std::optional<Pairs<Box>> pairs(const Box& b, const Cylinder<double>& c, double scale) {
    const std::optional<double> tau = tiny_limit(scale);
    if (!tau) return std::nullopt;
    Pairs<Box> p{b, b, c, c};
    const bool box_tiny = detail::shrink_and_grow(b, p.inner_box, p.outer_box, *tau);
    const bool cyl_tiny = detail::shrink_and_grow(c, p.inner_cyl, p.outer_cyl, *tau);
    if (!box_tiny && !cyl_tiny) return std::nullopt;
    return p;
}

// The verdict from the pairs: `ask(box, cyl)` answers a pair exactly, or nullopt. The pair that can
// prove the likely answer is asked first (`likely_hit()`: a hint, which orders, never decides; called
// only where there are pairs): on one-ulp pairs, where each pair costs microseconds, asking the inner
// pair first spent one on every miss.
template <class Box, class Hint, class Ask>
std::optional<bool> decide(const Box& b, const Cylinder<double>& c, double scale, Hint&& likely_hit, Ask&& ask) {
    const std::optional<Pairs<Box>> p = pairs(b, c, scale);
    if (!p) return std::nullopt;
    auto inner_hits = [&] { return ask(p->inner_box, p->inner_cyl) == true; };
    auto outer_misses = [&] { return ask(p->outer_box, p->outer_cyl) == false; };
    const bool hit_first = likely_hit();
    if (hit_first ? inner_hits() : outer_misses()) return hit_first;
    if (hit_first ? outer_misses() : inner_hits()) return !hit_first;
    return std::nullopt;
}

}  // namespace boxcyl::filtered::sandwich
