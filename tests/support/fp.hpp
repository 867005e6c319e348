// Floating-point test helpers shared by the enclosure tests (test_filtered: Interval, test_bounded:
// Bounded): special values, a rounding-mode guard, and operands across the whole double range.
#pragma once

#include <cfenv>   // rounding modes
#include <cmath>   // std::ldexp
#include <limits>  // special values
#include <random>  // std::mt19937_64

namespace boxcyl::testing {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double dmax = std::numeric_limits<double>::max();
constexpr double dmin = std::numeric_limits<double>::min();
constexpr double denorm = std::numeric_limits<double>::denorm_min();

// Restores the rounding mode on scope exit.
class RoundingMode {
public:
    explicit RoundingMode(int mode) : saved_(std::fegetround()) { std::fesetround(mode); }
    ~RoundingMode() { std::fesetround(saved_); }
    RoundingMode(const RoundingMode&) = delete;
    RoundingMode& operator=(const RoundingMode&) = delete;

private:
    int saved_;
};

inline const char* mode_name(int mode) {
    switch (mode) {
        case FE_TONEAREST: return "to_nearest";
        case FE_UPWARD: return "upward";
        case FE_DOWNWARD: return "downward";
        case FE_TOWARDZERO: return "toward_zero";
    }
    return "?";
}

// Operands across the whole double range: zeros, subnormals, tiny and huge normals, ordinary values,
// powers of two and the extremes, both signs.
inline double random_operand(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double s = (rng() & 1) ? -1.0 : 1.0;
    switch (rng() % 10) {
        case 0: return (rng() & 3) == 0 ? s * 0.0 : 0.0;
        case 1: return s * denorm * double(1 + rng() % (1ull << (rng() % 52)));             // subnormal
        case 2: return s * std::ldexp(0.5 + unit(rng), -1022 - int(rng() % 30) + 30);   // near min normal
        case 3: return s * std::ldexp(0.5 + unit(rng), 900 + int(rng() % 124));         // huge
        case 4: return s * std::ldexp(0.5 + unit(rng), -1000 + int(rng() % 100));       // tiny
        case 5: return s * std::ldexp(1.0, int(rng() % 200) - 100);                     // power of two
        case 6: {
            const double special[] = {dmax, dmin, denorm, 1.0, 2.0, 0.5, 3.0};
            return s * special[rng() % 7];
        }
        default: return s * std::ldexp(0.5 + unit(rng), int(rng() % 80) - 40);  // ordinary
    }
}

}  // namespace boxcyl::testing
