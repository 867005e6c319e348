// The same box–cylinder queries through peer collision libraries: FCL's GJK, Bullet's GJK
// pair detector, ODE's dCollide and (for the clearance question and the distance) MuJoCo's collision
// with a contact margin, from Debian's packages. Built only with -DBOXCYL_BENCH_PEERS=ON
// (bench/CMakeLists.txt); bench_query.cpp times them beside boxcyl's queries in the same run,
// bench_clearance.cpp the clearance question (within a distance m?) beside within_distance, and
// bench_distance.cpp their distances and signed distances beside distance and signed_distance.
//
// Each library gets the queries converted once, untimed, into its own shapes and transforms (so the
// timed loop is the library's narrow-phase call alone, which favours the peers: boxcyl's times
// include its own reduction to the canonical frame). See peers.cpp for the mapping of each query.
#pragma once

#include <algorithm>  // std::max
#include <cstddef>    // std::size_t
#include <memory>     // std::unique_ptr
#include <optional>   // a peer's distance, when it gives one
#include <vector>     // the queries

#include "support/cases.hpp"

namespace boxcyl::bench {

// "Small" queries, where the peers' absolute tolerances (FCL's default gjk_tolerance 1e-6, …) are
// no longer small: every length of the query (box sides, cylinder diameter and height) is below this.
inline constexpr double kSmallSize = 0.01;

inline double query_size(const boxcyl::testing::Case& c) {
    using boxcyl::testing::BoxKind;
    double m = std::max(2 * c.cylinder.radius, c.cylinder.height);
    for (int i = 0; i < 3; ++i) {
        switch (c.kind) {
            case BoxKind::aligned: m = std::max(m, c.aligned.max[i] - c.aligned.min[i]); break;
            case BoxKind::oriented: m = std::max(m, 2 * c.oriented.extents[i]); break;
            case BoxKind::canonical: m = std::max(m, 2 * c.canonical.extents[i]); break;
        }
    }
    return m;
}

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

// The clearance question (is the box within distance m of the cylinder?) as each library can ask it.
// FCL 0.7's CollisionRequest has no security margin (Coal's has), and ODE has neither a margin nor a
// box–cylinder distance, so those are distance queries compared with m. MuJoCo has a margin of its
// own: a contact "if dist < margin".
enum class ClearancePeer { fcl_libccd, fcl_indep, bullet_gjk, bullet_gjkepa2, mujoco };

struct ClearancePeerInfo {
    ClearancePeer peer;
    const char* key;
    const char* label;
};

inline constexpr ClearancePeerInfo kClearancePeers[] = {
    {ClearancePeer::fcl_libccd, "fcl_distance_libccd", "FCL distance() ≤ m, solver GST_LIBCCD (FCL's default)"},
    {ClearancePeer::fcl_indep, "fcl_distance_indep", "FCL distance() ≤ m, solver GST_INDEP"},
    {ClearancePeer::bullet_gjk, "bullet_gjk_distance", "Bullet btGjkPairDetector distance ≤ m (margins 0)"},
    {ClearancePeer::bullet_gjkepa2, "bullet_gjkepa2_distance", "Bullet btGjkEpaSolver2::Distance ≤ m (margins 0)"},
    {ClearancePeer::mujoco, "mujoco_margin", "MuJoCo mj_collision, the box geom's margin m (contact: distance < m)"},
};

// One data set's queries in one peer library's representation.
class PeerQueries {
public:
    PeerQueries(Peer peer, const std::vector<boxcyl::testing::Case>& cases);
    // The clearance question: query i asks whether its box is within margins[i] of its cylinder.
    PeerQueries(ClearancePeer peer, const std::vector<boxcyl::testing::Case>& cases, const std::vector<double>& margins);
    ~PeerQueries();
    PeerQueries(const PeerQueries&) = delete;
    PeerQueries& operator=(const PeerQueries&) = delete;

    // Whether the library reports that query i's box and cylinder intersect (clearance: are within its margin).
    bool answer(std::size_t i) const;
    // Answers queries 0 … n−1 in order (the timed pass), except failed ones; returns how many say yes.
    long pass(std::size_t n) const;
    // Whether the library failed on query i when it was first tried (ODE's internal assertions): its
    // answer counts as false, and the timed passes leave it out.
    bool failed(std::size_t i) const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

// The signed distance (the distance, or minus the penetration depth where the solids overlap) as each
// library computes it (bench_distance.cpp's overlapping sets): FCL's distance() with
// enable_signed_distance (GST_LIBCCD; GST_INDEP's aborts on overlapping shapes, so its two steps, the
// distance and collide()'s contact depth, by hand: peers.cpp), btGjkPairDetector's distance (EPA's
// depth, negated, where they overlap) and btGjkEpaSolver2::SignedDistance.
enum class SignedPeer { fcl_libccd, fcl_indep, bullet_gjk, bullet_gjkepa2 };

struct SignedPeerInfo {
    SignedPeer peer;
    const char* key;
    const char* label;
};

inline constexpr SignedPeerInfo kSignedPeers[] = {
    {SignedPeer::fcl_libccd, "fcl_signed_distance_libccd", "FCL distance(), enable_signed_distance, GST_LIBCCD (FCL's default)"},
    {SignedPeer::fcl_indep, "fcl_signed_distance_indep", "FCL distance() then collide()'s contact depth, GST_INDEP"},
    {SignedPeer::bullet_gjk, "bullet_gjk_signed_distance", "Bullet btGjkPairDetector (GJK + EPA, margins 0)"},
    {SignedPeer::bullet_gjkepa2, "bullet_gjkepa2_signed_distance", "Bullet btGjkEpaSolver2::SignedDistance (margins 0)"},
};

// Whether the clearance peer has a distance call: MuJoCo 2.2 has none (its contacts under a margin
// carry a `dist`, but under a margin far beyond the distance that is not the distance).
constexpr bool has_distance(ClearancePeer p) { return p != ClearancePeer::mujoco; }

// The distance itself as each clearance peer computes it (bench_distance.cpp): FCL's distance() (its
// defaults: distance_tolerance 1e-6, no nearest points), btGjkPairDetector's and btGjkEpaSolver2's.
// None when the library gives none (Bullet's GJK gave up; btGjkEpaSolver2 says "not separated").
// Or the signed distance as each signed peer computes it: none when Bullet's GJK or EPA gave up, FCL
// gave no contact, or the query ends the process (FCL's assertions: tried once, untimed, in a child process).
class PeerDistances {
public:
    PeerDistances(ClearancePeer peer, const std::vector<boxcyl::testing::Case>& cases);
    PeerDistances(SignedPeer peer, const std::vector<boxcyl::testing::Case>& cases);
    ~PeerDistances();
    PeerDistances(const PeerDistances&) = delete;
    PeerDistances& operator=(const PeerDistances&) = delete;

    std::optional<double> distance(std::size_t i) const;
    // Whether query i ends the process (none, and left out of the timed passes).
    bool failed(std::size_t i) const;
    // Distances 0 … n−1 in order (the timed pass), except failed ones; returns their sum.
    double pass(std::size_t n) const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace boxcyl::bench
