// A consumer of the compiled library boxcyl::boxcyl: the double and float queries (scalar for the three
// box kinds, distance and signed distance, batch, grid) from the light header <boxcyl/boxcyl.hpp>.
// Exits non-zero, saying why, when an answer is wrong. Also compiles against the header-only templates
// (-DBOXCYL_HEADER_ONLY -DBOXCYL_HAS_EXACT, with GMP), which is how scripts/compile-time.sh compares
// the two.
#include <cmath>    // std::nextafter
#include <cstdint>  // std::uint64_t
#include <cstdio>   // std::printf
#include <cstring>  // std::strcmp
#include <span>     // batch inputs and outputs
#include <stdexcept>  // a refused margin
#include <string>   // its message
#include <vector>   // batch arrays

// Every header the README shows: with the compiled library, <boxcyl/batch.hpp> and <boxcyl/grid.hpp>
// are its declarations; with the templates, the templates.
#include <boxcyl/batch.hpp>
#include <boxcyl/boxcyl.hpp>
#include <boxcyl/grid.hpp>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
    if (!ok) {
        std::printf("FAIL: %s\n", what);
        ++failures;
    }
}

// The cylinder touching the face x = 1 of the box [-1, 1]^3, and the same one ulp further away, in T.
template <class T>
void scalar(const char* type) {
    const boxcyl::AlignedBox<T> aligned{{-1, -1, -1}, {1, 1, 1}};
    const boxcyl::OrientedBox<T> oriented{{0, 0, 0}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1, 1, 1}};
    const boxcyl::CanonicalBox<T> canonical{{1, 1, 1}};
    const boxcyl::Cylinder<T> touching{{3, 0, 0}, {0, 0, 5}, 2, 1};
    const boxcyl::Cylinder<T> apart{{std::nextafter(T(3), T(4)), 0, 0}, {0, 0, 5}, 2, 1};
    const bool all = boxcyl::intersects(aligned, touching) && boxcyl::intersects(oriented, touching) &&
                     boxcyl::intersects(canonical, touching);
    const bool none = !boxcyl::intersects(aligned, apart) && !boxcyl::intersects(oriented, apart) &&
                      !boxcyl::intersects(canonical, apart);
    if (!all) std::printf("FAIL (%s): a touching cylinder reported apart\n", type);
    if (!none) std::printf("FAIL (%s): a cylinder one ulp away reported touching\n", type);
    failures += !all + !none;
    const boxcyl::QueryOptions hull{boxcyl::Algorithm::hull, boxcyl::Arithmetic::exact};
    check(boxcyl::intersects(oriented, touching, hull) && !boxcyl::intersects(oriented, apart, hull),
          "exact hull query");
    const boxcyl::QueryOptions plain{boxcyl::Algorithm::inequalities, boxcyl::Arithmetic::float64};
    const boxcyl::Cylinder<T> far{{4, 0, 0}, {0, 0, 5}, 2, 1};
    check(!boxcyl::intersects(aligned, far, plain), "plain double query");
    // The face x = 1 and the side at x = 4 − 2 = 2: distance 1 exactly; touching: [0, 0].
    const boxcyl::Distance d = boxcyl::distance(aligned, far);
    check(d.lower <= 1 && d.upper >= 1 && d.upper - d.lower <= 4 * std::nextafter(1.0, 2.0) - 4, "distance encloses 1");
    check(d.on_box[0] == 1 && boxcyl::distance(oriented, touching).upper == 0, "distance witnesses and touching");
    // The signed distance: apart, the distance's bounds; a cylinder over x in [0.5, 4.5] overlaps by 0.5
    // (its bounds at most 2^-40 times the largest length, 2.5, apart).
    const boxcyl::Cylinder<T> deep{{T(2.5), 0, 0}, {0, 0, 5}, 2, 1};
    const boxcyl::SignedDistance s = boxcyl::signed_distance(aligned, deep);
    check(s.lower <= -0.5 && s.upper >= -0.5 && s.upper - s.lower <= 0x1p-38 && s.normal[0] > 0.999,
          "signed distance encloses -0.5");
    const boxcyl::SignedDistance apart_sd = boxcyl::signed_distance(canonical, far);
    check(apart_sd.lower == d.lower && apart_sd.upper == d.upper, "signed distance apart is the distance");
}

// Three aligned boxes: touching, apart by one ulp, overlapping; as arrays, as rows and as oriented boxes.
template <class T>
void batch() {
    const T one_ulp = std::nextafter(T(1), T(0));
    const std::vector<T> min_x{-1, -1, 0}, min_y{-1, -1, -1}, min_z{-1, -1, -1};
    const std::vector<T> max_x{1, one_ulp, 2}, max_y{1, 1, 1}, max_z{1, 1, 1};
    const boxcyl::Cylinder<double> cyl{{3, 0, 0}, {0, 0, 5}, 2, 1};
    std::vector<std::uint64_t> mask(boxcyl::batch::mask_words(3));
    const boxcyl::batch::AlignedBoxes<T> boxes{min_x, min_y, min_z, max_x, max_y, max_z};
    const boxcyl::batch::Stats s = boxcyl::batch::intersects(cyl, boxes, std::span<std::uint64_t>(mask));
    check(mask[0] == 0b101 && s.boxes == 3, "batch of aligned boxes (mask)");
    bool out[3] = {};
    boxcyl::batch::intersects(cyl, boxes, std::span<bool>(out), {/*threads*/ 2});
    check(out[0] && !out[1] && out[2], "batch of aligned boxes (bools, 2 threads)");
    std::vector<boxcyl::Distance> dist(3);
    boxcyl::batch::distance(cyl, boxes, std::span<boxcyl::Distance>(dist));
    check(dist[0].upper == 0 && dist[1].lower > 0 && dist[2].upper == 0, "batch::distance of aligned boxes");
    // The third box overlaps the cylinder by 1 along x (its depth), the second is apart.
    std::vector<boxcyl::SignedDistance> sd(3);
    boxcyl::batch::signed_distance(cyl, boxes, std::span<boxcyl::SignedDistance>(sd), {/*threads*/ 2});
    check(sd[1].lower == dist[1].lower && sd[1].upper == dist[1].upper && sd[2].lower <= -1 && -1 <= sd[2].upper,
          "batch::signed_distance of aligned boxes");
    std::vector<boxcyl::AlignedBox<T>> rows;
    for (std::size_t i = 0; i < 3; ++i) rows.push_back({{min_x[i], min_y[i], min_z[i]}, {max_x[i], max_y[i], max_z[i]}});
    mask.assign(mask.size(), 0);
    boxcyl::batch::intersects(cyl, std::span<const boxcyl::AlignedBox<T>>(rows), std::span<std::uint64_t>(mask));
    check(mask[0] == 0b101, "batch of aligned boxes (rows)");
    rows[1].max[0] = rows[1].min[0] - 1;  // min > max: invalid
    bool threw = false;
    try {
        boxcyl::batch::intersects(cyl, std::span<const boxcyl::AlignedBox<T>>(rows), std::span<bool>(out),
                                  {1, boxcyl::batch::Kernel::automatic, /*check_boxes*/ true});
    } catch (const boxcyl::batch::InvalidBox& e) {
        threw = e.index == 1;
    }
    check(threw, "batch of aligned boxes (rows, checked: boxes[1] is invalid)");
    std::vector<boxcyl::OrientedBox<T>> oriented;
    for (std::size_t i = 0; i < 3; ++i)
        oriented.push_back({{(min_x[i] + max_x[i]) / 2, 0, 0},
                            {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                            {(max_x[i] - min_x[i]) / 2, 1, 1}});
    // (the centre and half-width are exact here: powers of two apart)
    mask.assign(mask.size(), 0);
    boxcyl::batch::intersects(cyl, std::span<const boxcyl::OrientedBox<T>>(oriented), std::span<std::uint64_t>(mask));
    check(mask[0] == 0b101, "batch of oriented boxes");
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    (defined(BOXCYL_BATCH_DISPATCH) || !defined(BOXCYL_HEADER_ONLY))
    // The kernels chosen at run time are there (boxcyl::batch_dispatch, inside the compiled library):
    // the AVX2 one runs wherever the CPU has what it was compiled for (src/batch/dispatch.cpp).
    const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                      __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
                      __builtin_cpu_supports("popcnt") && __builtin_cpu_supports("sse4.2");
    check(boxcyl::batch::available(boxcyl::batch::Kernel::avx2) == avx2, "the AVX2 kernel's availability");
    check(s.lanes >= (avx2 ? 4u : 2u), "the widest kernel answers");
#endif
    const boxcyl::Cylinder<float> fcyl{{3, 0, 0}, {0, 0, 5}, 2, 1};
    boxcyl::batch::intersects(fcyl, boxes, std::span<bool>(out));
    check(out[0] && !out[1] && out[2], "batch with a float cylinder");
    // The clearance form: box 1 is exactly d = 1 − one_ulp from the cylinder's side.
    const double d = 1 - double(one_ulp), below = std::nextafter(d, 0.0);
    boxcyl::batch::within_distance(cyl, boxes, d, std::span<std::uint64_t>(mask));
    check(mask[0] == 0b111, "batch::within_distance at the margin (arrays)");
    boxcyl::batch::within_distance(cyl, boxes, below, std::span<bool>(out));
    check(out[0] && !out[1] && out[2], "batch::within_distance one ulp below the margin (arrays, bools)");
    rows[1].max[0] = one_ulp;
    boxcyl::batch::within_distance(cyl, std::span<const boxcyl::AlignedBox<T>>(rows), d, std::span<std::uint64_t>(mask));
    check(mask[0] == 0b111, "batch::within_distance (rows)");
    boxcyl::batch::within_distance(fcyl, std::span<const boxcyl::OrientedBox<T>>(oriented), 0.5,
                                   std::span<std::uint64_t>(mask));
    check(mask[0] == 0b111, "batch::within_distance (oriented boxes, float cylinder)");
    boxcyl::batch::within_distance(cyl, std::span<const boxcyl::OrientedBox<T>>(oriented), 0.0,
                                   std::span<std::uint64_t>(mask));
    check(mask[0] == 0b101, "batch::within_distance at margin 0 (oriented boxes)");
    bool refused = false;
    try {
        boxcyl::batch::within_distance(cyl, boxes, -1.0, std::span<bool>(out));
    } catch (const std::invalid_argument& e) {
        refused = std::string(e.what()) == "margin: is negative";
    }
    check(refused, "batch::within_distance refuses a negative margin");
}

// The integer-vertex box spanned by (3,4,0), (-4,3,0), (0,0,5) (extents 1), and a segment along z at
// x = 7: touching its vertex (7, 1, z) exactly, and one ulp past it.
void parallelepiped() {
    const boxcyl::Parallelepiped<double> p{{0, 0, 0}, {{{3, 4, 0}, {-4, 3, 0}, {0, 0, 5}}}, {1, 1, 1}};
    const boxcyl::Cylinder<double> touching{{7, 1, 0}, {0, 0, 1}, 0, 2};
    const boxcyl::Cylinder<double> apart{{std::nextafter(7.0, 8.0), 1, 0}, {0, 0, 1}, 0, 2};
    check(boxcyl::intersects(p, touching) && !boxcyl::intersects(p, apart), "parallelepiped query");
    const std::vector<boxcyl::Parallelepiped<double>> many{p, p};
    bool out[2] = {};
    boxcyl::batch::intersects(touching, std::span<const boxcyl::Parallelepiped<double>>(many), std::span<bool>(out));
    check(out[0] && out[1], "batch of parallelepipeds");
    const boxcyl::Cylinder<double> near{{8, 1, 0}, {0, 0, 1}, 0, 2};  // the vertex (7, 1, z) exactly 1 away
    boxcyl::batch::within_distance(near, std::span<const boxcyl::Parallelepiped<double>>(many), 1.0, std::span<bool>(out));
    check(out[0] && out[1], "batch::within_distance of parallelepipeds at the margin");
    boxcyl::batch::within_distance(near, std::span<const boxcyl::Parallelepiped<double>>(many), std::nextafter(1.0, 0.0),
                                   std::span<bool>(out));
    check(!out[0] && !out[1], "batch::within_distance of parallelepipeds one ulp below the margin");
}

void grid() {
    const boxcyl::Grid g{{0, 0, 0}, {1, 1, 1}, {4, 4, 4}};
    const boxcyl::Cylinder<double> segment{{1, 2, 2}, {1, 0, 0}, 0, 1};
    const std::vector<boxcyl::CellIndex> cells = boxcyl::cells(g, segment);
    const std::vector<boxcyl::CellIndex> expected{{0, 1, 1}, {0, 1, 2}, {0, 2, 1}, {0, 2, 2},
                                                  {1, 1, 1}, {1, 1, 2}, {1, 2, 1}, {1, 2, 2}};
    check(cells == expected, "grid cells");
    int count = 0;
    boxcyl::for_each_cell(g, segment, [&](std::int64_t, std::int64_t, std::int64_t) { ++count; });
    check(count == 8, "grid for_each_cell");
    check(boxcyl::validate(g).ok(), "validate(grid)");
}

}  // namespace

int main() {
    scalar<double>("double");
    scalar<float>("float");
    batch<double>();
    batch<float>();
    grid();
    parallelepiped();
    const boxcyl::Cylinder<double> bad{{0, 0, 0}, {0, 0, 1}, -1, 1};
    check(boxcyl::validate(bad).message() == "cylinder.radius: is negative", "validate() named the wrong field");
#ifdef EXPECTED_VERSION
    check(std::strcmp(BOXCYL_VERSION_STRING, EXPECTED_VERSION) == 0, "header and package versions differ");
#endif
    std::printf("boxcyl %s compiled-library consumer: %s\n", BOXCYL_VERSION_STRING, failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
