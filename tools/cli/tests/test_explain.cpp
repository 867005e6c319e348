// Tests of `boxcyl explain`: the picture's geometry (boxcyl/explain/explanation.hpp) on hand cases with
// exact expected values, its agreement with the exact verdict away from touching on fixed-seed random
// cases, and the SVG writer's elements and escaping (tools/cli/explain.hpp). Well-formedness of the
// whole document is checked end to end by explain_test.sh with an XML parser.
#include <gtest/gtest.h>

#include <algorithm>  // std::max, std::count
#include <array>      // frames
#include <cmath>      // std::fabs, std::ldexp, std::nextafter
#include <cstdio>     // std::snprintf
#include <cstdlib>    // std::strtod
#include <string>
#include <vector>

#include "boxcyl/explain/explanation.hpp"
#include "support/cases.hpp"  // random and near-touching cases, copy-pasteable printing
#include "explain.hpp"

namespace boxcyl {
namespace {

using explain::Case;
using explain::Explanation;
using explain::Point2;

AlignedBox<double> unit_box() { return {{0, 0, 0}, {1, 1, 1}}; }

bool has_vertex(const std::vector<Point2>& poly, double x, double y) {
    return std::any_of(poly.begin(), poly.end(), [&](const Point2& p) { return p.x == x && p.y == y; });
}

// --- hand cases: exact expected values -----------------------------------------------------------

TEST(ExplainGeometry, VerticalCylinderBesideTheBoxHasTheKnownGap) {
    // examples/queries.jsonl "gap-side-face": the face x = 1 is 0.5 from the axis x = 1.5; r = 0.4375.
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.4375, 1});
    EXPECT_FALSE(e.exact_intersects);
    EXPECT_FALSE(e.picture_intersects);
    EXPECT_EQ(e.what, Case::gap);
    // The plane ⊥ z is seen as the top view: e1 = x, e2 = y, origin on the axis.
    EXPECT_EQ(e.e1, (Vec3<double>{1, 0, 0}));
    EXPECT_EQ(e.e2, (Vec3<double>{0, 1, 0}));
    EXPECT_EQ(e.section.size(), 8u);  // the box lies within the slab |z − 0.5| ≤ 0.5: all 8 vertices
    ASSERT_EQ(e.polygon.size(), 4u);
    EXPECT_TRUE(has_vertex(e.polygon, -1.5, -0.5));
    EXPECT_TRUE(has_vertex(e.polygon, -0.5, -0.5));
    EXPECT_TRUE(has_vertex(e.polygon, -0.5, 0.5));
    EXPECT_TRUE(has_vertex(e.polygon, -1.5, 0.5));
    EXPECT_EQ(e.closest.x, -0.5);
    EXPECT_EQ(e.closest.y, 0.0);
    EXPECT_EQ(e.distance, 0.5);
    EXPECT_EQ(e.gap(), 0.0625);
    EXPECT_EQ(e.box_axial_min, -0.5);
    EXPECT_EQ(e.box_axial_max, 0.5);
}

TEST(ExplainGeometry, TouchingSideIsTouching) {
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.5, 1});
    EXPECT_TRUE(e.exact_intersects);
    EXPECT_EQ(e.what, Case::touching);
    EXPECT_EQ(e.gap(), 0.0);
}

TEST(ExplainGeometry, SlabCutsTheBoxAndTheAxisPassesThrough) {
    // Slab z ∈ [0.75, 3.25]: box ∩ slab is the top quarter of the cube, 4 vertices + 4 edge crossings
    // at z = 0.75; seen along z it is the unit square around the axis (0.5, 0.5).
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{0.5, 0.5, 2}, {0, 0, 1}, 0.125, 2.5});
    EXPECT_TRUE(e.exact_intersects);
    EXPECT_EQ(e.what, Case::axis_through);
    ASSERT_EQ(e.section.size(), 8u);
    EXPECT_EQ(std::count_if(e.section.begin(), e.section.end(), [](const Vec3<double>& v) { return v[2] == 0.75; }), 4);
    EXPECT_EQ(e.polygon.size(), 4u);
    EXPECT_TRUE(has_vertex(e.polygon, -0.5, -0.5));
    EXPECT_TRUE(has_vertex(e.polygon, 0.5, 0.5));
    EXPECT_EQ(e.distance, 0.0);
    EXPECT_EQ(e.closest.x, 0.0);
    EXPECT_EQ(e.closest.y, 0.0);
}

TEST(ExplainGeometry, DiagonalAxisSeesAHexagon) {
    // "skew-through-diagonal": along the cube's diagonal the cube's shadow is a regular hexagon.
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{2, 2, 2}, {-1, -1, -1}, 0.1, 10});
    EXPECT_TRUE(e.exact_intersects);
    EXPECT_EQ(e.what, Case::axis_through);
    EXPECT_EQ(e.polygon.size(), 6u);
    EXPECT_EQ(e.distance, 0.0);
}

TEST(ExplainGeometry, BoxBeyondTheEndPlaneHasNoPolygon) {
    // "point-box-one-ulp-above-cap": a point box at z = 1 + 2^-52, the top end plane at z = 1.
    const double z = 1 + std::ldexp(1.0, -52);
    const Explanation e = explain::compute(AlignedBox<double>{{0, 0, z}, {0, 0, z}}, Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 2});
    EXPECT_FALSE(e.exact_intersects);
    EXPECT_TRUE(e.slab_empty);
    EXPECT_TRUE(e.polygon.empty());
    EXPECT_TRUE(e.section.empty());
    EXPECT_EQ(e.what, Case::outside_slab);
    EXPECT_EQ(e.box_axial_min, z);
    EXPECT_EQ(e.box_axial_max, z);
    EXPECT_EQ(e.half_height, 1.0);
}

TEST(ExplainGeometry, BoxOnTheEndPlaneTouchesAnEnd) {
    // "touch-cap-face": the bottom disk lies on the face z = 1 (axis [0, 0, 2]: only its direction counts).
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{0.5, 0.5, 1.25}, {0, 0, 2}, 0.125, 0.5});
    EXPECT_TRUE(e.exact_intersects);
    EXPECT_EQ(e.what, Case::touching_end_plane);
    EXPECT_EQ(e.direction, (Vec3<double>{0, 0, 1}));
    EXPECT_EQ(e.box_axial_max, -0.25);
    EXPECT_EQ(e.polygon.size(), 4u);  // the face z = 1
    EXPECT_EQ(e.distance, 0.0);
}

TEST(ExplainGeometry, FlatBoxSeenEdgeOnIsASegment) {
    // The square y = 0, x, z ∈ [0, 1], seen along z: the segment y = −2, x ∈ [−0.5, 0.5].
    const Explanation e = explain::compute(AlignedBox<double>{{0, 0, 0}, {1, 0, 1}}, Cylinder<double>{{0.5, 2, 0.5}, {0, 0, 1}, 1, 1});
    EXPECT_FALSE(e.exact_intersects);
    ASSERT_EQ(e.polygon.size(), 2u);
    EXPECT_TRUE(has_vertex(e.polygon, -0.5, -2));
    EXPECT_TRUE(has_vertex(e.polygon, 0.5, -2));
    EXPECT_EQ(e.closest.x, 0.0);
    EXPECT_EQ(e.closest.y, -2.0);
    EXPECT_EQ(e.gap(), 1.0);
    EXPECT_EQ(e.what, Case::gap);
}

TEST(ExplainGeometry, PointBoxIsAPoint) {
    // "point-box-on-lateral-surface": the point (1, 0, 0) on the side of a radius-1 cylinder.
    const Explanation e = explain::compute(AlignedBox<double>{{1, 0, 0}, {1, 0, 0}}, Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 2});
    EXPECT_TRUE(e.exact_intersects);
    ASSERT_EQ(e.polygon.size(), 1u);
    EXPECT_EQ(e.distance, 1.0);
    EXPECT_EQ(e.what, Case::touching);
}

TEST(ExplainGeometry, OrientedBoxUsesItsAxes) {
    // "oriented-gap-rot90": a 90° rotation about z; the box spans x ∈ [−1, 1], y ∈ [−2, 2].
    const OrientedBox<double> box{{0, 0, 0}, {Vec3<double>{0, 1, 0}, Vec3<double>{-1, 0, 0}, Vec3<double>{0, 0, 1}}, {2, 1, 1}};
    const Explanation e = explain::compute(box, Cylinder<double>{{1.5, 0, 0}, {0, 0, 1}, 0.4375, 1});
    EXPECT_FALSE(e.exact_intersects);
    ASSERT_EQ(e.polygon.size(), 4u);
    EXPECT_TRUE(has_vertex(e.polygon, -2.5, -2));
    EXPECT_TRUE(has_vertex(e.polygon, -0.5, 2));
    EXPECT_EQ(e.distance, 0.5);
    EXPECT_EQ(e.gap(), 0.0625);
}

TEST(ExplainGeometry, HorizontalAxisKeepsUpUp) {
    // For a horizontal axis e2 is +z, so the picture's "up" is the world's.
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{0.5, 3, 0.5}, {0, 1, 0}, 0.25, 1});
    EXPECT_EQ(e.e2, (Vec3<double>{0, 0, 1}));
    EXPECT_EQ(e.e1, (Vec3<double>{-1, 0, 0}));
    EXPECT_EQ(e.what, Case::outside_slab);  // the slab y ∈ [2.5, 3.5] misses the box
}

TEST(ExplainGeometry, ThePictureDefersToTheExactVerdict) {
    // The verdict is whatever the caller says is exact; a picture that disagrees is flagged, not drawn
    // as a different answer.
    const Cylinder<double> cyl{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.4375, 1};
    const Explanation e = explain::compute(unit_box(), cyl, /*exact_intersects=*/true);
    EXPECT_TRUE(e.exact_intersects);
    EXPECT_FALSE(e.picture_intersects);
    EXPECT_EQ(e.what, Case::touching_within_rounding);
}

// --- random cases: the double picture agrees with the exact verdict unless within rounding ----------

// How far from touching a case is in the picture: the lateral |d − r| and, along the axis, how far the
// box's range is from just touching the slab; relative to the case's magnitude.
double relative_margin(const Explanation& e) {
    double scale = std::max({e.radius, e.half_height, std::fabs(e.box_axial_min), std::fabs(e.box_axial_max)});
    for (const auto& v : e.box_vertices)
        for (int i = 0; i < 3; ++i) scale = std::max(scale, std::fabs(v[i] - e.center[i]));
    const double axial = std::min(std::fabs(e.box_axial_max + e.half_height), std::fabs(e.box_axial_min - e.half_height));
    const double lateral = e.slab_empty ? axial : std::fabs(e.gap());
    return std::min(lateral, axial) / scale;
}

Explanation explain_case(const testing::Case& c) {
    return c.kind == testing::BoxKind::aligned ? explain::compute(c.aligned, c.cylinder)
                                               : explain::compute(c.oriented, c.cylinder);
}

TEST(ExplainRandom, PictureAgreesWithTheExactVerdictAwayFromTouching) {
    // The verdict is boxcyl::intersects (tested against the oracle elsewhere); here the double picture
    // must say the same unless the case is within rounding of touching, and then it must be flagged.
    const std::uint64_t seed = 20261121;
    testing::CaseGenerator gen(seed);
    int considered = 0, drawn = 0, flagged = 0;
    for (int i = 0; i < 6000; ++i) {
        const testing::Case c = gen.next();
        if (c.kind == testing::BoxKind::canonical) continue;  // explain takes aligned and oriented boxes
        ++considered;
        const Explanation e = explain_case(c);
        if (!e.drawable) continue;
        ++drawn;
        const bool disagree = e.exact_intersects != e.picture_intersects;
        EXPECT_EQ(e.what == Case::touching_within_rounding, disagree);
        if (disagree) {
            ++flagged;
            EXPECT_LE(relative_margin(e), 1e-9) << "the picture disagrees far from touching";
        }
        EXPECT_EQ(e.slab_empty, e.polygon.empty());
        EXPECT_GE(e.distance, 0.0);
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "seed " << seed << " case " << i << ": " << testing::describe(c);
            return;
        }
    }
    EXPECT_EQ(drawn, considered);  // the mixed profile stays far from overflow
    EXPECT_GT(considered, 3000);
    EXPECT_LT(flagged, 10);  // generic inputs are rarely within rounding of touching
}

TEST(ExplainRandom, NearTouchingPairsAreFlaggedWhenThePictureCannotTell) {
    // Pairs one ulp apart with opposite exact answers: the picture cannot separate them, so it must
    // flag the side it gets wrong, never draw a confident wrong answer.
    testing::CaseGenerator gen(7);
    int pairs = 0, flagged = 0;
    while (pairs < 40) {
        testing::Case a, b;
        testing::Parameter which;
        if (!testing::boundary_pair(gen, a, b, which)) continue;
        if (a.kind == testing::BoxKind::canonical) continue;
        ++pairs;
        for (const testing::Case* c : {&a, &b}) {
            const Explanation e = explain_case(*c);
            EXPECT_EQ(e.what == Case::touching_within_rounding, e.exact_intersects != e.picture_intersects)
                << testing::describe(*c);
            if (e.what == Case::touching_within_rounding) ++flagged;
        }
    }
    EXPECT_GT(flagged, 0);  // the case exists in practice, not only in principle
}

// --- the SVG writer ----------------------------------------------------------------------------

TEST(ExplainSvg, CarriesEveryElementAndTheVerdict) {
    const Explanation e = explain::compute_nearest(unit_box(), Cylinder<double>{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.4375, 1});
    const std::string svg = cli::render_svg(e, "\"gap-side-face\"");
    EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
    for (const std::string id : cli::svg_ids)
        EXPECT_EQ(svg.find("id=\"" + id + "\"") != std::string::npos, id != "margin") << id;  // no margin asked
    EXPECT_NE(svg.find(">Does not intersect<"), std::string::npos);
    EXPECT_NE(svg.find(">gap 0.0625<"), std::string::npos);
    EXPECT_NE(svg.find(">radius 0.4375<"), std::string::npos);
    EXPECT_NE(svg.find("closest point, distance 0.5"), std::string::npos);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_EQ(svg.find("inf"), std::string::npos);
}

// The clearance question: the verdict is within_distance's, and the margin is drawn. The box lies
// exactly 0.0625 beside the cylinder (a side face against the side), so a margin of 0.0625 turns "does
// not intersect" into "within", and the double below it does not.
TEST(ExplainSvg, MarginIsTheVerdictAndIsDrawn) {
    const Cylinder<double> c{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.4375, 1};
    const Explanation at = explain::compute_within(unit_box(), c, 0.0625);
    EXPECT_FALSE(at.exact_intersects);
    EXPECT_TRUE(at.exact_within);
    EXPECT_TRUE(at.verdict());
    EXPECT_EQ(at.what, Case::gap);  // the picture of the cylinder itself is unchanged
    const std::string svg = cli::render_svg(at, "\"m\"");
    for (const std::string id : cli::svg_ids)
        EXPECT_EQ(svg.find("id=\"" + id + "\"") != std::string::npos, id != "nearest") << id;  // no distance asked
    EXPECT_NE(svg.find("<title>boxcyl explain: query &quot;m&quot;: Within distance 0.0625</title>"), std::string::npos);
    EXPECT_NE(svg.find(">Within distance 0.0625<"), std::string::npos);
    EXPECT_NE(svg.find("it meets the cylinder grown by 0.0625 (dashed)"), std::string::npos);
    EXPECT_NE(svg.find(">radius + margin 0.5<"), std::string::npos);
    EXPECT_NE(svg.find(">gap 0.0625<"), std::string::npos);  // to the cylinder itself
    EXPECT_NE(svg.find("the cylinder grown by the margin"), std::string::npos);  // the legend
    EXPECT_NE(svg.find("boxcyl::within_distance"), std::string::npos);
    EXPECT_EQ(svg.find("NaN"), std::string::npos);
    // The margin's disk in the view along the axis: radius r + m = 0.5 around the axis point.
    const auto g = svg.find("<g id=\"margin\">");
    ASSERT_NE(g, std::string::npos);
    EXPECT_NE(svg.find("stroke-dasharray=\"7,4\"", g), std::string::npos);

    const Explanation below = explain::compute_within(unit_box(), c, std::nextafter(0.0625, 0.0));
    EXPECT_FALSE(below.verdict());
    const std::string no = cli::render_svg(below, "");
    EXPECT_NE(no.find(">Not within distance 0.06249999999999999<"), std::string::npos);  // every digit it needs
    EXPECT_NE(no.find("the box is farther than 0.06249999999999999 from the cylinder"), std::string::npos);

    // Without a margin the same shapes do not intersect; with one the box meeting the cylinder says so.
    EXPECT_FALSE(explain::compute(unit_box(), c).verdict());
    const Cylinder<double> inside{{0.5, 0.5, 0.5}, {0, 0, 1}, 0.25, 0.5};
    const std::string meets = cli::render_svg(explain::compute_within(unit_box(), inside, 1), "");
    EXPECT_NE(meets.find(">Within distance 1 (intersects)<"), std::string::npos);
}

// Beyond an end and past the side, so a rim decides: the box's edge x = y = 1 is 1.375 from the axis
// (0.375 beyond the side) and its top 0.5 below the bottom end plane z = 1.5, so the box is 0.625
// (= √(0.375² + 0.5²)) from the bottom rim. The picture's own case stays "beyond the end plane".
TEST(ExplainSvg, MarginReachesARim) {
    const Cylinder<double> c{{2.375, 1, 2.5}, {0, 0, 1}, 1, 2};
    const Explanation at = explain::compute_within(unit_box(), c, 0.625);
    EXPECT_TRUE(at.verdict());
    EXPECT_EQ(at.what, Case::outside_slab);
    EXPECT_NE(cli::render_svg(at, "").find(">Within distance 0.625<"), std::string::npos);
    EXPECT_FALSE(explain::compute_within(unit_box(), c, std::nextafter(0.625, 0.0)).verdict());
}

// The text of one element: from `from` (e.g. "<g id=\"nearest\"") to the next "</g>".
std::string group(const std::string& svg, const std::string& from) {
    const auto at = svg.find(from);
    if (at == std::string::npos) return "";
    return svg.substr(at, svg.find("</g>", at) - at);
}

// The fewest digits (6 to 17) that read back as x, as explain prints exact numbers.
std::string round_trip(double x) {
    char buf[40];
    for (int d = 6; d <= 17; ++d) {
        std::snprintf(buf, sizeof buf, "%.*g", d, x);
        if (std::strtod(buf, nullptr) == x) break;
    }
    return buf;
}

// A number attribute of the first element `tag` (e.g. "<line") in `text`.
double attribute(const std::string& text, const std::string& tag, const std::string& name) {
    const auto at = text.find(tag);
    if (at == std::string::npos) return -1;
    const auto v = text.find(" " + name + "=\"", at) + name.size() + 3;
    return std::stod(text.substr(v, text.find('"', v) - v));
}

// The nearest pair of boxcyl::distance: a unit cube and a vertical cylinder of radius 1 whose axis is
// 2.5 from the face x = 1, so 1 apart; the pair lies on y = 0.5, at x = 1 on the box and x = 2 on the
// cylinder, and is marked in every view with the bounds written once.
TEST(ExplainSvg, NearestPairIsMarkedInEveryView) {
    const Cylinder<double> c{{3, 0.5, 0.5}, {0, 0, 1}, 1, 1};
    const Explanation e = explain::compute_nearest(unit_box(), c);
    ASSERT_TRUE(e.nearest);
    const Distance d = boxcyl::distance(unit_box(), c);
    EXPECT_EQ(e.nearest->lower, d.lower);
    EXPECT_EQ(e.nearest->upper, d.upper);
    EXPECT_LE(e.nearest->lower, 1.0);
    EXPECT_GE(e.nearest->upper, 1.0);
    EXPECT_NEAR(e.nearest->on_box[0], 1, 1e-12);
    EXPECT_NEAR(e.nearest->on_cylinder[0], 2, 1e-12);
    EXPECT_NEAR(e.nearest->on_box[1], 0.5, 1e-12);
    const std::string svg = cli::render_svg(e, "");
    for (const std::string id : cli::svg_ids)
        EXPECT_EQ(svg.find("id=\"" + id + "\"") != std::string::npos, id != "margin") << id;
    // The bounds, once, with the digits that read back as the doubles.
    const std::string text =
        ">Nearest points, distance in [" + round_trip(d.lower) + ", " + round_trip(d.upper) + "] (boxcyl::distance";
    EXPECT_NE(svg.find(text), std::string::npos) << text;
    EXPECT_NE(svg.find(">Nearest points, distance in [1"), std::string::npos);
    EXPECT_EQ(svg.find("Nearest points, distance in ["), svg.rfind("Nearest points, distance in ["));
    EXPECT_NE(svg.find("nearest points of the box and the cylinder"), std::string::npos);  // the legend
    // Seen along the axis (x right, y up) and from the top, the segment runs right from the box to the
    // cylinder at one height; from the front (x, z), right too. A dot on each end.
    for (const char* id : {"<g id=\"nearest\"", "<g id=\"view-top-nearest\"", "<g id=\"view-front-nearest\""}) {
        const std::string g = group(svg, id);
        ASSERT_FALSE(g.empty()) << id;
        EXPECT_NE(g.find("class=\"nearest\""), std::string::npos) << id;
        EXPECT_LT(attribute(g, "<line", "x1"), attribute(g, "<line", "x2")) << id;
        EXPECT_EQ(std::count(g.begin(), g.end(), '<') - 1, 3) << id;  // a line and two circles
    }
    for (const char* id : {"<g id=\"nearest\"", "<g id=\"view-top-nearest\""}) {
        const std::string g = group(svg, id);
        EXPECT_EQ(attribute(g, "<line", "y1"), attribute(g, "<line", "y2")) << id;
    }
    // From the side (y, z) the box point hides the cylinder point: both at y = 0.5.
    const std::string side = group(svg, "<g id=\"view-side-nearest\"");
    EXPECT_NEAR(attribute(side, "<line", "x1"), attribute(side, "<line", "x2"), 0.01);
}

// Intersecting solids: the distance is [0, 0] and the witnesses are near one common point, so only
// that point is drawn (no segment), and the text says they intersect.
TEST(ExplainSvg, NearestPairOfIntersectingSolidsIsOneCommonPoint) {
    const Cylinder<double> touching{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.5, 1};  // the side touches the face x = 1
    const Explanation e = explain::compute_nearest(unit_box(), touching);
    ASSERT_TRUE(e.nearest);
    EXPECT_EQ(e.nearest->lower, 0.0);
    EXPECT_EQ(e.nearest->upper, 0.0);
    EXPECT_NEAR(e.nearest->on_box[0], 1, 1e-9);  // where they touch
    const std::string svg = cli::render_svg(e, "");
    EXPECT_NE(svg.find(">Nearest points, distance 0: the solids intersect; purple marks a common point"),
              std::string::npos);
    for (const char* id : {"<g id=\"nearest\"", "<g id=\"view-top-nearest\"", "<g id=\"view-front-nearest\"",
                           "<g id=\"view-side-nearest\""}) {
        const std::string g = group(svg, id);
        ASSERT_FALSE(g.empty()) << id;
        EXPECT_EQ(g.find("<line"), std::string::npos) << id;
        EXPECT_EQ(std::count(g.begin(), g.end(), '<') - 1, 1) << id;  // one circle
    }
}

// Overlapping solids: the cylinder's side reaches 0.25 into the face x = 1 (its axis at x = 1.25, radius
// 0.5), and that is the penetration depth. The depth pair is drawn instead of a common point: the box's
// deepest point at x = 1, the cylinder's at x = 0.75, joined; the text gives the depth's bounds.
TEST(ExplainSvg, OverlappingSolidsShowTheDepthPair) {
    const Cylinder<double> c{{1.25, 0.5, 0.5}, {0, 0, 1}, 0.5, 1};
    const Explanation e = explain::compute_nearest(unit_box(), c);
    ASSERT_TRUE(e.nearest);
    EXPECT_EQ(e.nearest->upper, 0.0);
    ASSERT_TRUE(e.depth);
    const SignedDistance sd = boxcyl::signed_distance(unit_box(), c);
    EXPECT_EQ(e.depth->lower, sd.lower);
    EXPECT_EQ(e.depth->upper, sd.upper);
    EXPECT_LE(sd.lower, -0.25);
    EXPECT_GE(sd.upper, -0.25);
    EXPECT_NEAR(e.depth->on_box[0], 1, 1e-9);
    EXPECT_NEAR(e.depth->on_cylinder[0], 0.75, 1e-9);
    const std::string svg = cli::render_svg(e, "");
    const std::string text = ">Overlapping: penetration depth in [" + round_trip(-sd.upper) + ", " +
                             round_trip(-sd.lower) + "] (boxcyl::signed_distance, proved)";
    EXPECT_NE(svg.find(text), std::string::npos) << text;
    EXPECT_EQ(svg.find("distance 0: the solids intersect"), std::string::npos);
    EXPECT_NE(svg.find("deepest points of the box and the cylinder"), std::string::npos);  // the legend
    // Seen along the axis and from the top, the segment runs left from the box's point to the cylinder's.
    for (const char* id : {"<g id=\"nearest\"", "<g id=\"view-top-nearest\"", "<g id=\"view-front-nearest\""}) {
        const std::string g = group(svg, id);
        ASSERT_FALSE(g.empty()) << id;
        EXPECT_GT(attribute(g, "<line", "x1"), attribute(g, "<line", "x2")) << id;
        EXPECT_EQ(std::count(g.begin(), g.end(), '<') - 1, 3) << id;  // a line and two circles
    }
    // Touching solids have no depth: the common point only (the test above).
    EXPECT_FALSE(explain::with_depth(explain::compute_nearest(unit_box(), Cylinder<double>{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.5, 1}),
                                     boxcyl::signed_distance(unit_box(), Cylinder<double>{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.5, 1}))
                     .depth);
}

// No distance asked (compute) or a picture that shows nothing: no nearest pair.
TEST(ExplainSvg, NearestPairOnlyWhenAskedAndDrawable) {
    const Cylinder<double> c{{3, 0.5, 0.5}, {0, 0, 1}, 1, 1};
    const std::string plain = cli::render_svg(explain::compute(unit_box(), c), "");
    EXPECT_EQ(plain.find("nearest"), std::string::npos);
    EXPECT_EQ(plain.find("Nearest"), std::string::npos);
    const AlignedBox<double> huge{{-1.7e308, 0, 0}, {1.7e308, 1, 1}};
    const Cylinder<double> far{{1.7e308, 0.5, 0.5}, {1, 1, 0}, 1, 1};
    const Explanation e = explain::compute_nearest(huge, far);
    EXPECT_FALSE(e.drawable);
    EXPECT_FALSE(e.nearest);
    EXPECT_FALSE(explain::with_nearest(e, Distance{1, 1, {}, {}}).nearest);
    EXPECT_EQ(cli::render_svg(e, "").find("nearest"), std::string::npos);
}

TEST(ExplainSvg, VerdictTitles) {
    auto title = [](const AlignedBox<double>& b, const Cylinder<double>& c) {
        const std::string svg = cli::render_svg(explain::compute(b, c), "");
        const auto at = svg.find("<title>");
        return svg.substr(at, svg.find("</title>") - at);
    };
    EXPECT_EQ(title(unit_box(), {{1.5, 0.5, 0.5}, {0, 0, 1}, 0.5, 1}), "<title>boxcyl explain: Intersects (touching)");
    EXPECT_EQ(title(unit_box(), {{0.5, 0.5, 0.5}, {0, 0, 1}, 0.25, 0.5}), "<title>boxcyl explain: Intersects");
    EXPECT_EQ(title(unit_box(), {{0.5, 0.5, 1.25}, {0, 0, 2}, 0.125, 0.5}), "<title>boxcyl explain: Intersects (touching an end)");
    EXPECT_EQ(title(unit_box(), {{5, 5, 5}, {0, 0, 1}, 1, 1}), "<title>boxcyl explain: Does not intersect");
    const std::string within = cli::render_svg(explain::compute(unit_box(), Cylinder<double>{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.4375, 1}, true), "");
    EXPECT_NE(within.find(">Intersects (touching within rounding)<"), std::string::npos);
}

TEST(ExplainSvg, EmptySlabSaysSoAndDrawsNoPolygon) {
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{0.5, 0.5, 5}, {0, 0, 1}, 1, 1});
    ASSERT_EQ(e.what, Case::outside_slab);
    const std::string svg = cli::render_svg(e, "");
    EXPECT_EQ(svg.find("id=\"polygon\""), std::string::npos);
    EXPECT_NE(svg.find("box ∩ slab is empty"), std::string::npos);
    EXPECT_NE(svg.find("id=\"disk\""), std::string::npos);
    EXPECT_NE(svg.find("id=\"axial\""), std::string::npos);
}

TEST(ExplainSvg, LabelsAreEscaped) {
    const Explanation e = explain::compute(unit_box(), Cylinder<double>{{1.5, 0.5, 0.5}, {0, 0, 1}, 0.4375, 1});
    const std::string svg = cli::render_svg(e, "\"<a & b>'\"");
    EXPECT_NE(svg.find("&quot;&lt;a &amp; b&gt;&apos;&quot;"), std::string::npos);
    EXPECT_EQ(svg.find("<a "), std::string::npos);
}

TEST(ExplainSvg, OverflowingCoordinatesGetTheVerdictOnly) {
    // Valid inputs whose differences overflow double: no picture, but a well-defined document.
    const Explanation e = explain::compute(AlignedBox<double>{{-1.7e308, 0, 0}, {1.7e308, 1, 1}},
                                           Cylinder<double>{{1.7e308, 0.5, 0.5}, {1, 1, 0}, 1, 1});
    EXPECT_FALSE(e.drawable);
    EXPECT_EQ(e.what, Case::not_drawable);
    const std::string svg = cli::render_svg(e, "");
    EXPECT_NE(svg.find("Not drawable"), std::string::npos);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
}

// Coordinates near the double range and subnormal ones: the picture's distances are right or say
// that they exceed the range, and no sentence or label says NaN (the segment and polygon arithmetic
// used to take ∞ − ∞ or 0/0 there).
TEST(ExplainSvg, ExtremeCoordinatesNeverGiveNaN) {
    const std::array<Vec3<double>, 3> frame{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const Cylinder<double> c{{0, 0, 0.5}, {0, 0, 1}, 1, 1};
    // A segment from (−1e308, −1e308) to (1e308, −1e308) seen along the axis: its ends differ by 2e308.
    const Explanation wide = explain::compute(Parallelepiped<double>{{0, -1e308, 0.5}, frame, {1e308, 0, 0.25}}, c);
    EXPECT_TRUE(wide.drawable);
    EXPECT_EQ(wide.what, Case::gap);
    EXPECT_EQ(wide.closest.x, 0.0);
    EXPECT_EQ(wide.closest.y, -1e308);
    EXPECT_EQ(wide.distance, 1e308);
    std::string svg = cli::render_svg(wide, "");
    EXPECT_EQ(svg.find("NaN"), std::string::npos);
    EXPECT_NE(svg.find(">gap 1e+308 (distance − radius).<"), std::string::npos);
    // A point 1.5e308 from the axis in x and in y: its distance, 2.1e308, is beyond the range.
    const Explanation far = explain::compute(OrientedBox<double>{{1e308, 1e308, 0.5}, frame, {0, 0, 0.5}},
                                             Cylinder<double>{{-0.5e308, -0.5e308, 0.5}, {0, 0, 1}, 1, 1});
    EXPECT_TRUE(far.drawable);
    EXPECT_EQ(far.what, Case::gap);
    EXPECT_EQ(far.closest.x, 1.5e308);
    EXPECT_EQ(far.closest.y, 1.5e308);
    svg = cli::render_svg(far, "");
    EXPECT_EQ(svg.find("NaN"), std::string::npos);
    EXPECT_EQ(svg.find("∞"), std::string::npos);
    EXPECT_NE(svg.find(">gap more than 1.79769e+308 (distance − radius).<"), std::string::npos);
    // Subnormal: a segment of length 2e-320 at distance d = 1e-321 (both subnormal), radius 2d.
    const double d = 1e-321;
    const Explanation tiny = explain::compute(Parallelepiped<double>{{0, d, 0.5}, frame, {1e-320, 0, 0.25}},
                                              Cylinder<double>{{0, 0, 0.5}, {0, 0, 1}, 2 * d, 1});
    EXPECT_TRUE(tiny.drawable);
    EXPECT_EQ(tiny.closest.x, 0.0);
    EXPECT_EQ(tiny.closest.y, d);
    EXPECT_EQ(tiny.distance, d);
    EXPECT_EQ(tiny.what, Case::overlap);
    svg = cli::render_svg(tiny, "");
    EXPECT_EQ(svg.find("NaN"), std::string::npos);
}

}  // namespace
}  // namespace boxcyl
