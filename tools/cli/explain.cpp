// See explain.hpp. Plain string building: the document is small and fully determined by the numbers,
// so an XML library would add a dependency and nothing else. Every text goes through xml_escape; every
// number through num() or px() (finite, no locale).
#include "explain.hpp"

#include <algorithm>  // std::min, std::max
#include <array>      // view axes
#include <cerrno>     // errno after a failed open
#include <cmath>      // std::isfinite, std::cos, std::sin
#include <cstdio>     // std::snprintf
#include <cstdlib>    // std::strtod
#include <cstring>    // std::strerror
#include <istream>    // the input
#include <limits>     // the double range (amount), skipping whole lines
#include <memory>     // the input file
#include <numbers>    // std::numbers::pi
#include <ostream>    // the output
#include <sstream>    // several_lines
#include <string>
#include <type_traits>  // the box kind in input_lines
#include <variant>    // std::visit over the box kinds
#include <vector>

#include <CLI/CLI.hpp>

#include <fcntl.h>   // open (the -o file)
#include <unistd.h>  // close

#include "app.hpp"
#include "io.hpp"
#include "jsonl_query.hpp"

namespace boxcyl::cli {

namespace {

using explain::Case;
using explain::Explanation;
using explain::Point2;

// --- text and numbers -------------------------------------------------------------------------

std::string xml_escape(const std::string& s) {
    std::string r;
    r.reserve(s.size());
    for (char c : s) {
        switch (c) {
            case '&': r += "&amp;"; break;
            case '<': r += "&lt;"; break;
            case '>': r += "&gt;"; break;
            case '"': r += "&quot;"; break;
            case '\'': r += "&apos;"; break;
            default: r += c;
        }
    }
    return r;
}

// A value for people: `digits` significant digits (6 by default), "0" for ±0, a true minus sign.
std::string num(double x, int digits = 6) {
    if (x == 0) return "0";
    if (!std::isfinite(x)) return x != x ? "NaN" : (x > 0 ? "∞" : "−∞");
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, std::fabs(x));
    return (x < 0 ? "−" : "") + std::string(buf);
}

// As num(), with the digits reading it back needs (6 to 17): a margin decides at one ulp, so the
// double below 0.0625 must not read "0.0625".
std::string num_exact(double x) {
    for (int d = 6; d < 17; ++d) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.*g", d, x);
        if (std::strtod(buf, nullptr) == x) return num(x, d);
    }
    return num(x, 17);
}

// A distance, gap or overlap for the sentences: as num(), but one beyond the double range (computed as
// +∞) is "more than 1.79769e+308", and one that could not be computed at all says so (never "NaN").
std::string amount(double x) {
    if (std::isfinite(x)) return num(x);
    if (x != x) return "(too large to compute in double precision)";
    return std::string(x > 0 ? "" : "−") + "more than " + num(std::numeric_limits<double>::max());
}

// The fewest digits (6 to 17) at which values that differ also print differently: a box one ulp
// beyond an end plane must not read "1 … 1".
int distinguishing_digits(std::initializer_list<double> values) {
    for (int d = 6; d < 17; ++d) {
        bool ok = true;
        for (double a : values)
            for (double b : values)
                if (a != b && num(a, d) == num(b, d)) ok = false;
        if (ok) return d;
    }
    return 17;
}

std::string vec(const Vec3<double>& v) { return "(" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + ")"; }

// A pixel coordinate: finite, bounded (far-away geometry is clipped anyway), 2 decimals.
std::string px(double x) {
    if (!std::isfinite(x)) x = 0;
    x = std::clamp(x, -1e5, 1e5);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", x);
    return buf;
}

// --- 2-D mapping --------------------------------------------------------------------------------

struct Rect {
    double x, y, w, h;
};

// World (a, b) → pixels: uniform scale, b up, the world centre at the rectangle's centre.
struct Mapping {
    double ca = 0, cb = 0, scale = 1, px = 0, py = 0;
    double x(double a) const { return px + scale * (a - ca); }
    double y(double b) const { return py - scale * (b - cb); }
};

struct Extent {
    double amin = 0, amax = 0, bmin = 0, bmax = 0;
    bool any = false;
    void add(double a, double b) {
        if (!std::isfinite(a) || !std::isfinite(b)) return;
        if (!any) {
            amin = amax = a, bmin = bmax = b, any = true;
            return;
        }
        amin = std::min(amin, a), amax = std::max(amax, a), bmin = std::min(bmin, b), bmax = std::max(bmax, b);
    }
    double width() const { return amax - amin; }
    double height() const { return bmax - bmin; }
};

// Largest scale that fits `e` into `r` with a margin; a zero-size extent gets one unit.
double fit_scale(const Extent& e, const Rect& r, double margin) {
    const double w = e.width(), h = e.height();
    double s = 0;
    if (w > 0) s = (r.w - 2 * margin) / w;
    if (h > 0) s = s > 0 ? std::min(s, (r.h - 2 * margin) / h) : (r.h - 2 * margin) / h;
    if (!(s > 0) || !std::isfinite(s)) s = (std::min(r.w, r.h) - 2 * margin) / 2;
    return s;
}

Mapping centred(const Extent& e, const Rect& r, double scale) {
    return {(e.amin + e.amax) / 2, (e.bmin + e.bmax) / 2, scale, r.x + r.w / 2, r.y + r.h / 2};
}

// --- SVG building -------------------------------------------------------------------------------

class Svg {
public:
    std::string s;

    Svg& raw(const std::string& t) {
        s += t;
        return *this;
    }
    void text(double x, double y, const std::string& t, const std::string& attrs = "") {
        s += "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\"" + (attrs.empty() ? "" : " " + attrs) + ">" +
             xml_escape(t) + "</text>\n";
    }
    void line(double x1, double y1, double x2, double y2, const std::string& attrs) {
        s += "<line x1=\"" + px(x1) + "\" y1=\"" + px(y1) + "\" x2=\"" + px(x2) + "\" y2=\"" + px(y2) + "\" " + attrs +
             "/>\n";
    }
    void rect(const Rect& r, const std::string& attrs) {
        s += "<rect x=\"" + px(r.x) + "\" y=\"" + px(r.y) + "\" width=\"" + px(r.w) + "\" height=\"" + px(r.h) + "\" " +
             attrs + "/>\n";
    }
    void circle(double cx, double cy, double r, const std::string& attrs) {
        s += "<circle cx=\"" + px(cx) + "\" cy=\"" + px(cy) + "\" r=\"" + px(r) + "\" " + attrs + "/>\n";
    }
    // A closed polygon (3+ points), else a polyline (2 points) or a dot (1 point), so that degenerate
    // shapes stay visible.
    void shape(const std::vector<std::pair<double, double>>& pts, const std::string& attrs) {
        if (pts.empty()) return;
        if (pts.size() == 1) {
            circle(pts[0].first, pts[0].second, 3, attrs);
            return;
        }
        std::string p;
        for (const auto& [x, y] : pts) p += px(x) + "," + px(y) + " ";
        p.pop_back();
        s += std::string(pts.size() == 2 ? "<polyline" : "<polygon") + " points=\"" + p + "\" " + attrs + "/>\n";
    }
};

// Colours: blue for the box (∩ slab), orange for the cylinder, red for the gap, grey for context.
constexpr const char* blue_fill = "#7fb2e5";
constexpr const char* blue_line = "#1f5fa8";
constexpr const char* orange_fill = "#f8c987";
constexpr const char* orange_line = "#c77800";
constexpr const char* red = "#d0021b";
constexpr const char* grey = "#8a8a8a";
constexpr const char* text_dark = "#222";
// The cylinder grown by the margin: its outline, dashed (a boundary, not a solid of the query).
std::string margin_line() {
    return "fill=\"none\" stroke=\"" + std::string(orange_line) + "\" stroke-width=\"1.6\" stroke-dasharray=\"7,4\"";
}
// The nearest pair (boxcyl::distance): purple, a colour no other mark uses.
constexpr const char* purple = "#7b1fa2";

const char* verdict_colour(const Explanation& e) {
    if (e.what == Case::touching_within_rounding && !e.margin) return "#9a5b00";
    return e.verdict() ? "#1a7f37" : "#c62828";
}

std::string verdict_title(const Explanation& e) {
    if (e.margin)
        return std::string(e.exact_within ? "Within" : "Not within") + " distance " + num_exact(*e.margin) +
               (e.exact_intersects ? " (intersects)" : "");
    std::string t = e.exact_intersects ? "Intersects" : "Does not intersect";
    if (e.what == Case::touching) t += " (touching)";
    if (e.what == Case::touching_end_plane) t += " (touching an end)";
    if (e.what == Case::touching_within_rounding) t += " (touching within rounding)";
    return t;
}

// The sentences under the title: what the picture shows, in the picture's words.
std::vector<std::string> plane_lines(const Explanation& e) {
    const std::string d = amount(e.distance), r = num(e.radius);
    switch (e.what) {
        case Case::axis_through:
            return {"The cylinder's axis passes through the blue polygon (distance 0 ≤ radius " + r + "),",
                    "so the axis itself meets the box between the end planes."};
        case Case::overlap:
            return {"The blue polygon comes within " + d + " of the axis, inside the orange disk of radius " + r +
                        ":",
                    "overlap " + amount(-e.gap()) + " (radius − distance)."};
        case Case::touching:
            return {"The blue polygon touches the orange disk: distance = radius = " + r + ".",
                    "Both solids are closed, so touching counts as intersecting."};
        case Case::touching_end_plane:
            return {"The box only touches one of the cylinder's end planes (see 'along the axis'), and there",
                    "the blue polygon reaches the disk (distance " + d + " ≤ radius " + r +
                        "). Touching counts as intersecting."};
        case Case::touching_within_rounding:
            // Which boundary is within rounding: an end plane (along the axis) or the side (in the plane).
            if (e.slab_empty || std::fabs(e.axial_gap()) < std::fabs(e.gap()))
                return {std::string(e.exact_intersects ? "Exact answer: they meet." : "Exact answer: they do not meet.") +
                            " The box is within rounding of an end plane of the cylinder: this picture,",
                        "drawn in double precision, puts it " +
                            std::string(e.slab_empty ? "just beyond" : "just inside") +
                            " (see 'along the axis'), which double precision cannot tell apart."};
            if (e.exact_intersects)
                return {"Exact answer: they touch or overlap. This picture is drawn in double precision and shows a gap of " +
                            amount(e.gap()) + ",",
                        "which is rounding error: the solids are closer than double precision can draw."};
            return {"Exact answer: they do not meet. This picture is drawn in double precision and shows " +
                        std::string(e.gap() < 0 ? "an overlap of " + amount(-e.gap()) : "them touching") + ",",
                    "but the true gap is smaller than double precision can draw."};
        case Case::gap:
            return {"The blue polygon stays " + d + " from the axis, outside the orange disk of radius " + r + ":",
                    "gap " + amount(e.gap()) + " (distance − radius)."};
        case Case::outside_slab: {
            const bool above = e.box_axial_min > e.half_height;
            return {"No part of the box lies between the cylinder's end planes: the whole box is " +
                        std::string(above ? "beyond the +axis end" : "beyond the −axis end") + " (see 'along the axis').",
                    "So there is no blue polygon; the end-plane test (the slab cull) alone decides."};
        }
        case Case::not_drawable:
            return {"The coordinates are too large to draw in double precision (they overflow);",
                    "the verdict above is still the exact answer."};
    }
    return {};
}

// With a margin, a first sentence for the verdict (the rest explains the cylinder itself).
std::vector<std::string> verdict_lines(const Explanation& e) {
    std::vector<std::string> lines = plane_lines(e);
    if (!e.margin) return lines;
    const std::string m = num_exact(*e.margin);
    std::string first;
    if (!e.exact_within)
        first = "Exact answer: the box is farther than " + m + " from the cylinder; it misses the cylinder grown by " + m +
                " (dashed).";
    else if (e.exact_intersects)
        first = "Exact answer: within " + m + ", since the box meets the cylinder itself (distance 0).";
    else
        first = "Exact answer: the box misses the cylinder but comes within " + m + " of it: it meets the cylinder grown by " +
                m + " (dashed).";
    lines.insert(lines.begin(), first);
    return lines;
}

// Frame and caption of a panel.
void panel(Svg& svg, const Rect& r, const std::string& caption) {
    svg.rect(r, "fill=\"#fbfbfd\" stroke=\"#c8c8d0\"");
    svg.text(r.x + 8, r.y + 18, caption, "font-size=\"13\" font-weight=\"bold\" fill=\"#444\"");
}

// A clip path for a panel, so far-away geometry stays inside it.
std::string clip_def(const std::string& id, const Rect& r) {
    return "<clipPath id=\"" + id + "\"><rect x=\"" + px(r.x) + "\" y=\"" + px(r.y) + "\" width=\"" + px(r.w) +
           "\" height=\"" + px(r.h) + "\"/></clipPath>\n";
}

// --- the main panel: the plane ⊥ axis -------------------------------------------------------------

constexpr double main_caption = 46;  // the caption and note band; the drawing is clipped below it

// Approximate rendered width of a text (sans-serif averages ~0.6 em per character; bold a bit more).
double text_width(const std::string& t, double size, bool bold) {
    double chars = 0;
    for (unsigned char c : t)
        if ((c & 0xC0) != 0x80) chars += 1;  // count UTF-8 code points, not bytes
    return chars * size * (bold ? 0.64 : 0.58);
}

// A label at (x, y) anchored "start", "middle" or "end", moved to stay inside [lo, hi] horizontally.
void label(Svg& svg, double x, double y, const std::string& t, const std::string& anchor, double size, bool bold,
           const std::string& fill, double lo, double hi) {
    const double w = text_width(t, size, bold);
    double left = anchor == "start" ? x : anchor == "end" ? x - w : x - w / 2;
    left = std::max(lo, std::min(left, hi - w));
    // A white halo keeps labels legible over the filled shapes.
    svg.text(left, y, t, "font-size=\"" + px(size) + "\"" + (bold ? " font-weight=\"bold\"" : "") + " fill=\"" + fill +
                             "\" stroke=\"#fff\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\"");
}

// --- the nearest pair, in any view -------------------------------------------------------------

// A world point seen along the axis: the plane coordinates the box vertices take in the main panel.
Point2 in_plane(const Explanation& e, const Vec3<double>& x) {
    const Vec3<double> d = x - e.center;
    return {dot(e.e1, d), dot(e.e2, d)};
}

// The pair drawn: the depth pair where there is one, else the nearest pair.
std::optional<std::pair<Vec3<double>, Vec3<double>>> marked_pair(const Explanation& e) {
    if (e.depth) return std::pair{e.depth->on_box, e.depth->on_cylinder};
    if (e.nearest) return std::pair{e.nearest->on_box, e.nearest->on_cylinder};
    return std::nullopt;
}

// The nearest pair in one view, `to2` the view's mapping of world points to pixels (the one its box
// vertices take): a dot on each solid (ringed in the solid's colour) and the segment between them.
// For intersecting solids (upper = 0) the witnesses are near one common point, and only it is drawn:
// a segment of rounding length would show nothing, and the point says where the solids meet. Where they
// overlap and the signed distance is given, the depth pair is drawn instead, as a pair apart is: the
// deepest point of each solid along the separating direction, and the segment between them.
template <class To2>
void nearest_marks(Svg& svg, const Explanation& e, const std::string& id, const To2& to2) {
    const auto pair = marked_pair(e);
    if (!pair) return;
    const auto a = to2(pair->first), b = to2(pair->second);
    // Witnesses whose pixels overflow (coordinates near the double range) have no place to be drawn.
    for (double v : {a.first, a.second, b.first, b.second})
        if (!std::isfinite(v)) return;
    const auto mark = [&](const std::pair<double, double>& p, const char* ring) {
        svg.circle(p.first, p.second, 3.5,
                   "fill=\"" + std::string(purple) + "\" stroke=\"" + ring + "\" stroke-width=\"1.2\"");
    };
    svg.raw("<g id=\"" + id + "\" class=\"nearest\">\n");
    if (e.nearest->upper == 0 && !e.depth) {
        mark(a, "#fff");
    } else {
        svg.line(a.first, a.second, b.first, b.second, "stroke=\"" + std::string(purple) + "\" stroke-width=\"1.5\"");
        mark(a, blue_line);
        mark(b, orange_line);
    }
    svg.raw("</g>\n");
}

// The one label of the nearest (or depth) pair, with every digit the bounds need (they are a few ulps
// apart).
std::string nearest_text(const Explanation& e) {
    const Distance& d = *e.nearest;
    if (e.depth)
        return "Overlapping: penetration depth in [" + num_exact(-e.depth->upper) + ", " + num_exact(-e.depth->lower) +
               "] (boxcyl::signed_distance, proved); purple marks the deepest points.";
    if (d.upper == 0)
        return "Nearest points, distance 0: the solids intersect; purple marks a common point (boxcyl::distance).";
    if (!std::isfinite(d.upper))
        return "Nearest points, distance at least " + num_exact(d.lower) +
               ", beyond the double range (boxcyl::distance).";
    return "Nearest points, distance in [" + num_exact(d.lower) + ", " + num_exact(d.upper) +
           "] (boxcyl::distance, proved).";
}

void main_panel(Svg& svg, const Explanation& e, const Rect& r) {
    panel(svg, r, "Looking along the cylinder's axis (the plane ⊥ axis through its centre)");
    svg.raw("<g clip-path=\"url(#clip-main)\">\n");

    // Fit what matters: the polygon, the disk, the axis point (the whole box may be far larger).
    Extent ext;
    const double reach = e.margin ? e.radius + *e.margin : e.radius;  // the grown cylinder's disk, if any
    ext.add(-reach, -reach), ext.add(reach, reach), ext.add(0, 0);
    for (const Point2& p : e.polygon) ext.add(p.x, p.y);
    if (ext.width() == 0 && ext.height() == 0)
        for (const Point2& p : e.box_shadow) ext.add(p.x, p.y);
    if (const auto pair = marked_pair(e))  // the marked pair in sight (the box's may lie beyond the slab)
        for (const Vec3<double>& w : {pair->first, pair->second}) {
            const Point2 p = in_plane(e, w);
            ext.add(p.x, p.y);
        }
    // Square extent so that the picture sits centred.
    const double half = std::max(ext.width(), ext.height()) / 2;
    const double ca = (ext.amin + ext.amax) / 2, cb = (ext.bmin + ext.bmax) / 2;
    ext = {ca - half, ca + half, cb - half, cb + half, true};
    const Rect inner{r.x, r.y + main_caption, r.w, r.h - main_caption - 40};
    const Mapping m = centred(ext, inner, fit_scale(ext, inner, 70));

    auto pts = [&](const std::vector<Point2>& poly) {
        std::vector<std::pair<double, double>> out;
        out.reserve(poly.size());
        for (const Point2& p : poly) out.emplace_back(m.x(p.x), m.y(p.y));
        return out;
    };
    const std::string dashed = "stroke=\"" + std::string(grey) + "\" stroke-width=\"1\" stroke-dasharray=\"5,4\"";

    // Layers: the whole box's shadow (context), the polygon, the disk over it (translucent, so the
    // overlap shows), then both outlines again so that neither hides the other.
    svg.raw("<g id=\"box-shadow\">\n");
    svg.shape(pts(e.box_shadow), "fill=\"#ececec\" " + dashed);
    svg.raw("</g>\n");
    const std::string poly_fill = "fill=\"" + std::string(blue_fill) + "\" stroke=\"none\"";
    const std::string poly_line = "fill=\"none\" stroke=\"" + std::string(blue_line) + "\" stroke-width=\"2\" stroke-linejoin=\"round\"";
    const double rpx = e.radius * m.scale;
    const std::string disk_line = "fill=\"none\" stroke=\"" + std::string(orange_line) + "\" stroke-width=\"2\"";
    if (!e.polygon.empty()) {
        svg.raw("<g id=\"polygon\">\n");
        svg.shape(pts(e.polygon), poly_fill);
        svg.shape(pts(e.polygon), poly_line);
        for (const Point2& p : e.polygon) svg.circle(m.x(p.x), m.y(p.y), 3, "fill=\"" + std::string(blue_line) + "\"");
        svg.raw("</g>\n");
    }
    svg.raw("<g id=\"disk\">\n");
    svg.circle(m.x(0), m.y(0), rpx, "fill=\"" + std::string(orange_fill) + "\" fill-opacity=\"0.85\" stroke=\"none\"");
    svg.circle(m.x(0), m.y(0), rpx, disk_line);
    svg.raw("</g>\n");
    if (!e.polygon.empty()) svg.shape(pts(e.polygon), poly_line);
    svg.shape(pts(e.box_shadow), "fill=\"none\" " + dashed);
    if (e.margin) {
        // Seen along the axis, the cylinder grown by m is the disk of radius r + m.
        svg.raw("<g id=\"margin\">\n");
        svg.circle(m.x(0), m.y(0), reach * m.scale, margin_line());
        svg.raw("</g>\n");
    }

    // Screen direction from the axis towards the closest point (to the right when there is none),
    // and its perpendicular; labels go beside lines, never on them.
    double dx = 1, dy = 0;
    if (e.distance > 0) {  // the direction of `closest`, scaled first so that a distance beyond the range still has one
        const double m = std::max(std::fabs(e.closest.x), std::fabs(e.closest.y));
        const double ux = e.closest.x / m, uy = e.closest.y / m, len = std::hypot(ux, uy);
        dx = ux / len, dy = uy / len;
    }
    const double sx = dx, sy = -dy;  // screen y points down
    const double nx = -sy, ny = sx;  // perpendicular
    auto anchor = [](double x) { return std::string(x > 0.35 ? "start" : x < -0.35 ? "end" : "middle"); };
    const double lo = r.x + 6, hi = r.x + r.w - 6;

    // Radius: drawn away from the gap; its label just beyond the rim.
    if (e.radius > 0) {
        const double ex = m.x(0) - sx * rpx, ey = m.y(0) - sy * rpx;
        svg.line(m.x(0), m.y(0), ex, ey, "stroke=\"" + std::string(orange_line) + "\" stroke-width=\"1.5\"");
        label(svg, ex - sx * 8, ey - sy * 8 + 5, "radius " + num(e.radius), anchor(-sx), 13, true, orange_line, lo, hi);
    }
    // The grown disk's label beside its rim, across from the gap and the radius.
    if (e.margin) {
        const double gx = m.x(0) + nx * reach * m.scale, gy = m.y(0) + ny * reach * m.scale;
        label(svg, gx + nx * 10, gy + ny * 10 + 5, "radius + margin " + num(reach), anchor(nx), 13, false, orange_line,
              lo, hi);
    }

    svg.raw("<g id=\"axis-point\">\n");
    svg.line(m.x(0) - 7, m.y(0), m.x(0) + 7, m.y(0), "stroke=\"#000\" stroke-width=\"1.5\"");
    svg.line(m.x(0), m.y(0) - 7, m.x(0), m.y(0) + 7, "stroke=\"#000\" stroke-width=\"1.5\"");
    if (e.distance > 0 || e.polygon.empty())
        label(svg, m.x(0) - 16 * nx, m.y(0) - 16 * ny + 5, "axis", anchor(-nx), 13, false, "#000", lo, hi);
    else
        label(svg, m.x(0) + 10, m.y(0) + 22, "axis (distance 0)", "start", 13, true, red, lo, hi);
    svg.raw("</g>\n");

    if (!e.polygon.empty()) {
        const double cx = m.x(e.closest.x), cy = m.y(e.closest.y);
        // Gap (or overlap) on the ray from the axis through the closest point, between the disk's rim
        // and the polygon.
        svg.raw("<g id=\"gap\">\n");
        if (e.distance > 0) {
            const double bx = m.x(0) + sx * rpx, by = m.y(0) + sy * rpx;
            svg.line(bx, by, cx, cy, "stroke=\"" + std::string(red) + "\" stroke-width=\"3\"");
            const std::string what = e.gap() > 0   ? "gap " + amount(e.gap())
                                     : e.gap() < 0 ? "overlap " + amount(-e.gap())
                                                   : "gap 0";
            label(svg, (bx + cx) / 2 - 16 * nx, (by + cy) / 2 - 16 * ny + 5, what, anchor(-nx), 15, true, red, lo, hi);
        }
        svg.raw("</g>\n");

        svg.raw("<g id=\"closest\">\n");
        svg.circle(cx, cy, 5.5, "fill=\"" + std::string(red) + "\" stroke=\"#fff\" stroke-width=\"1.5\"");
        if (e.distance > 0)  // at distance 0 the point is the axis point, and the title says so
            label(svg, cx + 12 * sx + 16 * nx, cy + 12 * sy + 16 * ny + 5, "closest point, distance " + amount(e.distance),
                  anchor(sx), 13, false, red, lo, hi);
        svg.raw("</g>\n");
    }
    nearest_marks(svg, e, "nearest", [&](const Vec3<double>& w) {
        const Point2 p = in_plane(e, w);
        return std::pair<double, double>{m.x(p.x), m.y(p.y)};
    });
    svg.raw("</g>\n");

    // Notes under the caption for the degenerate pictures.
    std::string note;
    if (!e.drawable) note = "Not drawable: the coordinates overflow double precision.";
    else if (e.polygon.empty()) note = "box ∩ slab is empty: no polygon (the box is beyond an end plane).";
    else if (e.polygon.size() == 1) note = "Seen along the axis, box ∩ slab is a single point.";
    else if (e.polygon.size() == 2) note = "Seen along the axis, box ∩ slab is a segment.";
    if (!note.empty()) svg.text(r.x + 8, r.y + 38, note, "font-size=\"13\" font-weight=\"bold\" fill=\"#c62828\"");

    // The plane's frame in world coordinates, to relate this view to the 3-D ones; the axis points at
    // the viewer (⊙).
    const double ox = r.x + 22, oy = r.y + r.h - 22;
    svg.line(ox, oy, ox + 36, oy, "stroke=\"#555\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"");
    svg.line(ox, oy, ox, oy - 36, "stroke=\"#555\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"");
    svg.circle(ox, oy, 5, "fill=\"#fff\" stroke=\"#555\" stroke-width=\"1.2\"");
    svg.circle(ox, oy, 1.5, "fill=\"#555\"");
    svg.text(ox + 44, oy + 4, "e1 = " + vec(e.e1), "font-size=\"11\" fill=\"#555\"");
    svg.text(ox + 6, oy - 42, "e2 = " + vec(e.e2), "font-size=\"11\" fill=\"#555\"");
    svg.text(ox + 12, oy - 10, "axis u = " + vec(e.direction) + ", towards you", "font-size=\"11\" fill=\"#555\"");
}

// --- the axial strip: the slab and the box along the axis -----------------------------------------

void axial_strip(Svg& svg, const Explanation& e, const Rect& r) {
    svg.raw("<g id=\"axial\">\n");
    panel(svg, r, "Along the axis (position t = u·(X − C), C the cylinder's centre)");
    if (!e.drawable) {
        svg.text(r.x + 10, r.y + 50, "not drawable: the positions overflow double precision", "font-size=\"12\" fill=\"#c62828\"");
        svg.raw("</g>\n");
        return;
    }
    const double grown = e.half_height + (e.margin ? *e.margin : 0);  // the grown cylinder's reach along the axis
    const double lo = std::min(-grown, e.box_axial_min), hi = std::max(grown, e.box_axial_max);
    const double span = hi > lo ? hi - lo : 1;
    const double x0 = r.x + 170, x1 = r.x + r.w - 120;
    auto X = [&](double t) { return x0 + (x1 - x0) * (t - lo) / span - (hi > lo ? 0 : (x1 - x0) / 2); };
    const double y1 = r.y + 36, y2 = r.y + 62;
    const int digits = distinguishing_digits({-e.half_height, e.half_height, e.box_axial_min, e.box_axial_max});
    // A band from a to b, its end values outside [a − reach, b + reach] (clear of the grown cylinder's outline).
    auto band = [&](double a, double b, double y, const char* fill, const char* stroke, const std::string& name,
                    double reach = 0) {
        double xa = X(a), xb = X(b);
        if (xb - xa < 3) xa -= 1.5, xb += 1.5;  // a point stays visible
        svg.rect({xa, y - 8, xb - xa, 16}, "fill=\"" + std::string(fill) + "\" stroke=\"" + stroke + "\"");
        svg.text(r.x + 10, y + 5, name, "font-size=\"12\" fill=\"" + std::string(text_dark) + "\"");
        const double la = std::min(xa, X(a - reach)), lb = std::max(xb, X(b + reach));
        if (a != b) svg.text(la - 4, y + 5, num(a, digits), "font-size=\"11\" fill=\"#555\" text-anchor=\"end\"");
        svg.text(lb + 4, y + 5, num(b, digits), "font-size=\"11\" fill=\"#555\"");
    };
    band(-e.half_height, e.half_height, y1, orange_fill, orange_line, "cylinder (slab)", grown - e.half_height);
    if (e.margin) {  // the grown cylinder reaches m beyond each end plane
        const double xa = X(-grown), xb = X(grown);
        svg.rect({xa, y1 - 11, xb - xa, 22}, margin_line());
    }
    band(e.box_axial_min, e.box_axial_max, y2, blue_fill, blue_line, "box");
    svg.raw("</g>\n");
}

// --- the orthographic views ---------------------------------------------------------------------

struct View {
    const char* id;
    const char* caption;
    int a, b;  // the world coordinates drawn right and up
};

constexpr std::array<View, 3> views{{
    {"view-top", "Top view (x →, y ↑)", 0, 1},
    {"view-front", "Front view (x →, z ↑)", 0, 2},
    {"view-side", "Side view (y →, z ↑)", 1, 2},
}};

// Points of the cylinder's two end circles (the outline of its projection is their convex hull).
// Points of the circle of the cylinder at axial position t.
std::vector<Vec3<double>> rim_points(const Explanation& e, double t, int n) {
    std::vector<Vec3<double>> p;
    const Vec3<double> c = e.center + t * e.direction;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        p.push_back(c + (e.radius * std::cos(a)) * e.e1 + (e.radius * std::sin(a)) * e.e2);
    }
    return p;
}

void ortho_views(Svg& svg, const Explanation& e, const std::array<Rect, 3>& rects) {
    const int n = 72;
    const double hh = e.half_height;
    const std::vector<Vec3<double>> top = rim_points(e, hh, n), bottom = rim_points(e, -hh, n);

    // Framing: the box and the part of the cylinder near it along the axis, so that a long cylinder
    // does not shrink the box to a dot (the rest of it runs out of the clipped view). The part is the
    // box's axial range widened by about its size, within the cylinder; or the cylinder's end nearest
    // the box when the two ranges are apart.
    double size = 2 * e.radius;
    for (const auto& v : e.box_vertices)
        for (int i = 0; i < 3; ++i) size = std::max(size, std::fabs(v[i] - e.box_vertices[0][i]));
    double ta = std::max(-hh, e.box_axial_min - size), tb = std::min(hh, e.box_axial_max + size);
    if (ta > tb) {
        const double reach = std::min(2 * hh, size);
        if (e.box_axial_min > hh) ta = hh - reach, tb = hh;
        else ta = -hh, tb = -hh + reach;
    }
    const std::vector<Vec3<double>> near_a = rim_points(e, ta, n), near_b = rim_points(e, tb, n);
    const double margin = e.margin ? *e.margin : 0;

    // One scale for the three views, so sizes compare across them.
    double scale = 0;
    std::array<Extent, 3> ext;
    for (std::size_t k = 0; k < views.size(); ++k) {
        const View& v = views[k];
        for (const auto& p : e.box_vertices) ext[k].add(p[v.a], p[v.b]);
        if (const auto pair = marked_pair(e))
            for (const Vec3<double>& w : {pair->first, pair->second}) ext[k].add(w[v.a], w[v.b]);
        for (const auto* rim : {&near_a, &near_b})
            for (const auto& p : *rim) {
                ext[k].add(p[v.a] - margin, p[v.b] - margin);
                ext[k].add(p[v.a] + margin, p[v.b] + margin);
            }
        const Rect inner{rects[k].x, rects[k].y + 22, rects[k].w, rects[k].h - 22};
        const double s = fit_scale(ext[k], inner, 14);
        scale = k == 0 ? s : std::min(scale, s);
    }

    for (std::size_t k = 0; k < views.size(); ++k) {
        const View& v = views[k];
        const Rect& r = rects[k];
        svg.raw("<g id=\"" + std::string(v.id) + "\">\n");
        panel(svg, r, v.caption);
        svg.raw("<clipPath id=\"clip-" + std::string(v.id) + "\"><rect x=\"" + px(r.x) + "\" y=\"" + px(r.y + 22) +
                "\" width=\"" + px(r.w) + "\" height=\"" + px(r.h - 22) + "\"/></clipPath>\n<g clip-path=\"url(#clip-" +
                v.id + ")\">\n");
        const Rect inner{r.x, r.y + 22, r.w, r.h - 22};
        const Mapping m = centred(ext[k], inner, scale);
        auto to2 = [&](const Vec3<double>& p) { return std::pair<double, double>{m.x(p[v.a]), m.y(p[v.b])}; };
        auto hull_of = [&](const std::vector<Vec3<double>>& pts) {
            std::vector<Point2> q;
            q.reserve(pts.size());
            for (const auto& p : pts) q.push_back({p[v.a], p[v.b]});
            std::vector<std::pair<double, double>> out;
            for (const Point2& h : algo::hull2d::monotone_chain(std::move(q))) out.emplace_back(m.x(h.x), m.y(h.y));
            return out;
        };

        // Box ∩ slab first, the cylinder translucent over it (so neither hides the other), then the
        // cylinder's rims and axis and the box's edges and vertices (a point box stays visible).
        if (!e.section.empty())
            svg.shape(hull_of(e.section), "fill=\"" + std::string(blue_fill) + "\" stroke=\"none\"");
        std::vector<Vec3<double>> both = top;
        both.insert(both.end(), bottom.begin(), bottom.end());
        svg.shape(hull_of(both), "fill=\"" + std::string(orange_fill) + "\" fill-opacity=\"0.85\" stroke=\"" +
                                     orange_line + "\" stroke-width=\"1.2\"");
        if (margin > 0) {
            // The grown cylinder projects to the cylinder's outline grown by a disk of radius m: around
            // each outline vertex a circle of radius m, and their hull (straight sides at r + m and
            // h/2 + m, corners rounded by m).
            std::vector<Point2> outline;
            outline.reserve(both.size());
            for (const auto& p : both) outline.push_back({p[v.a], p[v.b]});
            std::vector<Point2> grown;
            for (const Point2& q : algo::hull2d::monotone_chain(std::move(outline)))
                for (int i = 0; i < 24; ++i) {
                    const double a = 2 * std::numbers::pi * i / 24;
                    grown.push_back({q.x + margin * std::cos(a), q.y + margin * std::sin(a)});
                }
            std::vector<std::pair<double, double>> out;
            for (const Point2& h : algo::hull2d::monotone_chain(std::move(grown))) out.emplace_back(m.x(h.x), m.y(h.y));
            svg.shape(out, margin_line());
        }
        for (const auto* rim : {&top, &bottom}) {
            std::string p;
            for (const auto& q : *rim) p += px(to2(q).first) + "," + px(to2(q).second) + " ";
            p.pop_back();
            svg.raw("<polygon points=\"" + p + "\" fill=\"none\" stroke=\"" + orange_line +
                    "\" stroke-width=\"0.8\" stroke-opacity=\"0.7\"/>\n");
        }
        for (const auto& [a, b] : explain::box_edges) {
            const auto pa = to2(e.box_vertices[a]), pb = to2(e.box_vertices[b]);
            svg.line(pa.first, pa.second, pb.first, pb.second,
                     "stroke=\"" + std::string(blue_line) + "\" stroke-width=\"1.2\"");
        }
        for (const auto& v : e.box_vertices) {
            const auto p = to2(v);
            svg.circle(p.first, p.second, 1.8, "fill=\"" + std::string(blue_line) + "\"");
        }
        const auto c0 = to2(e.center + (-e.half_height) * e.direction), c1 = to2(e.center + e.half_height * e.direction);
        svg.line(c0.first, c0.second, c1.first, c1.second, "stroke=\"#000\" stroke-width=\"1\" stroke-dasharray=\"4,3\"");
        const auto cc = to2(e.center);
        svg.circle(cc.first, cc.second, 2, "fill=\"#000\"");
        nearest_marks(svg, e, std::string(v.id) + "-nearest", to2);  // ids stay unique: one group per view
        svg.raw("</g>\n</g>\n");
    }
}

// --- legend -------------------------------------------------------------------------------------

void legend(Svg& svg, const Rect& r, const Explanation& e) {
    svg.raw("<g id=\"legend\">\n");
    panel(svg, r, "Legend");
    double y = r.y + 40;
    const double x = r.x + 12, tx = r.x + 44;
    auto entry = [&](const std::string& swatch, std::initializer_list<const char*> lines) {
        svg.raw(swatch);
        double ly = y;
        for (const char* l : lines) {
            svg.text(tx, ly, l, "font-size=\"12\" fill=\"" + std::string(text_dark) + "\"");
            ly += 15;
        }
        y = ly + 7;
    };
    auto sq = [&](const char* fill, const char* stroke, const char* extra = "") {
        return "<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) + "\" width=\"24\" height=\"14\" fill=\"" + fill +
               "\" stroke=\"" + stroke + "\" " + extra + "/>\n";
    };
    entry(sq(blue_fill, blue_line), {"box ∩ slab: the part of the box between the", "cylinder's two end planes (main view: its shadow)"});
    entry(sq(orange_fill, orange_line), {"cylinder (main view: seen end-on, the disk of", "its radius; views: outline, end circles, axis)"});
    entry(sq("#eeeeee", grey, "stroke-dasharray=\"4,3\""), {"the whole box's shadow, for context"});
    entry("<circle cx=\"" + px(x + 12) + "\" cy=\"" + px(y - 4) + "\" r=\"5\" fill=\"" + red + "\"/>\n",
          {"closest point of the polygon to the axis"});
    entry("<line x1=\"" + px(x) + "\" y1=\"" + px(y - 4) + "\" x2=\"" + px(x + 24) + "\" y2=\"" + px(y - 4) +
              "\" stroke=\"" + red + "\" stroke-width=\"3\"/>\n",
          {"gap = distance − radius (overlap when < 0)"});
    if (e.margin)
        entry("<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) + "\" width=\"24\" height=\"14\" rx=\"5\" " +
                  margin_line() + "/>\n",
              {"the cylinder grown by the margin: every point", "within it of the cylinder (the verdict's solid)"});
    if (e.nearest) {
        const std::string ring = "\" stroke-width=\"1.2\"/>\n";
        entry("<line x1=\"" + px(x + 3) + "\" y1=\"" + px(y - 4) + "\" x2=\"" + px(x + 21) + "\" y2=\"" + px(y - 4) +
                  "\" stroke=\"" + purple + "\" stroke-width=\"1.5\"/>\n<circle cx=\"" + px(x + 3) + "\" cy=\"" +
                  px(y - 4) + "\" r=\"3.5\" fill=\"" + purple + "\" stroke=\"" + blue_line + ring + "<circle cx=\"" +
                  px(x + 21) + "\" cy=\"" + px(y - 4) + "\" r=\"3.5\" fill=\"" + purple + "\" stroke=\"" + orange_line + ring,
              {e.depth ? "deepest points of the box and the cylinder along" : "nearest points of the box and the cylinder",
               e.depth ? "the separating direction (boxcyl::signed_distance)"
                       : "(boxcyl::distance), and the segment joining them"});
    }
    svg.raw("</g>\n");
}

// The query's numbers (6 digits; the JSON has them all), one line per part so that lines fit.
std::vector<std::string> input_lines(const Query& q) {
    std::vector<std::string> lines;
    if (const auto* a = std::get_if<AlignedBox<double>>(&q.box)) {
        lines.push_back("box (aligned): min " + vec(a->min) + ", max " + vec(a->max));
    } else {
        std::visit(
            [&](const auto& o) {
                if constexpr (!std::is_same_v<std::decay_t<decltype(o)>, AlignedBox<double>>) {
                    const bool oriented = std::is_same_v<std::decay_t<decltype(o)>, OrientedBox<double>>;
                    lines.push_back(std::string(oriented ? "box (oriented)" : "box (parallelepiped)") + ": centre " +
                                    vec(o.center) + ", extents " + vec(o.extents));
                    lines.push_back("    axes " + vec(o.axes[0]) + ", " + vec(o.axes[1]) + ", " + vec(o.axes[2]));
                }
            },
            q.box);
    }
    const Cylinder<double>& c = q.cylinder;
    lines.push_back("cylinder: centre " + vec(c.center) + ", axis " + vec(c.axis) + ", radius " + num(c.radius) +
                    ", height " + num(c.height) + (q.margin ? "; margin " + num_exact(*q.margin) : ""));
    return lines;
}

std::string render(const Explanation& e, const std::string& label, const std::vector<std::string>& inputs) {
    // A margin (and a verdict line) and the nearest pair each add a legend entry: the page grows by its height.
    const double grow = (e.margin ? 37 : 0) + (e.nearest ? 37 : 0);
    const double W = 1040, H = 950 + grow;
    Svg svg;
    svg.raw("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    svg.raw("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(W) + "\" height=\"" + px(H) + "\" viewBox=\"0 0 " +
            px(W) + " " + px(H) + "\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n");
    const std::string title = "boxcyl explain" + (label.empty() ? "" : ": query " + label) + ": " + verdict_title(e);
    svg.raw("<title>" + xml_escape(title) + "</title>\n");

    const Rect main_r{24, 146, 600, 600}, axial_r{24, 756, 600, 80}, legend_r{650, 756, 366, 180 + grow};
    const std::array<Rect, 3> view_r{{{650, 146, 366, 192}, {650, 350, 366, 192}, {650, 554, 366, 192}}};
    svg.raw("<defs>\n<marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" "
            "markerHeight=\"7\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#555\"/></marker>\n" +
            clip_def("clip-main", {main_r.x, main_r.y + main_caption, main_r.w, main_r.h - main_caption}) + "</defs>\n");
    svg.rect({0, 0, W, H}, "fill=\"#fff\"");

    // Title block: the verdict (exact), what the picture shows, the inputs.
    svg.raw("<g id=\"verdict\">\n");
    svg.text(24, 44, verdict_title(e), "font-size=\"30\" font-weight=\"bold\" fill=\"" + std::string(verdict_colour(e)) + "\"");
    svg.text(W - 24, 44, label.empty() ? "" : "query " + label, "font-size=\"15\" fill=\"#555\" text-anchor=\"end\"");
    // Two sentences (three with a margin, closer together) above the inputs.
    const std::vector<std::string> sentences = verdict_lines(e);
    const double step = sentences.size() > 2 ? 16 : 18;
    double y = sentences.size() > 2 ? 66 : 70;
    for (const std::string& l : sentences) {
        svg.text(24, y, l, "font-size=\"14\" fill=\"" + std::string(text_dark) + "\"");
        y += step;
    }
    y = sentences.size() > 2 ? 112 : 106;
    for (const std::string& l : inputs) {
        svg.text(24, y, l, "font-size=\"11\" fill=\"#666\"");
        y += 13;
    }
    svg.raw("</g>\n");

    main_panel(svg, e, main_r);
    axial_strip(svg, e, axial_r);
    ortho_views(svg, e, view_r);
    legend(svg, legend_r, e);

    // For a newcomer: how to read the main panel, and where the verdict comes from.
    double ty = 858;
    for (const char* l : {
             "How to read this: seen along its axis, the cylinder is a disk. Only the part of the",
             "box between the cylinder's two end planes (the slab) can touch it; seen the same way,",
             "that part is the blue polygon. They intersect exactly when the polygon reaches the disk.",
             e.margin ? "The verdict is the exact answer of boxcyl::within_distance; the drawing is in double precision."
                      : "The verdict is the exact answer of boxcyl::intersects; the drawing is in double precision.",
         }) {
        svg.text(24, ty, l, "font-size=\"12\" fill=\"#444\"");
        ty += 16;
    }
    if (e.nearest) {  // smaller where the bounds need many digits, so that it stays left of the legend
        const std::string t = nearest_text(e);
        const double size = std::min(12.0, 12 * 600 / text_width(t, 12, false));
        svg.text(24, ty, t, "font-size=\"" + px(size) + "\" fill=\"" + std::string(purple) + "\"");
    }
    svg.raw("</svg>\n");
    return svg.s;
}

// The whole input, when it is at most `max_bytes` long: false when it is longer (then only part of it
// was read). A read error leaves `in` bad.
bool read_all(std::istream& in, std::size_t max_bytes, std::string& text) {
    text.clear();
    std::array<char, std::size_t{64} * 1024> chunk;
    while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0) {
        const auto got = static_cast<std::size_t>(in.gcount());
        if (text.size() + got > max_bytes) return false;
        text.append(chunk.data(), got);
    }
    return true;
}

// Skips whole lines of `in` until `line` (from 1) is next, without keeping them; the number of lines
// skipped (fewer when the input ends first).
std::size_t skip_lines(std::istream& in, std::size_t line) {
    std::size_t skipped = 0;
    while (skipped + 1 < line && stop_signal() == 0) {
        in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
        if (in.gcount() == 0) break;  // end of input (or a read error)
        ++skipped;
        if (in.eof()) break;  // a last line without newline
    }
    return skipped;
}

// More than one line with something on it (a JSON Lines file given without --line, most likely).
bool several_lines(const std::string& text) {
    std::istringstream lines(text);
    std::string l;
    int n = 0;
    while (std::getline(lines, l))
        if (l.find_first_not_of(" \t\r") != std::string::npos) ++n;
    return n > 1;
}

}  // namespace

std::string render_svg(const Explanation& e, const std::string& label, const std::vector<std::string>& inputs) {
    return render(e, label, inputs);
}

void add_explain_command(CLI::App& app, ExplainCommand& cmd) {
    cmd.app = app.add_subcommand(
        "explain", "Draw one query as an SVG picture: the view along the cylinder's axis, the verdict, 3-D views");
    cmd.app->add_option("file", cmd.file,
                        "One query (a JSON object as `intersect` reads, may span lines); '-' or none: standard input");
    cmd.app->add_option("-o,--output", cmd.output, "Write the SVG to this file (default: standard output)");
    cmd.app->add_option("--line", cmd.line,
                        "Take the query on line N (from 1) of a JSON Lines input; only lines 1 to N are read")
        ->check(CLI::PositiveNumber);
    add_max_line_bytes_option(*cmd.app, cmd.max_line_bytes);
    cmd.app->footer(
        "EXAMPLE\n"
        "  boxcyl explain --line 4 examples/queries.jsonl -o gap.svg\n"
        "  echo '{\"box\":{\"min\":[0,0,0],\"max\":[1,1,1]},\"cylinder\":{\"center\":[2,0.5,0.5],\"axis\":[0,0,1],"
        "\"radius\":1,\"height\":1}}' | boxcyl explain > picture.svg\n\n"
        "The verdict is the exact answer (as `boxcyl intersect` gives by default); the drawing is in double\n"
        "precision and says so when the two differ (inputs within rounding of touching).\n\n"
        "With a \"margin\": M key the verdict is whether the box is within distance M of the cylinder\n"
        "(exact, as `intersect` answers it), and the cylinder grown by M is drawn dashed.\n\n"
        "The nearest points boxcyl::distance gives (as `boxcyl distance` answers) are marked in every view,\n"
        "with the segment between them, and the distance's proved bounds are written under the picture.\n"
        "Where the solids overlap, the deepest points boxcyl::signed_distance gives (as `boxcyl distance\n"
        "--signed` answers) are marked instead, with the proved bounds of the penetration depth.\n\n"
        "With --line N only the first N lines of the input are read.\n\n"
        "EXIT STATUS\n"
        "  0  the picture was written\n"
        "  1  the query is bad (the message `intersect` would give, on standard error)\n"
        "  2  usage error: unknown option, an input that cannot be opened, an output file that\n"
        "     cannot be created\n"
        "  3  input/output error: reading the input or writing the picture failed (message on\n"
        "     standard error)\n"
        "  128+N  stopped by signal N (130 SIGINT, 143 SIGTERM) before the query was read\n");
}

namespace {

// What to say and return when reading the input failed or a stop signal came: 0 when neither.
int input_failure(const std::istream& input, const std::string& name, std::ostream& err) {
    if (input.bad()) {
        err << "boxcyl: cannot read " << name << ": " << describe_error(stream_error(input), "read error") << "\n";
        return exit_io;
    }
    if (const int sig = stop_signal(); sig != 0) {
        err << "boxcyl: stopped by a signal before the query was read; no picture written\n";
        return exit_signal_base + sig;
    }
    return 0;
}

// Writes `svg` to the file `name`, or says why not: exit_usage when it cannot be created, exit_io when
// writing it fails.
int write_file(const std::string& name, const std::string& svg, std::ostream& err) {
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        err << "boxcyl: cannot write '" << name << "': " << std::strerror(errno) << "\n";
        return exit_usage;
    }
    int error = 0;
    {
        OutputFd f(fd);
        f << svg;
        f.flush();
        if (!f) error = f.buffer().error() != 0 ? f.buffer().error() : EIO;
    }
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) {
        err << "boxcyl: cannot write '" << name << "': " << std::strerror(error) << "\n";
        return exit_io;
    }
    return exit_ok;
}

}  // namespace

int run_explain(const ExplainCommand& cmd, std::istream& in, std::ostream& out, std::ostream& err) {
#if !defined(BOXCYL_CLI_EXACT)
    (void)cmd, (void)in, (void)out;
    err << "boxcyl: explain needs the exact backend (GMP) for its verdict; this build has none\n";
    return exit_usage;
#else
    std::unique_ptr<std::istream> file;
    if (cmd.file != "-") {
        file = open_input(cmd.file, err);
        if (!file) return exit_usage;
    }
    std::istream& input = file ? *file : in;
    const std::string name = input_name(cmd.file);

    // The query text and the line number its messages name. With --line N only the lines up to N are
    // read: the input may go on for ever (a pipe) or be far larger than the line.
    std::string query_text;
    std::size_t line_number = 1;
    if (cmd.line > 0) {
        const std::size_t skipped = skip_lines(input, cmd.line);
        if (const int code = input_failure(input, name, err)) return code;
        LineRead r = LineRead::end;
        if (skipped + 1 == cmd.line) r = read_line(input, query_text, cmd.max_line_bytes);
        if (const int code = input_failure(input, name, err)) return code;
        if (r == LineRead::end) {
            err << "boxcyl: line " << cmd.line << ": no such line (the input has " << skipped << ")\n";
            return exit_bad_lines;
        }
        if (r != LineRead::line) {
            err << "boxcyl: " << unread_line_message(r, cmd.line, cmd.max_line_bytes) << "\n";
            return exit_bad_lines;
        }
        line_number = cmd.line;
    } else {
        const bool whole = read_all(input, cmd.max_line_bytes, query_text);
        if (const int code = input_failure(input, name, err)) return code;
        if (!whole) {
            err << "boxcyl: " << name << " is longer than " << cmd.max_line_bytes
                << " bytes (--max-line-bytes); for a JSON Lines file choose one query with --line N\n";
            return exit_bad_lines;
        }
    }

    const ParsedLine p = parse_line(query_text, line_number);
    if (!p.query) {
        err << "boxcyl: " << p.error << "\n";
        if (cmd.line == 0 && several_lines(query_text))
            err << "boxcyl: (the input spans several lines; for a JSON Lines file choose one query with --line N)\n";
        return exit_bad_lines;
    }
    const Query& q = *p.query;
    // The verdicts are the default query's (exact), as `intersect` gives them: intersects for the
    // picture of the cylinder itself, and with a margin (validated by parse_line) within_distance.
    Query plain = q;
    plain.margin.reset();
    const bool intersects = run_query(plain, QueryOptions{});
    Explanation e = std::visit([&](const auto& box) { return explain::compute(box, q.cylinder, intersects); }, q.box);
    if (q.margin) e = explain::with_margin(e, *q.margin, run_query(q, QueryOptions{}));
    // The nearest pair, as `boxcyl distance` answers it; not computed for a picture that cannot show it.
    if (e.drawable) e = explain::with_nearest(e, run_distance_query(q));
    // Where they overlap, how deep, as `boxcyl distance --signed` answers it.
    if (e.nearest && e.nearest->upper == 0) e = explain::with_depth(e, run_signed_distance_query(q));
    const std::string svg = render(e, p.id, input_lines(q));

    if (!cmd.output.empty()) return write_file(cmd.output, svg, err);
    out << svg;
    out.flush();
    if (!out) {
        err << "boxcyl: cannot write standard output: " << describe_error(stream_error(out), "write error") << "\n";
        return exit_io;
    }
    return exit_ok;
#endif
}

}  // namespace boxcyl::cli
