// What a number type can do. Algorithms are written once over T; they ask these traits instead of
// assuming floating point: an exact T never reaches std::sqrt.
#pragma once

#include <cmath>        // std::sqrt for the floating-point specialisation
#include <type_traits>  // std::is_floating_point_v

// Forces inlining where GCC at -O2 would keep a small hot function out of line (each use says why):
// before a function's declaration (with `inline`), or after a lambda's parameter list.
#if defined(__GNUC__) || defined(__clang__)
#define BOXCYL_FORCE_INLINE __attribute__((always_inline))
#else
#define BOXCYL_FORCE_INLINE
#endif

namespace boxcyl {

// Primary template: unknown types are not exact and have no sqrt; specialise to opt in.
template <class T, class Enable = void>
struct number_traits {
    static constexpr bool is_exact = false;
    static constexpr bool has_sqrt = false;
};

template <class T>
struct number_traits<T, std::enable_if_t<std::is_floating_point_v<T>>> {
    static constexpr bool is_exact = false;
    static constexpr bool has_sqrt = true;
    static T sqrt(T x) { return std::sqrt(x); }
};

template <class T>
inline constexpr bool is_exact_v = number_traits<T>::is_exact;

// The only door to a square root. Instantiating it for an exact type is a compile error, by design:
// exact paths reformulate instead of normalising, so that they stay exact.
template <class T>
T inexact_sqrt(const T& x) {
    static_assert(number_traits<T>::has_sqrt,
                  "boxcyl: sqrt is inexact; exact number types must not normalise (use squared norms "
                  "or quadratic-field numbers)");
    return number_traits<T>::sqrt(x);
}

// |x| and x clamped to [−e, e] (e ≥ 0). Enclosure types (Interval, Bounded) provide enclosure_abs and
// enclosure_clamp, found by argument-dependent lookup: they enclose the result without deciding a
// sign, so a value near 0 does not make the filter undecided. Other types compare.
template <class T>
constexpr T abs_value(const T& x) {
    if constexpr (requires { enclosure_abs(x); }) {
        return enclosure_abs(x);
    } else if constexpr (std::is_floating_point_v<T>) {
        // fabs, one AND: GCC compiles the comparison below to a branch for double (it keeps −0's
        // sign, which fabs drops), and on random data that branch mispredicts — a tenth of stage 0's
        // time (filtered/semi_static.hpp). Comparisons cannot tell the two zeros apart.
        if (std::is_constant_evaluated()) return x < T(0) ? T(-x) : x;
        return std::fabs(x);
    } else {
        return x < T(0) ? T(-x) : x;
    }
}
template <class T>
T clamp_symmetric(const T& x, const T& e) {
    if constexpr (requires { enclosure_clamp(x, e); }) {
        return enclosure_clamp(x, e);
    } else {
        if (x < -e) return T(-e);
        if (e < x) return e;
        return x;
    }
}

// Sign of a value as -1, 0, +1. Exact types specialise sign_of for speed.
template <class T>
int sign_of(const T& x) {
    return (T(0) < x) - (x < T(0));
}

}  // namespace boxcyl
