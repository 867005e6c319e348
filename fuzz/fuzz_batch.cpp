// libFuzzer target: the batch API (boxcyl/batch.hpp) against the scalar default query, box by box. The
// bytes are decoded (fuzz/decode.hpp) into one cylinder and then boxes until the bytes run out (at
// most 40; each led by a byte whose low bit chooses aligned or oriented); boxes that validate()
// rejects are skipped. Both batches (aligned as six arrays, oriented as structs) must give, for every
// box, the answer of boxcyl::intersects(box, cyl) — which fuzz_query checks against the oracle — so
// this target probes the SIMD filter's certificates (its first pass included) where rounding and
// range are hardest.
#include <cstddef>  // std::size_t
#include <cstdint>  // std::uint8_t, std::uint64_t
#include <cstdio>   // std::fprintf
#include <cstdlib>  // std::abort
#include <span>     // batch inputs and outputs
#include <string>   // failure messages
#include <vector>   // the boxes

#include "boxcyl/batch.hpp"
#include "boxcyl/query.hpp"
#include "decode.hpp"

namespace {

[[noreturn]] void report(const std::string& box, const boxcyl::Cylinder<double>& cyl, bool got, bool want) {
    std::fprintf(stderr, "fuzz_batch: batch says %d, scalar default %d\n%s, %s\n", got, want, box.c_str(),
                 boxcyl::fuzz::describe(cyl).c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace boxcyl::fuzz;
    Decoder d(data, size);
    const boxcyl::Cylinder<double> cyl = cylinder(d);
    if (!boxcyl::validate(cyl).ok()) return 0;
    std::vector<boxcyl::AlignedBox<double>> aligned;
    std::vector<boxcyl::OrientedBox<double>> oriented;
    for (int k = 0; k < 40 && d.remaining(); ++k) {
        if (d.byte() & 1) {
            const boxcyl::OrientedBox<double> b = oriented_box(d);
            if (boxcyl::validate(b).ok()) oriented.push_back(b);
        } else {
            const boxcyl::AlignedBox<double> b = aligned_box(d);
            if (boxcyl::validate(b).ok()) aligned.push_back(b);
        }
    }
    std::vector<double> v[6];
    for (const boxcyl::AlignedBox<double>& b : aligned)
        for (std::size_t j = 0; j < 3; ++j) v[j].push_back(b.min[j]), v[3 + j].push_back(b.max[j]);
    std::vector<std::uint64_t> mask(boxcyl::batch::mask_words(aligned.size()));
    boxcyl::batch::intersects(cyl, boxcyl::batch::AlignedBoxes<double>{v[0], v[1], v[2], v[3], v[4], v[5]},
                              std::span<std::uint64_t>(mask));
    for (std::size_t i = 0; i < aligned.size(); ++i) {
        const bool got = (mask[i / 64] >> (i % 64)) & 1u, want = boxcyl::intersects(aligned[i], cyl);
        if (got != want) report(show(aligned[i]), cyl, got, want);
    }
    mask.assign(boxcyl::batch::mask_words(oriented.size()), 0);
    boxcyl::batch::intersects(cyl, std::span<const boxcyl::OrientedBox<double>>(oriented), std::span<std::uint64_t>(mask));
    for (std::size_t i = 0; i < oriented.size(); ++i) {
        const bool got = (mask[i / 64] >> (i % 64)) & 1u, want = boxcyl::intersects(oriented[i], cyl);
        if (got != want) report(show(oriented[i]), cyl, got, want);
    }
    return 0;
}
