// A consumer of boxcyl::header_only alone (no GMP): validation and an explicitly chosen float64 query.
// Exits non-zero, saying why, when an answer is wrong.
#include <cstdio>  // std::printf

#include <boxcyl/boxcyl.hpp>

#if defined(BOXCYL_HAS_EXACT)
#error "this consumer must build without the exact backend"
#endif

int main() {
    int failures = 0;
    auto check = [&](bool ok, const char* what) {
        if (!ok) {
            std::printf("FAIL: %s\n", what);
            ++failures;
        }
    };
    const boxcyl::AlignedBox<double> box{{-1, -1, -1}, {1, 1, 1}};
    const boxcyl::Cylinder<double> near{{2.5, 0, 0}, {0, 0, 5}, 2, 1};
    const boxcyl::Cylinder<double> far{{3.5, 0, 0}, {0, 0, 5}, 2, 1};
    const boxcyl::Cylinder<double> bad{{0, 0, 0}, {0, 0, 1}, -1, 1};
    const boxcyl::QueryOptions plain{boxcyl::Algorithm::inequalities, boxcyl::Arithmetic::float64};
    check(boxcyl::intersects(box, near, plain), "overlapping cylinder reported apart");
    check(!boxcyl::intersects(box, far, plain), "distant cylinder reported touching");
    check(boxcyl::validate(bad).message() == "cylinder.radius: is negative", "validate() named the wrong field");
    std::printf("boxcyl %s core consumer: %s\n", BOXCYL_VERSION_STRING, failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
