// The batch distance queries, boxcyl::batch::distance, distance_within and signed_distance
// (boxcyl/batch/distance.hpp), against the scalar boxcyl::distance and signed_distance, bit for bit: random sets around CaseGenerator cylinders for every
// box layout (six arrays, AlignedBox rows, OrientedBox, Parallelepiped), double and float, over threads;
// distance_within gives the scalar distance to the boxes within the margin and [margin, +∞] to the
// others (which the scalar distance must put beyond it); invalid input, short outputs and the stop.
#include <gtest/gtest.h>

#include <bit>         // std::bit_cast: answers compared bit for bit
#include <cmath>       // std::isnan
#include <cstddef>     // std::size_t
#include <cstdint>     // std::uint64_t
#include <limits>      // infinity
#include <stdexcept>   // std::invalid_argument
#include <stop_token>  // Options::stop
#include <string>      // labels
#include <vector>      // the sets

#include "boxcyl/batch.hpp"
#include "boxcyl/distance.hpp"
#include "boxcyl/signed_distance.hpp"
#include "support/batch_cases.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same(const Distance& a, const Distance& b) {
    for (int k = 0; k < 3; ++k)
        if (!same(a.on_box[k], b.on_box[k]) || !same(a.on_cylinder[k], b.on_cylinder[k])) return false;
    return same(a.lower, b.lower) && same(a.upper, b.upper);
}

bool same(const SignedDistance& a, const SignedDistance& b) {
    for (int k = 0; k < 3; ++k)
        if (!same(a.normal[k], b.normal[k]) || !same(a.on_box[k], b.on_box[k]) || !same(a.on_cylinder[k], b.on_cylinder[k]))
            return false;
    return same(a.lower, b.lower) && same(a.upper, b.upper);
}

// The scalar answer of the query whose batch answers `out` holds: distance or signed_distance.
template <class Box>
Distance scalar(const Box& b, const Cylinder<double>& cyl, const Distance&) {
    return distance(b, cyl);
}
template <class Box>
SignedDistance scalar(const Box& b, const Cylinder<double>& cyl, const SignedDistance&) {
    return signed_distance(b, cyl);
}

template <class Box, class Out>
void expect_scalar(const Cylinder<double>& cyl, const std::vector<Box>& boxes, const std::vector<Out>& out,
                   const std::string& label) {
    int bad = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (!same(out[i], scalar(boxes[i], cyl, out[i])) && ++bad <= 3) ADD_FAILURE() << label << ": box " << i;
    EXPECT_EQ(bad, 0) << label;
}

AlignedBox<float> narrowed(const AlignedBox<double>& b) {
    AlignedBox<float> f;
    for (int k = 0; k < 3; ++k) {
        f.min[k] = static_cast<float>(b.min[k]);
        f.max[k] = std::max(f.min[k], static_cast<float>(b.max[k]));
    }
    return f;
}

// Every layout of s's boxes through `call(cyl, boxes, out, options)` (a batch query whose answers are
// Out), over 1 and 3 threads, each answer bit for bit the scalar query's; the aligned rows' answers
// are returned for the caller's own checks.
template <class Out, class Call>
std::vector<Out> expect_every_layout(const BatchSet& s, Call call) {
    const Cylinder<double>& cyl = s.cylinder;
    std::vector<Out> first;
    for (unsigned threads : {1u, 3u}) {
        const batch::Options opt{threads};
        const std::string t = " (threads " + std::to_string(threads) + ")";
        std::vector<Out> out(s.aligned.size());
        const batch::Stats st = call(cyl, std::span<const AlignedBox<double>>(s.aligned), std::span<Out>(out), opt);
        expect_scalar(cyl, s.aligned, out, "aligned rows" + t);
        EXPECT_EQ(st.boxes, s.aligned.size());
        EXPECT_EQ(st.exact_lanes, s.aligned.size());
        if (first.empty()) first = out;

        std::vector<double> min_x, min_y, min_z, max_x, max_y, max_z;
        for (const AlignedBox<double>& b : s.aligned) {
            min_x.push_back(b.min[0]), min_y.push_back(b.min[1]), min_z.push_back(b.min[2]);
            max_x.push_back(b.max[0]), max_y.push_back(b.max[1]), max_z.push_back(b.max[2]);
        }
        std::vector<Out> soa(s.aligned.size());
        call(cyl, batch::AlignedBoxes<double>{min_x, min_y, min_z, max_x, max_y, max_z}, std::span<Out>(soa), opt);
        expect_scalar(cyl, s.aligned, soa, "aligned arrays" + t);

        std::vector<Out> oriented(s.oriented.size());
        call(cyl, std::span<const OrientedBox<double>>(s.oriented), std::span<Out>(oriented), opt);
        expect_scalar(cyl, s.oriented, oriented, "oriented" + t);

        std::vector<Parallelepiped<double>> pp;
        for (const OrientedBox<double>& o : s.oriented) pp.push_back({o.center, o.axes, o.extents});
        std::vector<Out> ppd(pp.size());
        call(cyl, std::span<const Parallelepiped<double>>(pp), std::span<Out>(ppd), opt);
        expect_scalar(cyl, pp, ppd, "parallelepipeds" + t);

        std::vector<AlignedBox<float>> fl;
        std::vector<AlignedBox<double>> widened;
        for (const AlignedBox<double>& b : s.aligned) {
            fl.push_back(narrowed(b));
            widened.push_back({{fl.back().min[0], fl.back().min[1], fl.back().min[2]},
                               {fl.back().max[0], fl.back().max[1], fl.back().max[2]}});
        }
        std::vector<Out> fd(fl.size());
        call(cyl, std::span<const AlignedBox<float>>(fl), std::span<Out>(fd), opt);
        expect_scalar(cyl, widened, fd, "float rows" + t);
    }
    return first;
}

TEST(BatchDistance, EveryLayoutEqualsTheScalarQuery) {
    for (std::uint64_t seed : {0xba7d0001u, 0xba7d0002u, 0xba7d0003u})
        expect_every_layout<Distance>(random_batch(seed, 300), [](const auto& c, const auto& b, auto out, const auto& o) {
            return batch::distance(c, b, out, o);
        });
}

TEST(BatchSignedDistance, EveryLayoutEqualsTheScalarQuery) {
    const std::vector<SignedDistance> out = expect_every_layout<SignedDistance>(
        random_batch(0xba7d0201, 160),
        [](const auto& c, const auto& b, auto out, const auto& o) { return batch::signed_distance(c, b, out, o); });
    std::size_t overlapping = 0;
    for (const SignedDistance& d : out) overlapping += d.upper < 0;
    EXPECT_GT(overlapping, 0u) << "the set has overlapping pairs";
    EXPECT_LT(overlapping, out.size()) << "and pairs apart";
}

TEST(BatchDistance, WithinAMarginOnlyTheNearOnes) {
    const BatchSet s = random_batch(0xba7d0100, 400);
    const Cylinder<double>& cyl = s.cylinder;
    const double m = 0.25 * (cyl.radius + cyl.height) + 0x1p-1000;
    std::vector<Distance> out(s.aligned.size());
    const batch::Stats st = batch::distance_within(cyl, std::span<const AlignedBox<double>>(s.aligned), m,
                                                   std::span<Distance>(out), batch::Options{2});
    std::size_t near = 0;
    for (std::size_t i = 0; i < s.aligned.size(); ++i) {
        const Distance d = distance(s.aligned[i], cyl);
        if (within_distance(s.aligned[i], cyl, m)) {
            ++near;
            EXPECT_TRUE(same(out[i], d)) << "box " << i;
        } else {
            EXPECT_EQ(out[i].lower, m) << "box " << i;
            EXPECT_EQ(out[i].upper, std::numeric_limits<double>::infinity()) << "box " << i;
            EXPECT_TRUE(std::isnan(out[i].on_box[0]) && std::isnan(out[i].on_cylinder[2])) << "box " << i;
            EXPECT_GT(d.upper, m) << "box " << i;  // the scalar enclosure agrees: beyond the margin
        }
    }
    EXPECT_EQ(st.exact_lanes, near);
    EXPECT_GT(near, 0u);
    EXPECT_LT(near, s.aligned.size());
}

TEST(BatchDistance, RefusesWhatItCannotAnswer) {
    const std::vector<AlignedBox<double>> boxes{{{0, 0, 0}, {1, 1, 1}}, {{2, 0, 0}, {1, 1, 1}}};  // the second: min > max
    const Cylinder<double> cyl{{3, 0, 0}, {0, 0, 1}, 1, 1};
    std::vector<Distance> out(2);
    batch::Options checked;
    checked.check_boxes = true;
    EXPECT_THROW(batch::distance(cyl, std::span<const AlignedBox<double>>(boxes), std::span<Distance>(out), checked),
                 batch::InvalidBox);
    std::vector<Distance> short_out(1);
    EXPECT_THROW(batch::distance(cyl, std::span<const AlignedBox<double>>(boxes), std::span<Distance>(short_out)),
                 std::invalid_argument);
    const Cylinder<double> no_axis{{3, 0, 0}, {0, 0, 0}, 1, 1};
    EXPECT_THROW(batch::distance(no_axis, std::span<const AlignedBox<double>>(boxes), std::span<Distance>(out)),
                 std::invalid_argument);
    EXPECT_THROW(batch::distance_within(cyl, std::span<const AlignedBox<double>>(boxes), -1.0, std::span<Distance>(out)),
                 std::invalid_argument);
    std::stop_source stop;
    stop.request_stop();
    batch::Options stopped;
    stopped.stop = stop.get_token();
    EXPECT_THROW(batch::distance(cyl, std::span<const AlignedBox<double>>(boxes), std::span<Distance>(out), stopped),
                 batch::Stopped);

    std::vector<SignedDistance> sd(2), short_sd(1);
    EXPECT_THROW(batch::signed_distance(cyl, std::span<const AlignedBox<double>>(boxes), std::span<SignedDistance>(sd), checked),
                 batch::InvalidBox);
    EXPECT_THROW(batch::signed_distance(cyl, std::span<const AlignedBox<double>>(boxes), std::span<SignedDistance>(short_sd)),
                 std::invalid_argument);
    EXPECT_THROW(batch::signed_distance(no_axis, std::span<const AlignedBox<double>>(boxes), std::span<SignedDistance>(sd)),
                 std::invalid_argument);
    EXPECT_THROW(batch::signed_distance(cyl, std::span<const AlignedBox<double>>(boxes), std::span<SignedDistance>(sd), stopped),
                 batch::Stopped);
}

}  // namespace
}  // namespace boxcyl
