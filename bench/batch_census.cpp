// Where the batch's undecided lanes go (docs/performance.md): for bench_batch's near-surface
// sets (the same 32 mixed cylinders × 2048 aligned and 2048 oriented boxes), every box that the SIMD
// filter leaves to the scalar exact default, by the cylinder's shape (segment r = 0, disk h = 0,
// regular), by the answer, and by the pipeline row that decides it (filtered::Stats). Counts only — deterministic, the same
// on every machine and kernel (each lane is decided on its own); bench_batch times them.
// Run: build-batch/bench/batch_census
#include <cstdint>  // seeds
#include <cstdio>   // the table
#include <span>     // one box per call
#include <string>   // row names
#include <vector>   // the sets

#include "boxcyl/batch.hpp"
#include "boxcyl/filtered.hpp"
#include "support/batch_cases.hpp"

namespace {

using namespace boxcyl;

// The pipeline row that decides a query (filtered::Stats of that one query).
template <class Box>
filtered::RowId deciding_row(const Box& b, const Cylinder<double>& c) {
    filtered::Stats one;
    filtered::query(b, c, one);
    for (std::size_t i = 0; i < filtered::row_count; ++i)
        if (one.rows[i].hits + one.rows[i].misses > 0) return static_cast<filtered::RowId>(i);
    return filtered::RowId::exact;
}

struct Census {
    long boxes = 0, left = 0;
    long by[3][2][filtered::row_count] = {};  // shape × answer × row
    void add(const Cylinder<double>& c, bool hit, filtered::RowId r) {
        ++left;
        ++by[c.radius == 0 ? 0 : c.height == 0 ? 1 : 2][hit ? 1 : 0][static_cast<std::size_t>(r)];
    }
    void print(const char* kind) const {
        std::printf("%s boxes: %ld, left by the SIMD filter: %ld (%.2f%%)\n", kind, boxes, left, 100.0 * double(left) / double(boxes));
        const char* shapes[3] = {"segment", "disk", "regular"};
        for (std::size_t r = 0; r < filtered::row_count; ++r) {
            long any = 0;
            for (int a = 0; a < 3; ++a) any += by[a][0][r] + by[a][1][r];
            if (any == 0) continue;
            std::printf("  %-26s", std::string(filtered::name(static_cast<filtered::RowId>(r))).c_str());
            for (int a = 0; a < 3; ++a)
                for (int h = 0; h < 2; ++h) std::printf(" %s %s %6ld", shapes[a], h ? "hit" : "miss", by[a][h][r]);
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
                aligned.add(s.cylinder, mask[0] != 0, deciding_row(b, s.cylinder));
        }
        for (const OrientedBox<double>& b : s.oriented) {
            ++oriented.boxes;
            if (batch::intersects(s.cylinder, std::span<const OrientedBox<double>>(&b, 1), std::span<std::uint64_t>(mask))
                    .exact_lanes != 0)
                oriented.add(s.cylinder, mask[0] != 0, deciding_row(b, s.cylinder));
        }
    }
    aligned.print("aligned");
    oriented.print("oriented");
}
