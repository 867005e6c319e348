// A consumer of boxcyl::exact (GMP): the default query is exact, so touching counts and one ulp away
// does not. Exits non-zero, saying why, when an answer is wrong.
#include <cmath>    // std::nextafter
#include <cstdio>   // std::printf
#include <cstring>  // std::strcmp

#include <boxcyl/boxcyl.hpp>

int main() {
    int failures = 0;
    auto check = [&](bool ok, const char* what) {
        if (!ok) {
            std::printf("FAIL: %s\n", what);
            ++failures;
        }
    };
    const boxcyl::AlignedBox<double> box{{-1, -1, -1}, {1, 1, 1}};
    // Axis parallel to z at x = 3, radius 2: the side touches the face x = 1 exactly.
    const boxcyl::Cylinder<double> touching{{3, 0, 0}, {0, 0, 5}, 2, 1};
    const boxcyl::Cylinder<double> apart{{std::nextafter(3.0, 4.0), 0, 0}, {0, 0, 5}, 2, 1};
    check(boxcyl::intersects(box, touching), "touching cylinder reported apart");
    check(!boxcyl::intersects(box, apart), "cylinder one ulp away reported touching");
    check(boxcyl::intersects(box, touching, {boxcyl::Algorithm::oracle, boxcyl::Arithmetic::exact}),
          "the oracle disagrees");
#ifdef EXPECTED_VERSION
    check(std::strcmp(BOXCYL_VERSION_STRING, EXPECTED_VERSION) == 0, "header and package versions differ");
#endif
    std::printf("boxcyl %s exact consumer: %s\n", BOXCYL_VERSION_STRING, failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
