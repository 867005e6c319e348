// Where the batch's undecided lanes go (docs/performance.md): for bench_batch's near-surface
// sets (the same 32 mixed cylinders × 2048 aligned and 2048 oriented boxes), every box that the SIMD
// filter leaves to the scalar exact default, by the cylinder's shape (segment r = 0, disk h = 0,
// regular), by the answer, and by the scalar stage that decides it (0: semi_static, 0b:
// witness_search, 1: certified linear inequalities, thorough hit search, exact). Counts only — deterministic, the same
// on every machine and kernel (each lane is decided on its own); bench_batch times them.
// Run: build-batch/bench/batch_census
#include <cstdint>  // seeds
#include <cstdio>   // the table
#include <span>     // one box per call
#include <vector>   // the sets

#include "boxcyl/batch.hpp"
#include "boxcyl/filtered.hpp"
#include "support/batch_cases.hpp"

namespace {

using namespace boxcyl;

enum Stage { stage0, stage0b, stage1, thorough, exact, stages };
constexpr const char* stage_names[stages] = {"stage 0", "stage 0b", "stage 1", "thorough", "exact"};

template <class Box>
Stage deciding_stage(const Box& b, const Cylinder<double>& c) {
    filtered::semi_static::Problem p;
    const bool in_range = filtered::semi_static::problem(b, c, p);
    if (in_range && filtered::semi_static::decide(p, b, c)) return stage0;
    if (in_range && filtered::witness_search::decide(p, b, c)) return stage0b;
    if (filtered::detail::filter(b, c)) return stage1;
    if (in_range && filtered::witness_search::certain_hit(p, b, c)) return thorough;
    return exact;
}

struct Census {
    long boxes = 0, left = 0;
    long by[3][2][stages] = {};  // shape × answer × stage
    void add(const Cylinder<double>& c, bool hit, Stage s) {
        ++left;
        ++by[c.radius == 0 ? 0 : c.height == 0 ? 1 : 2][hit ? 1 : 0][s];
    }
    void print(const char* kind) const {
        std::printf("%s boxes: %ld, left by the SIMD filter: %ld (%.2f%%)\n", kind, boxes, left, 100.0 * double(left) / double(boxes));
        std::printf("  %-16s %8s %8s %8s %8s %8s\n", "shape, answer", stage_names[0], stage_names[1], stage_names[2],
                    stage_names[3], stage_names[4]);
        const char* shapes[3] = {"segment", "disk", "regular"};
        for (int a = 0; a < 3; ++a)
            for (int h = 0; h < 2; ++h) {
                std::printf("  %-8s %-7s", shapes[a], h ? "hit" : "miss");
                for (int s = 0; s < stages; ++s) std::printf(" %8ld", by[a][h][s]);
                std::printf("\n");
            }
    }
};

}  // namespace

int main() {
    Census aligned, oriented;
    std::vector<std::uint64_t> mask(1);
    for (std::uint64_t seed = 0xBE7C0000; seed < 0xBE7C0000 + 32; ++seed) {  // bench_batch's mixed sets
        const testing::BatchSet s = testing::random_batch(seed, 2048);
        for (const AlignedBox<double>& b : s.aligned) {
            const double lo[3] = {b.min[0], b.min[1], b.min[2]}, hi[3] = {b.max[0], b.max[1], b.max[2]};
            const batch::AlignedBoxes<double> one{std::span(lo, 1), std::span(lo + 1, 1), std::span(lo + 2, 1),
                                                  std::span(hi, 1), std::span(hi + 1, 1), std::span(hi + 2, 1)};
            ++aligned.boxes;
            if (batch::intersects(s.cylinder, one, std::span<std::uint64_t>(mask)).exact_lanes != 0)
                aligned.add(s.cylinder, mask[0] != 0, deciding_stage(b, s.cylinder));
        }
        for (const OrientedBox<double>& b : s.oriented) {
            ++oriented.boxes;
            if (batch::intersects(s.cylinder, std::span<const OrientedBox<double>>(&b, 1), std::span<std::uint64_t>(mask))
                    .exact_lanes != 0)
                oriented.add(s.cylinder, mask[0] != 0, deciding_stage(b, s.cylinder));
        }
    }
    aligned.print("aligned");
    oriented.print("oriented");
}
