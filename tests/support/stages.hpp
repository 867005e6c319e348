// Single rows of the exact default's pipeline called from the inputs, for the tests and benchmarks
// that look at one certifier alone (the pipeline itself runs them on a prepared query:
// filtered/schedule.hpp).
#pragma once

#include <optional>

#include "boxcyl/filtered.hpp"

namespace boxcyl::testing {

// Stage 0 (semi_static): nullopt when undecided or out of its range of scales.
template <class Box>
std::optional<bool> stage0(const Box& b, const Cylinder<double>& cyl) {
    filtered::semi_static::Problem p;
    if (!filtered::semi_static::problem(b, cyl, p)) return std::nullopt;
    return filtered::semi_static::decide(p, b, cyl);
}
// Stage 0b (search): the searched certificates.
template <class Box>
std::optional<bool> stage0b(const Box& b, const Cylinder<double>& cyl) {
    filtered::semi_static::Problem p;
    if (!filtered::semi_static::problem(b, cyl, p)) return std::nullopt;
    return filtered::witness_search::decide(p, b, cyl);
}
// Linear inequalities on Bounded, then on Interval (the directed-rounding rows).
template <class Box>
std::optional<bool> stage1(const Box& b, const Cylinder<double>& cyl) {
    filtered::Prepared<Box> q(b, cyl);
    if (const std::optional<bool> r = filtered::enclosed::inequalities<Bounded>(q)) return r;
    return filtered::enclosed::inequalities<Interval>(q);
}
// The thorough search for a deep witness point.
template <class Box>
bool thorough_hit(const Box& b, const Cylinder<double>& cyl) {
    filtered::semi_static::Problem p;
    return filtered::semi_static::problem(b, cyl, p) && filtered::witness_search::certain_hit(p, b, cyl);
}

}  // namespace boxcyl::testing
