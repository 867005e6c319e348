// libFuzzer target: the default (exact, filtered) query against the exact oracle. The bytes are decoded
// (fuzz/decode.hpp) into one aligned or oriented box and one cylinder; inputs that boxcyl::validate()
// rejects are skipped, every other one must get the oracle's answer from boxcyl::intersects(box, cyl).
#include <cstddef>  // std::size_t
#include <cstdint>  // std::uint8_t
#include <cstdio>   // std::fprintf
#include <cstdlib>  // std::abort
#include <string>   // failure messages

#include "boxcyl/query.hpp"
#include "decode.hpp"

namespace {

[[noreturn]] void report(const char* kind, bool got, bool want, const char* text) {
    std::fprintf(stderr, "fuzz_query: %s box: default query says %d, oracle %d\n%s\n", kind, got, want, text);
    std::abort();
}

constexpr boxcyl::QueryOptions oracle{boxcyl::Algorithm::oracle, boxcyl::Arithmetic::exact};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace boxcyl::fuzz;
    Decoder d(data, size);
    const bool is_oriented = d.byte() & 1;
    const boxcyl::Cylinder<double> cyl = cylinder(d);
    if (!boxcyl::validate(cyl).ok()) return 0;
    if (is_oriented) {
        const boxcyl::OrientedBox<double> box = oriented_box(d);
        if (!boxcyl::validate(box).ok()) return 0;
        const bool got = boxcyl::intersects(box, cyl), want = boxcyl::intersects(box, cyl, oracle);
        if (got != want) report("oriented", got, want, (show(box) + ", " + describe(cyl)).c_str());
    } else {
        const boxcyl::AlignedBox<double> box = aligned_box(d);
        if (!boxcyl::validate(box).ok()) return 0;
        const bool got = boxcyl::intersects(box, cyl), want = boxcyl::intersects(box, cyl, oracle);
        if (got != want) report("aligned", got, want, (show(box) + ", " + describe(cyl)).c_str());
    }
    return 0;
}
