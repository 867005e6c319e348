// The front door, boxcyl::intersects (include/boxcyl/query.hpp): the default call is the filtered exact
// query itself — same answers, and no exact arithmetic unless the filter leaves the query undecided.
// The second property is what users pay for: converting the inputs to GMP rationals costs about ten
// times the filter, and an earlier front door did so on every call (1.2 µs per query instead of
// 0.13 µs on the benchmark's random set). It is checked by counting GMP's allocations, not by timing.
#include <gtest/gtest.h>

#include <gmp.h>

#include <cstddef>  // std::size_t
#include <cstdio>   // std::printf

#include "boxcyl/query.hpp"
#include "support/cases.hpp"

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

// GMP's allocations while a counter is installed (GMP allows replacing its memory functions when no
// GMP object is alive across the switch; the counters are installed and removed around plain calls).
struct GmpAllocationCounter {
    static inline long count = 0;
    static inline void* (*alloc)(std::size_t) = nullptr;
    static inline void* (*realloc)(void*, std::size_t, std::size_t) = nullptr;
    static inline void (*release)(void*, std::size_t) = nullptr;

    GmpAllocationCounter() {
        mp_get_memory_functions(&alloc, &realloc, &release);
        count = 0;
        mp_set_memory_functions(
            [](std::size_t n) { ++count; return alloc(n); },
            [](void* p, std::size_t old_size, std::size_t n) { ++count; return realloc(p, old_size, n); },
            [](void* p, std::size_t n) { release(p, n); });
    }
    ~GmpAllocationCounter() { mp_set_memory_functions(alloc, realloc, release); }
    GmpAllocationCounter(const GmpAllocationCounter&) = delete;
    GmpAllocationCounter& operator=(const GmpAllocationCounter&) = delete;
};

template <class F>
long gmp_allocations(F&& f) {
    const GmpAllocationCounter counter;
    f();
    return GmpAllocationCounter::count;
}

bool front_door(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return intersects(box, cyl); });
}
filtered::Result filtered_query(const Case& c) {
    return with_box(c, [](const auto& box, const Cylinder<double>& cyl) { return filtered::query(box, cyl); });
}

TEST(FrontDoor, DefaultIsTheFilteredQueryWithoutExactArithmetic) {
    constexpr std::uint64_t seed = 0xf00d0001;
    CaseGenerator gen(seed);
    long decided = 0, fallbacks = 0, fallback_allocations = 0;
    for (int i = 0; i < 4000; ++i) {
        const Case c = gen.next();
        const filtered::Result want = filtered_query(c);
        bool got = false;
        const long allocations = gmp_allocations([&] { got = front_door(c); });
        ASSERT_EQ(got, want.intersect) << "seed " << std::hex << seed << std::dec << " case " << i << ": " << describe(c);
        if (want.exact_used) {
            ++fallbacks;
            fallback_allocations += allocations;
        } else {
            ++decided;
            ASSERT_EQ(allocations, 0) << "the filter decides this query, yet the front door used GMP: seed " << std::hex
                                      << seed << std::dec << " case " << i << ": " << describe(c);
        }
    }
    std::printf("[ info ] %ld queries decided without GMP, %ld exact fallbacks (%ld GMP allocations)\n", decided,
                fallbacks, fallback_allocations);
    EXPECT_GT(decided, 3900);
}

// The counter's teeth: exact arithmetic through the same door does allocate.
TEST(FrontDoor, ExactArithmeticIsCounted) {
    const Case c = CaseGenerator(0xf00d0002).next();
    const long exact = gmp_allocations([&] {
        const QueryOptions opt{Algorithm::inequalities, Arithmetic::exact};
        switch (c.kind) {
            case BoxKind::aligned: (void)intersects(c.aligned, c.cylinder, opt); break;
            case BoxKind::oriented: (void)intersects(c.oriented, c.cylinder, {Algorithm::hull, Arithmetic::exact}); break;
            case BoxKind::canonical: (void)intersects(c.canonical, c.cylinder, opt); break;
        }
    });
    EXPECT_GT(exact, 0);
    EXPECT_GT(gmp_allocations([&] { (void)oracle_answer(c); }), 0);
}

// Explicit options that mean the default take the same path.
TEST(FrontDoor, ExplicitDefaultOptionsAreTheDefault) {
    CaseGenerator gen(0xf00d0003);
    for (int i = 0; i < 500; ++i) {
        const Case c = gen.next();
        if (c.kind != BoxKind::aligned) continue;
        const QueryOptions opt{Algorithm::inequalities, Arithmetic::filtered};
        bool got = false;
        const long allocations = gmp_allocations([&] { got = intersects(c.aligned, c.cylinder, opt); });
        const filtered::Result want = filtered::query(c.aligned, c.cylinder);
        ASSERT_EQ(got, want.intersect) << describe(c);
        if (!want.exact_used) {
            ASSERT_EQ(allocations, 0) << describe(c);
        }
    }
}

// float inputs are converted exactly to double and take the same path.
TEST(FrontDoor, FloatInputsTakeTheFilteredPath) {
    const AlignedBox<float> box{{0, 0, 0}, {1, 1, 1}};
    const Cylinder<float> touching{{2.5F, 0.5F, 0.5F}, {0, 0, 1}, 1.5F, 1};  // touches the face x = 1
    const Cylinder<float> apart{{2.5F, 0.5F, 0.5F}, {0, 0, 1}, 1.25F, 1};
    bool hit = false, miss = true;
    EXPECT_EQ(gmp_allocations([&] { miss = intersects(box, apart); }), 0);
    EXPECT_FALSE(miss);
    (void)gmp_allocations([&] { hit = intersects(box, touching); });
    EXPECT_TRUE(hit);
}

}  // namespace
}  // namespace boxcyl
