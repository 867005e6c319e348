// The exact counterpart of to_unit(): the unit axis u = D/|D| = (D/d)·√d, d = D·D, as numbers of the
// quadratic field Q(√d). No rounding anywhere; the reductions to the canonical frame of reduce.hpp then run
// unchanged with T = QFRational (exactly, for aligned boxes and exactly orthonormal oriented boxes).
#pragma once

#include <stdexcept>  // std::invalid_argument

#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"

namespace boxcyl {

// `field` must be Q(√(D·D)) for this cylinder's axis D and must outlive the result:
//     QuadraticField<Rational> field(dot(cyl.axis, cyl.axis));
//     UnitCylinder<QFRational> u = to_unit(cyl, field);
inline UnitCylinder<QFRational> to_unit(const Cylinder<Rational>& c, const QuadraticField<Rational>& field) {
    const Rational d = dot(c.axis, c.axis);
    if (sgn(d) == 0) throw std::invalid_argument("boxcyl::to_unit: zero axis");
    if (d != field.d()) throw std::invalid_argument("boxcyl::to_unit: field is not Q(sqrt(axis·axis))");
    UnitCylinder<QFRational> u;
    for (int i = 0; i < 3; ++i) {
        u.center[i] = QFRational(c.center[i]);
        u.direction[i] = QFRational(Rational(0), Rational(c.axis[i] / d), field);
    }
    u.radius = QFRational(c.radius);
    u.half_height = QFRational(Rational(c.height / 2));
    return u;
}

// Lifts rational shapes into the field (b = 0), for the generic reductions.
inline Vec3<QFRational> lift(const Vec3<Rational>& v) { return {QFRational(v[0]), QFRational(v[1]), QFRational(v[2])}; }

}  // namespace boxcyl
