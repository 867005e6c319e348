// Exact checks shared by the enclosure tests (test_filtered: Interval, test_bounded: Bounded).
#pragma once

#include <gtest/gtest.h>

#include <cmath>   // std::isinf
#include <string>  // messages

#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"
#include "boxcyl/oracle/oracle.hpp"  // to_rational: the rational a double denotes

namespace boxcyl::testing {

// Whether lo ≤ √x ≤ hi (hi = +∞ allowed), decided exactly in Q(√x); x ≥ 0.
inline ::testing::AssertionResult sqrt_enclosed(const Rational& x, double lo, double hi) {
    const QuadraticField<Rational> field(x);
    const QFRational root = QFRational::root(field);
    if (!(QFRational(to_rational(lo)) <= root)) return ::testing::AssertionFailure() << "lower bound above the root";
    if (!std::isinf(hi) && !(root <= QFRational(to_rational(hi))))
        return ::testing::AssertionFailure() << "upper bound below the root";
    return ::testing::AssertionSuccess();
}

}  // namespace boxcyl::testing
