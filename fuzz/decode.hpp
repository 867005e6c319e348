// The fuzz targets' input decoder (fuzz_query, fuzz_batch, fuzz_symmetry): bytes to doubles, vectors,
// frames, boxes and cylinders, favouring what breaks floating point — magnitudes across the whole double range,
// subnormals, signed zeros, repeated values and one-ulp neighbours (touching configurations), raw bit
// patterns, exactly orthonormal frames (signed permutations) and rotations rounded to double — and the
// hex-float printing of a failing case (cpp(): as C++ that compiles).
#pragma once

#include <array>    // decoder tables
#include <cmath>    // std::ldexp, std::nextafter, std::sqrt, std::fabs
#include <cstddef>  // std::size_t
#include <cstdint>  // byte decoding
#include <cstdio>   // std::snprintf
#include <cstring>  // std::memcpy
#include <limits>   // infinity
#include <string>   // failure messages

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"

namespace boxcyl::fuzz {

using boxcyl::Vec3;

class Decoder {
public:
    Decoder(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}

    // From now on, every value within about 64 binades of 2^e (e itself anywhere), instead of mixing the
    // whole double range within one query: the exact stage's integers then stay short and a query
    // costs microseconds, not up to milliseconds (fuzz_symmetry, which asks many questions per second).
    void narrow(int e) {
        narrow_ = true;
        e_ = e;
    }

    std::uint8_t byte() { return p_ < end_ ? *p_++ : 0; }
    bool remaining() const { return p_ < end_; }
    // Operands and arguments are read in separate statements: their order of evaluation is unspecified
    // (gcc and clang differ), and the same bytes must decode alike in the replay and the fuzz builds.
    std::int16_t i16() {
        const unsigned lo = byte();
        return static_cast<std::int16_t>(lo | (unsigned{byte()} << 8));
    }

    // One double: the first byte chooses how the rest is read.
    double value() {
        const std::uint8_t tag = byte();
        double v = 0;
        switch (tag % 8) {
            case 0: v = scaled(static_cast<std::int8_t>(byte())); break;        // small integers
            case 1: v = scaled(static_cast<std::int8_t>(byte()) / 8.0); break;  // exact eighths
            case 2: {  // any magnitude, subnormals
                const double m = i16();
                v = narrow_ ? std::ldexp(m, e_ + i16() % 64) : std::ldexp(m, i16() % 1100);
                break;
            }
            case 3: {  // any bit pattern (narrow: any sign and significand, the exponent near e)
                std::uint64_t b = 0;
                for (int i = 0; i < 8; ++i) b |= std::uint64_t{byte()} << (8 * i);
                if (narrow_) {
                    constexpr std::uint64_t one = std::uint64_t{1023} << 52, fraction = (std::uint64_t{1} << 52) - 1;
                    const int e = e_ + static_cast<int>(b >> 52 & 63) - 32;
                    b = (b & ~(std::uint64_t{2047} << 52 | fraction)) | one | (b & fraction);  // in [1, 2), signed
                    std::memcpy(&v, &b, sizeof v);
                    v = std::ldexp(v, e);
                } else {
                    std::memcpy(&v, &b, sizeof v);
                }
                break;
            }
            case 4: v = last_; break;  // coincident values: touching
            case 5: v = std::nextafter(last_, (tag & 8) ? std::numeric_limits<double>::infinity()
                                                        : -std::numeric_limits<double>::infinity());
                break;  // one ulp away from touching
            case 6: v = (tag & 8) ? -0.0 : 0.0; break;
            case 7: v = scaled(static_cast<std::int8_t>(byte()) / 10.0); break;  // decimals rounded to double
        }
        last_ = v;
        return v;
    }
    Vec3<double> vec() {
        const double x = value(), y = value();
        return {x, y, value()};
    }

private:
    double scaled(double v) const { return e_ != 0 ? std::ldexp(v, e_) : v; }

    const std::uint8_t* p_;
    const std::uint8_t* end_;
    double last_ = 0;
    bool narrow_ = false;
    int e_ = 0;
};

// The oriented-box frame: a signed permutation (exactly orthonormal), a rotation from a quaternion with
// small integer components rounded to double, or nine decoded values (mostly rejected by validate()).
inline std::array<Vec3<double>, 3> frame(Decoder& d) {
    const std::uint8_t mode = d.byte() % 3;
    if (mode == 0) {
        static constexpr int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        const std::uint8_t b = d.byte();
        const int* p = perms[b % 6];
        std::array<Vec3<double>, 3> a{};
        for (int i = 0; i < 3; ++i) a[static_cast<std::size_t>(i)][static_cast<std::size_t>(p[i])] = ((b >> (3 + i)) & 1) ? -1.0 : 1.0;
        return a;
    }
    if (mode == 1) {
        double w = static_cast<std::int8_t>(d.byte()), x = static_cast<std::int8_t>(d.byte());
        double y = static_cast<std::int8_t>(d.byte()), z = static_cast<std::int8_t>(d.byte());
        const double n = std::sqrt(w * w + x * x + y * y + z * z);
        if (n == 0) w = 1;
        else w /= n, x /= n, y /= n, z /= n;
        return {Vec3<double>{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                Vec3<double>{2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                Vec3<double>{2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
    }
    const Vec3<double> a = d.vec(), b = d.vec();
    return {a, b, d.vec()};
}

inline std::string hex(const Vec3<double>& v) {
    char s[128];
    std::snprintf(s, sizeof s, "{%a, %a, %a}", v[0], v[1], v[2]);
    return s;
}

inline std::string describe(const boxcyl::Cylinder<double>& c) {
    char s[64];
    std::snprintf(s, sizeof s, "%a, %a}", c.radius, c.height);
    return "cylinder{" + hex(c.center) + ", " + hex(c.axis) + ", " + s;
}

inline std::string show(const boxcyl::AlignedBox<double>& b) { return "AlignedBox{" + hex(b.min) + ", " + hex(b.max) + "}"; }
inline std::string show(const boxcyl::OrientedBox<double>& b) {
    return "OrientedBox{" + hex(b.center) + ", {" + hex(b.axes[0]) + ", " + hex(b.axes[1]) + ", " + hex(b.axes[2]) +
           "}, " + hex(b.extents) + "}";
}

// A cylinder from the bytes (radius and height as absolute values): validate() decides whether it is used.
inline boxcyl::Cylinder<double> cylinder(Decoder& d) {
    boxcyl::Cylinder<double> cyl;
    cyl.center = d.vec();
    cyl.axis = d.vec();
    cyl.radius = std::fabs(d.value());
    cyl.height = std::fabs(d.value());
    return cyl;
}
inline boxcyl::AlignedBox<double> aligned_box(Decoder& d) {
    boxcyl::AlignedBox<double> box;
    const Vec3<double> a = d.vec(), b = d.vec();
    for (std::size_t i = 0; i < 3; ++i) box.min[i] = std::fmin(a[i], b[i]), box.max[i] = std::fmax(a[i], b[i]);
    return box;
}
inline boxcyl::OrientedBox<double> oriented_box(Decoder& d) {
    boxcyl::OrientedBox<double> box;
    box.axes = frame(d);
    box.center = d.vec();
    const Vec3<double> e = d.vec();
    box.extents = {std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2])};
    return box;
}

// Any three axes (the frame's modes: signed permutations, rotations, nine decoded values, so also zero
// and parallel axes), non-negative extents: every finite one is valid.
inline boxcyl::Parallelepiped<double> parallelepiped(Decoder& d) {
    boxcyl::Parallelepiped<double> box;
    box.axes = frame(d);
    box.center = d.vec();
    const Vec3<double> e = d.vec();
    box.extents = {std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2])};
    return box;
}
inline boxcyl::CanonicalBox<double> canonical_box(Decoder& d) {
    const Vec3<double> e = d.vec();
    return {{std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2])}};
}

// The shapes as C++ expressions (hex floats), so that a failing case can be pasted into a test.
inline std::string cpp(const Vec3<double>& v) { return "boxcyl::Vec3<double>" + hex(v); }
inline std::string cpp(double x) {
    char s[40];
    std::snprintf(s, sizeof s, "%a", x);
    return s;
}
inline std::string cpp(const boxcyl::Cylinder<double>& c) {
    return "boxcyl::Cylinder<double>{" + cpp(c.center) + ", " + cpp(c.axis) + ", " + cpp(c.radius) + ", " +
           cpp(c.height) + "}";
}
inline std::string cpp(const boxcyl::AlignedBox<double>& b) {
    return "boxcyl::AlignedBox<double>{" + cpp(b.min) + ", " + cpp(b.max) + "}";
}
inline std::string cpp(const boxcyl::CanonicalBox<double>& b) { return "boxcyl::CanonicalBox<double>{" + cpp(b.extents) + "}"; }
inline std::string cpp(const boxcyl::OrientedBox<double>& b) {
    return "boxcyl::OrientedBox<double>{" + cpp(b.center) + ", {" + cpp(b.axes[0]) + ", " + cpp(b.axes[1]) + ", " +
           cpp(b.axes[2]) + "}, " + cpp(b.extents) + "}";
}
inline std::string cpp(const boxcyl::Parallelepiped<double>& b) {
    return "boxcyl::Parallelepiped<double>{" + cpp(b.center) + ", {" + cpp(b.axes[0]) + ", " + cpp(b.axes[1]) + ", " +
           cpp(b.axes[2]) + "}, " + cpp(b.extents) + "}";
}

}  // namespace boxcyl::fuzz
