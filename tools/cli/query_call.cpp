// The tool's only call into the library's query front door (kept apart so the rest of the tool does
// not depend on which algorithms exist).
#include <array>    // box axes
#include <cmath>    // std::fabs
#include <stdexcept>  // a margin or a (signed) distance without the exact backend
#include <variant>  // std::visit over the box kinds

#if defined(BOXCYL_CLI_EXACT)
#include "boxcyl/compiled.hpp"  // libboxcyl: the queries compiled once, every algorithm and arithmetic
#else
#include "boxcyl/query.hpp"  // no exact backend: the templates, float and double only
#endif
#include "jsonl_query.hpp"

namespace boxcyl::cli {

namespace {

// Whether the axes are orthonormal to within the rounding of arithmetic U: |Ai·Aj − δij| ≤ 2^-49 for
// double (a few units in the last place: axes computed in double, e.g. from a rotation, pass), 2^-20
// for float (the axes are rounded to float first). The Gram matrix is computed in double; for floats
// its products are exact.
template <class U>
bool orthonormal_within_rounding(const std::array<Vec3<double>, 3>& axes) {
    constexpr double tolerance = sizeof(U) == sizeof(float) ? 0x1p-20 : 0x1p-49;
    std::array<Vec3<double>, 3> a;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) a[i][k] = static_cast<double>(static_cast<U>(axes[i][k]));
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            const double g = a[i][0] * a[j][0] + a[i][1] * a[j][1] + a[i][2] * a[j][2];
            if (!(std::fabs(g - (i == j ? 1.0 : 0.0)) <= tolerance)) return false;
        }
    return true;
}

}  // namespace

bool needs_hull_for_frame(const Query& q, const QueryOptions& opt) {
    const bool rounded = opt.arithmetic == Arithmetic::float32 || opt.arithmetic == Arithmetic::float64;
    if (!rounded || (opt.algorithm != Algorithm::inequalities && opt.algorithm != Algorithm::lcp)) return false;
    const std::array<Vec3<double>, 3>* axes = nullptr;
    if (const auto* o = std::get_if<OrientedBox<double>>(&q.box)) axes = &o->axes;
    if (const auto* p = std::get_if<Parallelepiped<double>>(&q.box)) axes = &p->axes;
    if (axes == nullptr) return false;
    return opt.arithmetic == Arithmetic::float32 ? !orthonormal_within_rounding<float>(*axes)
                                                 : !orthonormal_within_rounding<double>(*axes);
}

bool run_query(const Query& q, const QueryOptions& opt) {
    if (q.margin) {
#if defined(BOXCYL_CLI_EXACT)
        return std::visit([&](const auto& box) { return boxcyl::within_distance(box, q.cylinder, *q.margin); }, q.box);
#else
        throw std::invalid_argument("margin: needs the exact backend (this boxcyl was built without GMP/FLINT)");
#endif
    }
    // The linear-inequalities and LCP methods work in the box's frame, taking its axes as orthonormal:
    // in rounded arithmetic, axes further from orthonormal than rounding (an oriented box's axes may be
    // 1e-4 off) would answer for a different box. The convex-hull method takes the parallelepiped the
    // axes span, as given, in the same arithmetic.
    if (needs_hull_for_frame(q, opt)) {
        const auto* o = std::get_if<OrientedBox<double>>(&q.box);
        const Parallelepiped<double> p =
            o ? Parallelepiped<double>{o->center, o->axes, o->extents} : std::get<Parallelepiped<double>>(q.box);
        return boxcyl::intersects(p, q.cylinder, QueryOptions{Algorithm::hull, opt.arithmetic});
    }
    return std::visit([&](const auto& box) { return boxcyl::intersects(box, q.cylinder, opt); }, q.box);
}

Distance run_distance_query(const Query& q) {
#if defined(BOXCYL_CLI_EXACT)
    return std::visit([&](const auto& box) { return boxcyl::distance(box, q.cylinder); }, q.box);
#else
    (void)q;
    throw std::invalid_argument("distance: needs the exact backend (this boxcyl was built without GMP/FLINT)");
#endif
}

SignedDistance run_signed_distance_query(const Query& q) {
#if defined(BOXCYL_CLI_EXACT)
    return std::visit([&](const auto& box) { return boxcyl::signed_distance(box, q.cylinder); }, q.box);
#else
    (void)q;
    throw std::invalid_argument("signed distance: needs the exact backend (this boxcyl was built without GMP/FLINT)");
#endif
}

}  // namespace boxcyl::cli
