// Peer libraries answering boxcyl's queries; see peers.hpp.
//
// Mapping of one query, the same for every library (computed in double from the same inputs):
// - box: centre, rotation R whose columns are the box axes, half extents. Aligned box: centre
//   (min + max)/2, half extents (max − min)/2, R = I (both rounded: the peers take no min/max form).
//   Canonical box: centre 0, R = I. Oriented box: its axes as given (orthonormal within rounding); a
//   left-handed frame gets its third axis negated, which leaves the box the same solid.
// - cylinder: every library's cylinder lies along its local z axis, centred at its origin. R's columns
//   are (u, v, d) with d = axis/|axis| and u, v completing a right-handed orthonormal frame; the radius
//   as given; the length is the full height (Bullet: half extents (r, r, height/2)).
// Both conversions round, so on the one-ulp boundary set a library's answer may differ from the
// oracle's for the converted inputs' sake as well as its own.
#include "peers.hpp"

#include <algorithm>  // std::copy
#include <array>      // 3×3 matrices
#include <cmath>      // std::sqrt, std::copysign, std::ilogb, std::scalbn, std::fabs
#include <cstdarg>    // va_list (ODE's message handlers)
#include <cstdio>     // std::fflush before fork()
#include <mutex>      // std::call_once
#include <optional>   // Bullet's distance, when it has one
#include <stdexcept>  // std::logic_error, std::runtime_error
#include <string>     // MuJoCo's messages
#include <utility>    // std::pair

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <ode/ode.h>

#include <mujoco/mujoco.h>

#include <fcntl.h>     // open: /dev/null for a child's stderr
#include <sys/wait.h>  // waitpid
#include <unistd.h>    // fork, _exit, alarm

#ifndef BT_USE_DOUBLE_PRECISION
#error "Bullet must be the double-precision build (Debian: bullet-float64), as the inputs are doubles"
#endif
#ifndef dDOUBLE
#error "ODE must be the double-precision build, as the inputs are doubles"
#endif

namespace boxcyl::bench {
namespace {

using boxcyl::testing::BoxKind;
using boxcyl::testing::Case;
using Mat3 = std::array<std::array<double, 3>, 3>;  // row-major: m[row][column]

// A solid placed in space: centre, rotation (local frame's axes as columns) and local dimensions.
struct Placed {
    Vec3<double> center;
    Mat3 rotation;
};

struct BoxPose : Placed {
    Vec3<double> half;  // half extents
};

struct CylinderPose : Placed {
    double radius = 0, height = 0;  // full height, along the local z axis
};

constexpr Mat3 kIdentity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

BoxPose box_pose(const Case& c) {
    BoxPose b;
    switch (c.kind) {
        case BoxKind::aligned:
            for (int i = 0; i < 3; ++i) {
                b.center[i] = 0.5 * c.aligned.min[i] + 0.5 * c.aligned.max[i];
                b.half[i] = 0.5 * (c.aligned.max[i] - c.aligned.min[i]);
            }
            b.rotation = kIdentity;
            break;
        case BoxKind::canonical:
            b.center = {0, 0, 0};
            b.half = c.canonical.extents;
            b.rotation = kIdentity;
            break;
        case BoxKind::oriented: {
            b.center = c.oriented.center;
            b.half = c.oriented.extents;
            auto a = c.oriented.axes;
            const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                               a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
            if (det < 0) a[2] = -a[2];  // a box is symmetric in each axis: same solid, a proper rotation
            for (int row = 0; row < 3; ++row)
                for (int col = 0; col < 3; ++col) b.rotation[row][col] = a[col][row];
            break;
        }
    }
    return b;
}

CylinderPose cylinder_pose(const Case& c) {
    CylinderPose p;
    p.center = c.cylinder.center;
    p.radius = c.cylinder.radius;
    p.height = c.cylinder.height;
    // Unit direction: scale by a power of two first (exact), as axis components may be subnormal.
    Vec3<double> d = c.cylinder.axis;
    const double m = std::fmax(std::fabs(d[0]), std::fmax(std::fabs(d[1]), std::fabs(d[2])));
    const int e = std::ilogb(m);
    for (int i = 0; i < 3; ++i) d[i] = std::scalbn(d[i], -e);
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int i = 0; i < 3; ++i) d[i] /= len;
    // u, v: Duff et al., "Building an orthonormal basis, revisited" (JCGT 2017); u × v = d.
    const double s = std::copysign(1.0, d[2]);
    const double a = -1.0 / (s + d[2]);
    const double b = d[0] * d[1] * a;
    const Vec3<double> u{1 + s * d[0] * d[0] * a, s * b, -s * d[0]};
    const Vec3<double> v{b, s + d[1] * d[1] * a, -d[1]};
    for (int row = 0; row < 3; ++row) {
        p.rotation[row][0] = u[row];
        p.rotation[row][1] = v[row];
        p.rotation[row][2] = d[row];
    }
    return p;
}

}  // namespace

struct PeerQueries::Impl {
    virtual ~Impl() = default;
    virtual bool answer(std::size_t i) const = 0;
    virtual long pass(std::size_t n) const = 0;
    virtual bool failed(std::size_t) const { return false; }
};

namespace {

// answer() and the timed pass of a library whose query(i) never fails.
template <class Library>
struct Answering : PeerQueries::Impl {
    bool answer(std::size_t i) const override { return self().query(i); }
    long pass(std::size_t n) const override {
        long hits = 0;
        for (std::size_t i = 0; i < n; ++i) hits += self().query(i);
        return hits;
    }

private:
    const Library& self() const { return static_cast<const Library&>(*this); }
};

// The same for a library whose query(i) can fail, tried once first (untimed): the constructor fills
// failed_; a failed query answers false and is left out of the timed passes.
template <class Library>
struct AnsweringUnlessFailed : PeerQueries::Impl {
    bool answer(std::size_t i) const override { return !failed_[i] && self().query(i); }
    long pass(std::size_t n) const override {
        long hits = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (!failed_[i]) hits += self().query(i);
        return hits;
    }
    bool failed(std::size_t i) const override { return failed_[i]; }

protected:
    std::vector<char> failed_;

private:
    const Library& self() const { return static_cast<const Library&>(*this); }
};

// ---- FCL 0.7: fcl::collide and fcl::distance on two shapes, GJK solver libccd (the default) or FCL's own ----

fcl::Transform3d fcl_transform(const Placed& p) {
    fcl::Transform3d t = fcl::Transform3d::Identity();
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) t.linear()(row, col) = p.rotation[row][col];
    t.translation() = fcl::Vector3d(p.center[0], p.center[1], p.center[2]);
    return t;
}

// Each query's shapes and placements in FCL's form, shared by the intersection and distance queries.
struct FclShapes {
    explicit FclShapes(const std::vector<Case>& cases) {
        boxes.reserve(cases.size());
        cylinders.reserve(cases.size());
        for (const Case& c : cases) {
            const BoxPose b = box_pose(c);
            const CylinderPose y = cylinder_pose(c);
            boxes.emplace_back(2 * b.half[0], 2 * b.half[1], 2 * b.half[2]);  // side lengths
            cylinders.emplace_back(y.radius, y.height);
            box_tf.push_back(fcl_transform(b));
            cylinder_tf.push_back(fcl_transform(y));
        }
    }
    std::vector<fcl::Boxd> boxes;
    std::vector<fcl::Cylinderd> cylinders;
    std::vector<fcl::Transform3d> box_tf, cylinder_tf;
};

class Fcl final : public Answering<Fcl> {
public:
    Fcl(const std::vector<Case>& cases, fcl::GJKSolverType solver) : s_(cases) {
        request_.num_max_contacts = 1;
        request_.enable_contact = false;  // a yes/no query
        request_.gjk_solver_type = solver;
    }
    // Called by Answering, not virtually: the timed pass is the library's call alone.
    bool query(std::size_t i) const {
        fcl::CollisionResultd result;
        fcl::collide(&s_.boxes[i], s_.box_tf[i], &s_.cylinders[i], s_.cylinder_tf[i], request_, result);
        return result.isCollision();
    }

private:
    FclShapes s_;
    fcl::CollisionRequestd request_;
};

// The clearance question: fcl::distance ≤ m. For shapes in contact FCL returns an unspecified
// distance ≤ 0 (mostly −1) unless asked for the signed one, which a yes/no question needs not.
class FclDistance final : public Answering<FclDistance> {
public:
    FclDistance(const std::vector<Case>& cases, const std::vector<double>& margins, fcl::GJKSolverType solver)
        : s_(cases), margins_(margins) {
        request_.gjk_solver_type = solver;  // defaults otherwise: no nearest points, distance_tolerance 1e-6
    }
    // Called by Answering, not virtually: the timed pass is the library's call alone.
    bool query(std::size_t i) const {
        fcl::DistanceResultd result;
        return fcl::distance(&s_.boxes[i], s_.box_tf[i], &s_.cylinders[i], s_.cylinder_tf[i], request_, result) <= margins_[i];
    }

private:
    FclShapes s_;
    std::vector<double> margins_;
    fcl::DistanceRequestd request_;
};

// ---- Bullet 3.24 (double): btGjkPairDetector, Voronoi simplex solver, GJK–EPA penetration depth; btGjkEpaSolver2 ----

btTransform bullet_transform(const Placed& p) {
    const Mat3& r = p.rotation;
    return btTransform(btMatrix3x3(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2]),
                       btVector3(p.center[0], p.center[1], p.center[2]));
}

// Margins 0. setMargin recomputes the shape's inner dimensions as (half extents − old margin) + new
// margin, which rounds; the half extents are set again exactly afterwards.
template <class Shape>
std::unique_ptr<Shape> bullet_shape(const btVector3& half) {
    auto s = std::make_unique<Shape>(half);
    s->setMargin(0);
    s->setImplicitShapeDimensions(half);
    return s;
}

// Each query's shapes and placements in Bullet's form, shared by the intersection and distance queries.
struct BulletShapes {
    explicit BulletShapes(const std::vector<Case>& cases) {
        for (const Case& c : cases) {
            const BoxPose b = box_pose(c);
            const CylinderPose y = cylinder_pose(c);
            boxes.push_back(bullet_shape<btBoxShape>(btVector3(b.half[0], b.half[1], b.half[2])));
            cylinders.push_back(bullet_shape<btCylinderShapeZ>(btVector3(y.radius, y.radius, 0.5 * y.height)));
            btGjkPairDetector::ClosestPointInput in;  // maximum distance: unlimited (the default)
            in.m_transformA = bullet_transform(b);
            in.m_transformB = bullet_transform(y);
            inputs.push_back(in);
        }
    }
    // btGjkPairDetector's reported distance (negative: penetration depth from EPA), or no result at
    // all (GJK or EPA gave up).
    std::optional<double> gjk_distance(std::size_t i) const {
        btVoronoiSimplexSolver simplex;
        btGjkEpaPenetrationDepthSolver depth;
        btGjkPairDetector gjk(boxes[i].get(), cylinders[i].get(), &simplex, &depth);
        btPointCollector out;
        gjk.getClosestPoints(inputs[i], out, nullptr);
        if (!out.m_hasResult) return std::nullopt;
        return out.m_distance;
    }
    std::vector<std::unique_ptr<btBoxShape>> boxes;
    std::vector<std::unique_ptr<btCylinderShapeZ>> cylinders;
    std::vector<btGjkPairDetector::ClosestPointInput> inputs;
};

// btGjkPairDetector: intersecting (clearance: within m) when the reported distance is ≤ 0 (≤ m). No
// result counts as no contact, as Bullet's own convex–convex algorithm treats it.
class Bullet final : public Answering<Bullet> {
public:
    explicit Bullet(const std::vector<Case>& cases) : s_(cases), margins_(cases.size(), 0.0) {}
    Bullet(const std::vector<Case>& cases, const std::vector<double>& margins) : s_(cases), margins_(margins) {}
    // Called by Answering, not virtually: the timed pass is the library's call alone.
    bool query(std::size_t i) const {
        const std::optional<double> d = s_.gjk_distance(i);
        return d && *d <= margins_[i];
    }

private:
    BulletShapes s_;
    std::vector<double> margins_;
};

// btGjkEpaSolver2::Distance, the GJK that Bullet's soft bodies and btGjkEpaPenetrationDepthSolver use:
// it returns false for shapes that are not separated, status Penetrating or GJK_Failed (which Bullet
// reads as "probably just touching"), and both count as within m.
class BulletGjkEpa2 final : public Answering<BulletGjkEpa2> {
public:
    BulletGjkEpa2(const std::vector<Case>& cases, const std::vector<double>& margins) : s_(cases), margins_(margins) {}
    // Called by Answering, not virtually: the timed pass is the library's call alone.
    bool query(std::size_t i) const {
        btGjkEpaSolver2::sResults r;
        const btTransform& a = s_.inputs[i].m_transformA;
        const btTransform& b = s_.inputs[i].m_transformB;
        if (!btGjkEpaSolver2::Distance(s_.boxes[i].get(), a, s_.cylinders[i].get(), b, b.getOrigin() - a.getOrigin(), r))
            return true;
        return r.distance <= margins_[i];
    }

private:
    BulletShapes s_;
    std::vector<double> margins_;
};

// ---- ODE 0.16 (double): dCollide on a box geom and a cylinder geom, in no space ----

void ode_place(dGeomID g, const Placed& p) {
    const Mat3& r = p.rotation;
    const dMatrix3 m{r[0][0], r[0][1], r[0][2], 0, r[1][0], r[1][1], r[1][2], 0, r[2][0], r[2][1], r[2][2], 0};
    dGeomSetRotation(g, m);
    dGeomSetPosition(g, p.center[0], p.center[1], p.center[2]);
}

// Debian's ODE is built with its internal assertions on, and dCollideCylinderBox asserts (by default:
// abort()) where it normalises a zero vector, e.g. in its edge tests on a flat box (a side of length
// 0). While the queries are first tried (untimed), a handler turns the assertion into an
// exception instead, unwinding through ODE's frames (C++, with unwind tables); the query is marked as
// failed, answers false like a boxcyl query that throws, and is left out of the timed passes.
struct OdeAssertion : std::runtime_error {
    using std::runtime_error::runtime_error;
};
[[noreturn]] void throw_ode_assertion(int, const char* format, va_list) { throw OdeAssertion(format); }

class Ode final : public AnsweringUnlessFailed<Ode> {
public:
    explicit Ode(const std::vector<Case>& cases) {
        static std::once_flag init;
        std::call_once(init, [] { dInitODE2(0); });  // never closed: the process ends first
        for (const Case& c : cases) {
            const BoxPose b = box_pose(c);
            const CylinderPose y = cylinder_pose(c);
            const dGeomID box = dCreateBox(nullptr, 2 * b.half[0], 2 * b.half[1], 2 * b.half[2]);
            const dGeomID cylinder = dCreateCylinder(nullptr, y.radius, y.height);
            ode_place(box, b);
            ode_place(cylinder, y);
            geoms_.push_back({box, cylinder});
        }
        dSetDebugHandler(throw_ode_assertion);
        dSetErrorHandler(throw_ode_assertion);
        for (std::size_t i = 0; i < geoms_.size(); ++i) {
            try {
                query(i);
                failed_.push_back(0);
            } catch (const OdeAssertion&) {
                failed_.push_back(1);
            }
        }
        dSetDebugHandler(nullptr);  // ODE's defaults again: a failure in a timed pass aborts
        dSetErrorHandler(nullptr);
    }
    ~Ode() override {
        for (const auto& [box, cylinder] : geoms_) {
            dGeomDestroy(box);
            dGeomDestroy(cylinder);
        }
    }
    Ode(const Ode&) = delete;
    Ode& operator=(const Ode&) = delete;

    // Intersecting: at least one contact (a buffer of one: the count is capped by it).
    bool query(std::size_t i) const {
        dContactGeom contact;
        return dCollide(geoms_[i].first, geoms_[i].second, 1, &contact, sizeof contact) > 0;
    }

private:
    std::vector<std::pair<dGeomID, dGeomID>> geoms_;
};

// ---- MuJoCo 2.2 (Debian's libmujoco): mj_collision on a model of two free bodies ----
//
// A box geom and a cylinder geom (MuJoCo's sizes: half extents; radius and half height), each on a free
// body, so that the pair is not filtered out. Each query writes its poses (qpos: position, then the
// quaternion of R) and sizes (with the bounding radii the broad phase reads) into the one model and
// data, then mj_kinematics places the geoms and mj_collision finds the contacts. (A contact's `dist`
// under a margin beyond the distance is no distance: see peers.hpp's has_distance.) A pair's margin is the
// larger of its geoms', so the box geom's margin is m and the cylinder's 0. mju_user_error (by default:
// print and exit) throws while the queries are first tried, untimed; a query that fails counts as no
// contact and is left out of the timed passes, as for ODE. Warnings (contact buffer full, …) are dropped.
struct MujocoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
[[noreturn]] void throw_mujoco_error(const char* message) { throw MujocoError(message); }
void ignore_mujoco_warning(const char*) {}

class MujocoScene {
public:
    explicit MujocoScene(const std::vector<Case>& cases) {
        static const char* const kModel =
            "<mujoco><worldbody>"
            "<body><freejoint/><geom type='box' size='1 1 1'/></body>"
            "<body><freejoint/><geom type='cylinder' size='1 1'/></body>"
            "</worldbody></mujoco>";
        mjVFS vfs;
        mj_defaultVFS(&vfs);
        const auto size = static_cast<int>(std::char_traits<char>::length(kModel));
        if (mj_makeEmptyFileVFS(&vfs, "pair.xml", size) != 0) throw std::runtime_error("MuJoCo: no room in the VFS");
        std::copy(kModel, kModel + size, static_cast<char*>(vfs.filedata[vfs.nfile - 1]));
        char error[500] = "";
        model_ = mj_loadXML("pair.xml", &vfs, error, sizeof error);
        mj_deleteVFS(&vfs);
        if (model_ == nullptr) throw std::runtime_error(std::string("MuJoCo: ") + error);
        data_ = mj_makeData(model_);
        mju_user_warning = ignore_mujoco_warning;
        for (const Case& c : cases) {
            const BoxPose b = box_pose(c);
            const CylinderPose y = cylinder_pose(c);
            Query q{};
            place(q.qpos, b);
            place(q.qpos + 7, y);
            q.box = b.half;
            q.radius = y.radius, q.half_height = 0.5 * y.height;
            q.box_rbound = std::sqrt(b.half[0] * b.half[0] + b.half[1] * b.half[1] + b.half[2] * b.half[2]);
            q.cylinder_rbound = std::sqrt(q.radius * q.radius + q.half_height * q.half_height);
            queries_.push_back(q);
        }
    }
    ~MujocoScene() {
        mj_deleteData(data_);
        mj_deleteModel(model_);
    }
    MujocoScene(const MujocoScene&) = delete;
    MujocoScene& operator=(const MujocoScene&) = delete;

    // Whether each query fails at `margin(i)` (tried once, untimed).
    template <class Margin>
    std::vector<char> failures(Margin&& margin) const {
        std::vector<char> failed(queries_.size(), 0);
        mju_user_error = throw_mujoco_error;
        for (std::size_t i = 0; i < queries_.size(); ++i) {
            try {
                contact(i, margin(i));
            } catch (const MujocoError&) {
                failed[i] = 1;
            }
        }
        return failed;
    }
    // Whether query i has a contact at the given margin.
    bool contact(std::size_t i, double margin) const {
        const Query& q = queries_[i];
        std::copy(q.qpos, q.qpos + 14, data_->qpos);
        for (int j = 0; j < 3; ++j) model_->geom_size[j] = q.box[j];
        model_->geom_size[3] = q.radius, model_->geom_size[4] = q.half_height;
        model_->geom_rbound[0] = q.box_rbound, model_->geom_rbound[1] = q.cylinder_rbound;
        model_->geom_margin[0] = margin, model_->geom_margin[1] = 0;
        mj_kinematics(model_, data_);
        mj_collision(model_, data_);
        return data_->ncon > 0;
    }
private:
    struct Query {
        double qpos[14];  // box: position, quaternion (w, x, y, z); then the cylinder's
        Vec3<double> box;
        double radius, half_height, box_rbound, cylinder_rbound;
    };
    static void place(double* qpos, const Placed& p) {
        double rotation[9];
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) rotation[3 * row + col] = p.rotation[row][col];
        for (int j = 0; j < 3; ++j) qpos[j] = p.center[j];
        mju_mat2Quat(qpos + 3, rotation);
    }

    mjModel* model_ = nullptr;
    mjData* data_ = nullptr;
    std::vector<Query> queries_;
};

// The clearance question: a contact at margin m.
class Mujoco final : public AnsweringUnlessFailed<Mujoco> {
public:
    Mujoco(const std::vector<Case>& cases, const std::vector<double>& margins) : scene_(cases), margins_(margins) {
        failed_ = scene_.failures([this](std::size_t i) { return margins_[i]; });
    }
    bool query(std::size_t i) const { return scene_.contact(i, margins_[i]); }

private:
    MujocoScene scene_;
    std::vector<double> margins_;
};

}  // namespace

PeerQueries::PeerQueries(Peer peer, const std::vector<Case>& cases) {
    switch (peer) {
        case Peer::fcl_libccd: impl_ = std::make_unique<Fcl>(cases, fcl::GST_LIBCCD); break;
        case Peer::fcl_indep: impl_ = std::make_unique<Fcl>(cases, fcl::GST_INDEP); break;
        case Peer::bullet: impl_ = std::make_unique<Bullet>(cases); break;
        case Peer::ode: impl_ = std::make_unique<Ode>(cases); break;
    }
    if (!impl_) throw std::logic_error("unknown peer library");
}

PeerQueries::PeerQueries(ClearancePeer peer, const std::vector<Case>& cases, const std::vector<double>& margins) {
    if (margins.size() != cases.size()) throw std::logic_error("one margin per query");
    switch (peer) {
        case ClearancePeer::fcl_libccd: impl_ = std::make_unique<FclDistance>(cases, margins, fcl::GST_LIBCCD); break;
        case ClearancePeer::fcl_indep: impl_ = std::make_unique<FclDistance>(cases, margins, fcl::GST_INDEP); break;
        case ClearancePeer::bullet_gjk: impl_ = std::make_unique<Bullet>(cases, margins); break;
        case ClearancePeer::bullet_gjkepa2: impl_ = std::make_unique<BulletGjkEpa2>(cases, margins); break;
        case ClearancePeer::mujoco: impl_ = std::make_unique<Mujoco>(cases, margins); break;
    }
    if (!impl_) throw std::logic_error("unknown peer library");
}

PeerQueries::~PeerQueries() = default;

bool PeerQueries::answer(std::size_t i) const { return impl_->answer(i); }
long PeerQueries::pass(std::size_t n) const { return impl_->pass(n); }
bool PeerQueries::failed(std::size_t i) const { return impl_->failed(i); }

// ---- The distances themselves ----

struct PeerDistances::Impl {
    virtual ~Impl() = default;
    virtual std::optional<double> distance(std::size_t i) const = 0;
    virtual bool failed(std::size_t) const { return false; }
};

namespace {

// Which of queries 0 … n−1 end the process, each tried once (untimed) in a child process: Debian's libfcl
// keeps its assertions, and an assertion in FCL's EPA calls abort(), which no handler can turn into an
// exception as ODE's can. The child's stderr goes to /dev/null (no assertion message in the output); a
// child that runs a minute is stopped and its query counts as failed too.
template <class Query>
std::vector<char> ending_the_process(std::size_t n, const Query& query) {
    std::vector<char> failed(n, 0);
    std::fflush(nullptr);  // nothing buffered is written twice
    for (std::size_t i = 0; i < n; ++i) {
        const pid_t pid = fork();
        if (pid < 0) throw std::runtime_error("fork() failed");
        if (pid == 0) {
            if (const int null = open("/dev/null", O_WRONLY); null >= 0) dup2(null, STDERR_FILENO);
            alarm(60);
            query(i);
            _exit(0);
        }
        int status = 0;
        if (waitpid(pid, &status, 0) != pid) throw std::runtime_error("waitpid() failed");
        failed[i] = static_cast<char>(!(WIFEXITED(status) && WEXITSTATUS(status) == 0));
    }
    return failed;
}

class FclDistances final : public PeerDistances::Impl {
public:
    FclDistances(const std::vector<Case>& cases, fcl::GJKSolverType solver) : s_(cases) { request_.gjk_solver_type = solver; }
    std::optional<double> distance(std::size_t i) const override {
        fcl::DistanceResultd result;
        return fcl::distance(&s_.boxes[i], s_.box_tf[i], &s_.cylinders[i], s_.cylinder_tf[i], request_, result);
    }

private:
    FclShapes s_;
    fcl::DistanceRequestd request_;
};

// The signed distance: fcl::distance with enable_signed_distance. GST_LIBCCD computes it in the
// distance call. GST_INDEP computes the distance, and where it is negative (shapes in contact: −1) the
// depth afterwards by collide() with contacts, the deepest contact's penetration_depth; but FCL 0.7's
// GST_INDEP gives its contacts minus EPA's depth (gjk_solver_indep-inl.h: depth = −epa.depth), so no
// contact is deep enough and distance() fails its assertion (Debian's libfcl keeps them: abort()) on every
// overlapping pair. For GST_INDEP this makes the same two calls, unsigned distance then collide() with one
// contact, and reads the depth as the magnitude of the contact's penetration_depth (none: no contact).
class FclSignedDistances final : public PeerDistances::Impl {
public:
    FclSignedDistances(const std::vector<Case>& cases, fcl::GJKSolverType solver) : s_(cases) {
        request_.gjk_solver_type = solver;  // defaults otherwise: no nearest points, distance_tolerance 1e-6
        request_.enable_signed_distance = solver == fcl::GST_LIBCCD;
        contact_request_.gjk_solver_type = solver;
        contact_request_.enable_contact = true;  // num_max_contacts 1, as distance() asks
        failed_ = ending_the_process(cases.size(), [this](std::size_t i) { query(i); });
    }
    // None for a query that aborts (left out of the timed passes).
    std::optional<double> distance(std::size_t i) const override { return failed_[i] ? std::nullopt : query(i); }
    bool failed(std::size_t i) const override { return failed_[i]; }

private:
    std::optional<double> query(std::size_t i) const {
        fcl::DistanceResultd result;
        const double d = fcl::distance(&s_.boxes[i], s_.box_tf[i], &s_.cylinders[i], s_.cylinder_tf[i], request_, result);
        if (request_.enable_signed_distance || d >= 0) return d;
        fcl::CollisionResultd contacts;
        fcl::collide(&s_.boxes[i], s_.box_tf[i], &s_.cylinders[i], s_.cylinder_tf[i], contact_request_, contacts);
        if (contacts.numContacts() == 0) return std::nullopt;
        return -std::fabs(contacts.getContact(0).penetration_depth);
    }

    FclShapes s_;
    fcl::DistanceRequestd request_;
    fcl::CollisionRequestd contact_request_;
    std::vector<char> failed_;
};

// btGjkPairDetector's distance (signed already: EPA's depth, negated, where the shapes overlap), or
// btGjkEpaSolver2's Distance (separated shapes only) or SignedDistance (Distance, then Penetration
// where that fails: results.distance is minus EPA's depth).
class BulletDistances final : public PeerDistances::Impl {
public:
    enum class Call { gjk, epa2_distance, epa2_signed_distance };
    BulletDistances(const std::vector<Case>& cases, Call call) : s_(cases), call_(call) {}
    std::optional<double> distance(std::size_t i) const override {
        if (call_ == Call::gjk) return s_.gjk_distance(i);
        btGjkEpaSolver2::sResults r;
        const btTransform& a = s_.inputs[i].m_transformA;
        const btTransform& b = s_.inputs[i].m_transformB;
        const btVector3 guess = b.getOrigin() - a.getOrigin();
        if (call_ == Call::epa2_distance ? !btGjkEpaSolver2::Distance(s_.boxes[i].get(), a, s_.cylinders[i].get(), b, guess, r)
                                         : !btGjkEpaSolver2::SignedDistance(s_.boxes[i].get(), a, s_.cylinders[i].get(), b, guess, r))
            return std::nullopt;
        return r.distance;
    }

private:
    BulletShapes s_;
    Call call_;
};

}  // namespace

PeerDistances::PeerDistances(ClearancePeer peer, const std::vector<Case>& cases) {
    switch (peer) {
        case ClearancePeer::fcl_libccd: impl_ = std::make_unique<FclDistances>(cases, fcl::GST_LIBCCD); break;
        case ClearancePeer::fcl_indep: impl_ = std::make_unique<FclDistances>(cases, fcl::GST_INDEP); break;
        case ClearancePeer::bullet_gjk: impl_ = std::make_unique<BulletDistances>(cases, BulletDistances::Call::gjk); break;
        case ClearancePeer::bullet_gjkepa2: impl_ = std::make_unique<BulletDistances>(cases, BulletDistances::Call::epa2_distance); break;
        case ClearancePeer::mujoco: throw std::logic_error("MuJoCo 2.2 has no distance call (has_distance)");
    }
    if (!impl_) throw std::logic_error("unknown peer library");
}
PeerDistances::PeerDistances(SignedPeer peer, const std::vector<Case>& cases) {
    switch (peer) {
        case SignedPeer::fcl_libccd: impl_ = std::make_unique<FclSignedDistances>(cases, fcl::GST_LIBCCD); break;
        case SignedPeer::fcl_indep: impl_ = std::make_unique<FclSignedDistances>(cases, fcl::GST_INDEP); break;
        case SignedPeer::bullet_gjk: impl_ = std::make_unique<BulletDistances>(cases, BulletDistances::Call::gjk); break;
        case SignedPeer::bullet_gjkepa2:
            impl_ = std::make_unique<BulletDistances>(cases, BulletDistances::Call::epa2_signed_distance);
            break;
    }
    if (!impl_) throw std::logic_error("unknown peer library");
}
PeerDistances::~PeerDistances() = default;
std::optional<double> PeerDistances::distance(std::size_t i) const { return impl_->distance(i); }
bool PeerDistances::failed(std::size_t i) const { return impl_->failed(i); }
double PeerDistances::pass(std::size_t n) const {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += impl_->distance(i).value_or(0.0);  // a failed query: none, at once
    return sum;
}

}  // namespace boxcyl::bench
