// Exact rationals: GMP's mpq_class. Every finite double is a dyadic rational and converts exactly.
#pragma once

#include <gmpxx.h>  // mpq_class: exact rational arithmetic (Debian libgmp-dev)

#include <cmath>      // std::isfinite
#include <stdexcept>  // std::domain_error

#include "boxcyl/number/traits.hpp"

namespace boxcyl {

using Rational = mpq_class;

template <>
struct number_traits<Rational> {
    static constexpr bool is_exact = true;
    static constexpr bool has_sqrt = false;
};

inline int sign_of(const Rational& x) { return sgn(x); }

// The exact rational a finite double denotes (mpq_set_d is exact). Non-finite values have none.
inline Rational to_rational(double x) {
    if (!std::isfinite(x)) throw std::domain_error("boxcyl::to_rational: value is not finite");
    return Rational(x);
}

}  // namespace boxcyl
