// The same box–cylinder queries through peer collision libraries: FCL's GJK, Bullet's GJK
// pair detector and ODE's dCollide, from Debian's packages. Built only with -DBOXCYL_BENCH_PEERS=ON
// (bench/CMakeLists.txt); bench_query.cpp times them beside boxcyl's queries in the same run.
//
// Each library gets the queries converted once, untimed, into its own shapes and transforms (so the
// timed loop is the library's narrow-phase call alone, which favours the peers: boxcyl's times
// include its own reduction to the canonical frame). See peers.cpp for the mapping of each query.
#pragma once

#include <cstddef>  // std::size_t
#include <memory>   // std::unique_ptr
#include <vector>   // the queries

#include "support/cases.hpp"

namespace boxcyl::bench {

enum class Peer { fcl_libccd, fcl_indep, bullet, ode };

struct PeerInfo {
    Peer peer;
    const char* key;    // benchmark name part
    const char* label;  // summary row
};

inline constexpr PeerInfo kPeers[] = {
    {Peer::fcl_libccd, "fcl_libccd", "FCL collide(), GJK solver GST_LIBCCD (FCL's default)"},
    {Peer::fcl_indep, "fcl_indep", "FCL collide(), GJK solver GST_INDEP"},
    {Peer::bullet, "bullet_gjk", "Bullet btGjkPairDetector (GJK + EPA, margins 0)"},
    {Peer::ode, "ode", "ODE dCollide (box–cylinder)"},
};

// One data set's queries in one peer library's representation.
class PeerQueries {
public:
    PeerQueries(Peer peer, const std::vector<boxcyl::testing::Case>& cases);
    ~PeerQueries();
    PeerQueries(const PeerQueries&) = delete;
    PeerQueries& operator=(const PeerQueries&) = delete;

    // Whether the library reports that query i's box and cylinder intersect.
    bool answer(std::size_t i) const;
    // Answers queries 0 … n−1 in order (the timed pass), except failed ones; returns how many intersect.
    long pass(std::size_t n) const;
    // Whether the library failed on query i when it was first tried (ODE's internal assertions): its
    // answer counts as false, and the timed passes leave it out.
    bool failed(std::size_t i) const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace boxcyl::bench
