// The exact conversions of double (and float) shapes: each value is the rational it denotes. The one
// place where the inputs become exact numbers, for the exact algorithms (exact/paths.hpp), the exact
// stage's last resort and the oracle alike.
#pragma once

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/rational.hpp"

namespace boxcyl {

inline Vec3<Rational> to_exact(const Vec3<double>& v) {
    return {to_rational(v[0]), to_rational(v[1]), to_rational(v[2])};
}
inline Cylinder<Rational> to_exact(const Cylinder<double>& c) {
    return {to_exact(c.center), to_exact(c.axis), to_rational(c.radius), to_rational(c.height)};
}
inline AlignedBox<Rational> to_exact(const AlignedBox<double>& b) { return {to_exact(b.min), to_exact(b.max)}; }
inline CanonicalBox<Rational> to_exact(const CanonicalBox<double>& b) { return {to_exact(b.extents)}; }
inline OrientedBox<Rational> to_exact(const OrientedBox<double>& b) {
    return {to_exact(b.center), {to_exact(b.axes[0]), to_exact(b.axes[1]), to_exact(b.axes[2])},
            to_exact(b.extents)};
}
inline Parallelepiped<Rational> to_exact(const Parallelepiped<double>& b) {
    return {to_exact(b.center), {to_exact(b.axes[0]), to_exact(b.axes[1]), to_exact(b.axes[2])},
            to_exact(b.extents)};
}
inline Cylinder<Rational> to_exact(const Cylinder<float>& c) {
    return {{Rational(c.center[0]), Rational(c.center[1]), Rational(c.center[2])},
            {Rational(c.axis[0]), Rational(c.axis[1]), Rational(c.axis[2])},
            Rational(c.radius), Rational(c.height)};
}

}  // namespace boxcyl
