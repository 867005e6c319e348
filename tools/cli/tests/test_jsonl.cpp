// Unit tests of the JSON Lines layer of the boxcyl tool (tools/cli/jsonl_query.hpp): number
// conversion, structure checks and messages, id echo, output format, line accounting, hostile input
// (truncated lines, invalid UTF-8, huge lines, duplicate keys, numbers out of range).
#include <gtest/gtest.h>

#include <algorithm>     // std::equal
#include <bit>           // std::bit_cast for bit-exact comparison
#include <charconv>      // std::to_chars for 17-digit printing
#include <cmath>         // std::signbit, std::sqrt
#include <csignal>       // SIGTERM, SIGINT
#include <cstdint>       // bit patterns
#include <limits>        // the largest double, infinity
#include <random>        // fixed-seed random doubles
#include <sstream>       // process_stream on strings
#include <streambuf>     // inputs cut short by a stop signal, outputs that fail
#include <string>
#include <system_error>  // std::errc
#include <vector>

#include <nlohmann/json.hpp>  // outputs must be valid JSON (and so valid UTF-8)

#include "distance.hpp"
#include "io.hpp"
#include "jsonl_query.hpp"
#include "options.hpp"

namespace boxcyl::cli {
namespace {

const std::string kBox = R"("box": {"min": [0, 0, 0], "max": [1, 1, 1]})";
const std::string kCyl = R"("cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1})";

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// Parses `literal` as JSON number text through a whole query line (as cylinder.center[1], where any
// finite value is valid) and returns the double the tool would use.
double parse_number(const std::string& literal) {
    const std::string line = "{" + kBox + R"(, "cylinder": {"center": [0, )" + literal +
                             R"(, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}})";
    const ParsedLine p = parse_line(line, 1);
    EXPECT_TRUE(p.query.has_value()) << "literal " << literal << ": " << p.error;
    return p.query ? p.query->cylinder.center[1] : 0.0;
}

std::string error_of(const std::string& line) {
    const ParsedLine p = parse_line(line, 7);
    EXPECT_FALSE(p.query.has_value()) << line;
    return p.error;
}

// --- numbers: nearest double, bit-exact ---

TEST(JsonlNumbers, DecimalLiteralsBecomeTheNearestDouble) {
    // Expected bit patterns as hex floats, computed independently (Python float(), David Gay's
    // correctly rounded conversion).
    struct Case {
        const char* literal;
        double expected;
    };
    const Case cases[] = {
        {"0.1", 0x1.999999999999ap-4},
        {"1e-300", 0x1.56e1fc2f8f359p-997},
        {"4.9406564584124654e-324", 0x0.0000000000001p-1022},  // smallest subnormal
        {"1.7976931348623157e308", 0x1.fffffffffffffp+1023},   // largest finite
        {"1.7976931348623158e308", 0x1.fffffffffffffp+1023},   // just below the overflow midpoint
        {"2.2250738585072014e-308", 0x1p-1022},                // smallest normal
        {"2.2250738585072009e-308", 0x0.fffffffffffffp-1022},  // largest subnormal
        {"2.2250738585072011e-308", 0x0.fffffffffffffp-1022},
        {"2.4703282292062327e-324", 0.0},                      // just below half the smallest subnormal
        {"2.4703282292062328e-324", 0x0.0000000000001p-1022},  // just above it
        {"1e-400", 0.0},                                       // underflow rounds to zero: in range
        {"0.30000000000000004", 0x1.3333333333334p-2},
        {"1.0000000000000002", 0x1.0000000000001p+0},
        {"3.14159265358979323846264338327950288", 0x1.921fb54442d18p+1},
        {"1e23", 0x1.52d02c7e14af6p+76},
        {"8.589973e9", 0x1.00004b04p+33},
        {"1E+2", 100.0},
        {"0.1e1", 1.0},
        // Integers: exact when they fit, otherwise rounded to nearest-even like any literal.
        {"3", 3.0},
        {"-17", -17.0},
        {"9007199254740993", 0x1p+53},
        {"9007199254740995", 0x1.0000000000002p+53},
        {"9223372036854775807", 0x1p+63},
        {"-9223372036854775808", -0x1p+63},
        {"-9223372036854775809", -0x1p+63},
        {"18446744073709551615", 0x1p+64},
        {"18446744073709551616", 0x1p+64},
        {"123456789012345678901234567890", 0x1.8ee90ff6c373ep+96},
    };
    for (const Case& c : cases)
        EXPECT_EQ(bits(parse_number(c.literal)), bits(c.expected)) << "literal " << c.literal;
}

TEST(JsonlNumbers, NegativeZeroKeepsItsSign) {
    EXPECT_TRUE(std::signbit(parse_number("-0.0")));
    EXPECT_FALSE(std::signbit(parse_number("0.0")));
}

TEST(JsonlNumbers, SeventeenSignificantDigitsRoundTripBitExactly) {
    const std::uint64_t seed = 20240611;
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const double x = std::bit_cast<double>(rng());
        if (!std::isfinite(x)) continue;
        char buf[64];
        const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific, 16);
        ASSERT_EQ(r.ec, std::errc()) << "seed " << seed;
        const std::string text(buf, r.ptr);
        ASSERT_EQ(bits(parse_number(text)), bits(x)) << "seed " << seed << ", literal " << text;
        ++checked;
    }
    EXPECT_GT(checked, 19000);
}

TEST(JsonlNumbers, ShortestRepresentationsRoundTrip) {
    std::mt19937_64 rng(7);  // seed 7
    std::uniform_real_distribution<double> u(-1e6, 1e6);
    for (int i = 0; i < 5000; ++i) {
        const double x = i % 2 ? u(rng) : std::ldexp(u(rng), static_cast<int>(rng() % 2000) - 1000);
        char buf[64];
        const auto r = std::to_chars(buf, buf + sizeof buf, x);
        const std::string text(buf, r.ptr);
        ASSERT_EQ(bits(parse_number(text)), bits(x)) << "seed 7, literal " << text;
    }
}

TEST(JsonlNumbers, BeyondDoubleRangeIsReportedWithTheField) {
    EXPECT_EQ(error_of("{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1e400, "height": 1}})"),
              "line 7: cylinder.radius: out of double range");
    EXPECT_EQ(error_of("{" + kBox + R"(, "cylinder": {"center": [0, -1e400, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}})"),
              "line 7: cylinder.center[1]: out of double range");
    EXPECT_EQ(error_of(R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 1.7976931348623159e308], [0, 0, 1]], "extents": [1, 1, 1]}})"),
              "line 7: box.axes[1][2]: out of double range");
    EXPECT_EQ(error_of(R"({"id": 1e999})"), "line 7: id: out of double range");
    EXPECT_EQ(error_of("1e400"), "line 7: value: out of double range");
}

// --- structure and validation messages ---

TEST(JsonlStructure, MessagesNameTheField) {
    struct Case {
        std::string line;
        std::string error;
    };
    const std::string c = kCyl;
    const std::string ob = R"("center": [0, 0, 0], "extents": [1, 1, 1])";
    const std::string nul(1, '\0');
    const std::string nul_message = R"(a NUL byte (not allowed in JSON text; inside a string write \u0000))";
    const Case cases[] = {
        {"", "line 7: empty line"},
        {" \t \r", "line 7: empty line"},
        {"[1, 2, 3]", "line 7: expected a JSON object"},
        {"\"text\"", "line 7: expected a JSON object"},
        {"{" + c + "}", "line 7: box: missing"},
        {"{" + kBox + "}", "line 7: cylinder: missing"},
        {R"({"box": null, )" + c + "}", "line 7: box: expected an object"},
        {R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1], "axes": []}, )" + c + "}",
         "line 7: box: has both min/max and center/axes/extents"},
        {R"({"box": {}, )" + c + "}",
         "line 7: box: expected min/max (aligned box) or center/axes/extents (oriented box)"},
        {R"({"box": {"max": [1, 1, 1]}, )" + c + "}", "line 7: box.min: missing"},
        {R"({"box": {"min": [0, 0, 0, 0], "max": [1, 1, 1]}, )" + c + "}",
         "line 7: box.min: expected an array of 3 numbers"},
        {R"({"box": {"min": [0, 0, 0], "max": [1, true, 1]}, )" + c + "}",
         "line 7: box.max: expected an array of 3 numbers"},
        {R"({"box": {"min": [0, 0, 0], "max": {"x": 1}}, )" + c + "}",
         "line 7: box.max: expected an array of 3 numbers"},
        {R"({"box": {"axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, 1, 1]}, )" + c + "}",
         "line 7: box.center: missing"},
        {R"({"box": {"center": [0, 0, 0], "extents": [1, 1, 1]}, )" + c + "}", "line 7: box.axes: missing"},
        {R"({"box": {)" + ob + R"(, "axes": [1, 0, 0]}, )" + c + "}", "line 7: box.axes[0]: expected an array of 3 numbers"},
        {R"({"box": {)" + ob + R"(, "axes": [[1, 0, 0]]}, )" + c + "}", "line 7: box.axes: expected an array of 3 axes"},
        {R"({"box": {)" + ob + R"(, "axes": [[1, 0, 0], [0, 1, 0], [0, 0, "1"]]}, )" + c + "}",
         "line 7: box.axes[2]: expected an array of 3 numbers"},
        {R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}, )" + c + "}",
         "line 7: box.extents: missing"},
        {"{" + kBox + R"(, "cylinder": [])", "line 7: invalid JSON: column 61: syntax error while parsing object - unexpected end of input; expected '}'"},
        {"{" + kBox + R"(, "cylinder": []})", "line 7: cylinder: expected an object"},
        {"{" + kBox + R"(, "cylinder": {"axis": [0, 0, 1], "radius": 1, "height": 1}})", "line 7: cylinder.center: missing"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}})",
         "line 7: cylinder.center: expected an array of 3 numbers"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "radius": 1, "height": 1}})", "line 7: cylinder.axis: missing"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "height": 1}})", "line 7: cylinder.radius: missing"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": [1], "height": 1}})",
         "line 7: cylinder.radius: expected a number"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": null}})",
         "line 7: cylinder.height: expected a number"},
        // Field checks by boxcyl::validate().
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": -1, "height": 1}})",
         "line 7: cylinder.radius: is negative"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, -0.0, 0], "radius": 1, "height": 1}})",
         "line 7: cylinder.axis: is the zero vector"},
        {R"({"box": {"min": [0, 0, 2], "max": [1, 1, 1]}, )" + c + "}", "line 7: box.max[2]: is less than box.min[2]"},
        {R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, 1, -2]}, )" + c + "}",
         "line 7: box.extents[2]: is negative"},
        // |axes[2]|² = 1.00010000252…, beyond 1e-4 but "1.000100" to six decimals: printed with the digits that show it.
        {R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1.00005000001]], "extents": [1, 1, 1]}, )" + c + "}",
         "line 7: box.axes[2]: is not unit length (|axes[2]|² = 1.000100003, tolerance 1e-4); for axes of any length and angle use \"kind\": \"parallelepiped\""},
        // Syntax.
        {"{", "line 7: invalid JSON: column 2: syntax error while parsing object key - unexpected end of input; expected string literal"},
        {"{} {}", "line 7: invalid JSON: column 4: syntax error while parsing value - unexpected '{'; expected end of input"},
        // Bytes after the object: never the object alone.
        {"{" + kBox + ", " + c + "} junk",
         "line 7: invalid JSON: column 131: syntax error while parsing value - invalid literal; last read: '1}} j'; expected end of input"},
        {"{" + kBox + ", " + c + "}}", "line 7: invalid JSON: column 130: syntax error while parsing value - unexpected '}'; expected end of input"},
        // A NUL byte ends nlohmann's input: without a check `{...}\0 junk` would be the query `{...}`.
        {"{" + kBox + ", " + c + "}" + nul, "line 7: invalid JSON: column 130: " + nul_message},
        {"{" + kBox + ", " + c + "}" + nul + " junk", "line 7: invalid JSON: column 130: " + nul_message},
        {R"({"box")" + nul + ": 1}", "line 7: invalid JSON: column 7: " + nul_message},
        {R"({"box)" + nul + R"(": 1})", "line 7: invalid JSON: column 6: " + nul_message},
        // An error before the NUL byte comes first.
        {"{]" + nul, "line 7: invalid JSON: column 2: syntax error while parsing object key - unexpected ']'; expected string literal"},
        // Keys the format does not have: named, with the nearest accepted key and the accepted ones.
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 1, "heigth": 5}})",
         R"(line 7: cylinder.heigth: unknown key; did you mean "height"? (accepted: center, axis, radius, height))"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "half_height": 1}})",
         R"(line 7: cylinder.half_height: unknown key; did you mean "height" (the full height, end to end, not half of it)? (accepted: center, axis, radius, height))"},
        {"{" + kBox + R"(, "cylinder": {"centre": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}})",
         R"(line 7: cylinder.centre: unknown key; did you mean "center"? (accepted: center, axis, radius, height))"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axes": [0, 0, 1], "radius": 1, "height": 1}})",
         R"(line 7: cylinder.axes: unknown key; did you mean "axis"? (accepted: center, axis, radius, height))"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "Radius": 1, "height": 1}})",
         R"(line 7: cylinder.Radius: unknown key; did you mean "radius"? (accepted: center, axis, radius, height))"},
        {R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "half_extents": [1, 1, 1]}, )" + c + "}",
         R"(line 7: box.half_extents: unknown key; did you mean "extents" (half the edge lengths, as you wrote)? (accepted: kind, min, max, center, axes, extents))"},
        {R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1], "size": [1, 1, 1]}, )" + c + "}",
         "line 7: box.size: unknown key (accepted: kind, min, max, center, axes, extents)"},
        {"{" + kBox + ", " + c + R"(, "extra": {"deep": [1e300, "x"]}})", "line 7: extra: unknown key (accepted: id, box, cylinder, margin)"},
        {"{" + kBox + ", " + c + R"(, "ID": 3})", R"(line 7: ID: unknown key; did you mean "id"? (accepted: id, box, cylinder, margin))"},
        {"{" + kBox + ", " + c + ", \"" + std::string(100, 'k') + "\": 3}",
         "line 7: " + std::string(64, 'k') + "...: unknown key (accepted: id, box, cylinder, margin)"},
        {R"({"box": 1, "box": 2})", "line 7: box: duplicate key"},
        {"{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "center": [0, 0, 0]}})", "line 7: cylinder.center: duplicate key"},
        {R"({"id": null})", "line 7: id: expected a string or a number"},
        {R"({"id": {"a": 1}})", "line 7: id: expected a string or a number"},
    };
    for (const Case& k : cases) EXPECT_EQ(error_of(k.line), k.error) << k.line;
}

TEST(JsonlStructure, GoodLinesYieldTheShapes) {
    const ParsedLine a = parse_line("{" + kBox + ", " + kCyl + "}", 1);
    ASSERT_TRUE(a.query) << a.error;
    EXPECT_TRUE(a.id.empty());
    const auto& ab = std::get<AlignedBox<double>>(a.query->box);
    EXPECT_EQ(ab.min, (Vec3<double>{0, 0, 0}));
    EXPECT_EQ(ab.max, (Vec3<double>{1, 1, 1}));
    EXPECT_EQ(a.query->cylinder.center, (Vec3<double>{2, 0.5, 0.5}));
    EXPECT_EQ(a.query->cylinder.axis, (Vec3<double>{0, 0, 1}));
    EXPECT_EQ(a.query->cylinder.radius, 1.0);
    EXPECT_EQ(a.query->cylinder.height, 1.0);

    const ParsedLine o = parse_line(
        R"( {"cylinder": {"height": 4, "radius": 3, "axis": [1, 2, 3], "center": [-1, -2, -3]}, "box": {"extents": [0.5, 0, 2], "axes": [[0, 1, 0], [-1, 0, 0], [0, 0, 1]], "center": [7, 8, 9]}}  )",
        2);
    ASSERT_TRUE(o.query) << o.error;
    const auto& ob = std::get<OrientedBox<double>>(o.query->box);
    EXPECT_EQ(ob.center, (Vec3<double>{7, 8, 9}));
    EXPECT_EQ(ob.axes[0], (Vec3<double>{0, 1, 0}));
    EXPECT_EQ(ob.axes[1], (Vec3<double>{-1, 0, 0}));
    EXPECT_EQ(ob.axes[2], (Vec3<double>{0, 0, 1}));
    EXPECT_EQ(ob.extents, (Vec3<double>{0.5, 0, 2}));
    EXPECT_EQ(o.query->cylinder.axis, (Vec3<double>{1, 2, 3}));
    EXPECT_EQ(o.query->cylinder.radius, 3.0);
    EXPECT_EQ(o.query->cylinder.height, 4.0);

    // A trailing CR (CRLF files) is JSON whitespace.
    EXPECT_TRUE(parse_line("{" + kBox + ", " + kCyl + "}\r", 3).query);
}

// --- id echo ---

TEST(JsonlId, EchoedAsWritten) {
    struct Case {
        std::string id_json;
        std::string echoed;
    };
    const Case cases[] = {
        {"7", "7"},
        {"-12", "-12"},
        {"18446744073709551615", "18446744073709551615"},
        {"123456789012345678901234567890", "123456789012345678901234567890"},
        {"1e2", "1e2"},
        {"0.10000000000000000001", "0.10000000000000000001"},
        {R"("query-1")", R"("query-1")"},
        {R"("tab\tquote\"slash\/é\u00e9")", R"("tab\tquote\"slash/éé")"},
        {R"("")", R"("")"},
    };
    for (const Case& k : cases) {
        std::string line = R"({"id": )";
        line += k.id_json;
        line += ", " + kBox;
        line += ", " + kCyl + "}";
        const ParsedLine p = parse_line(line, 1);
        ASSERT_TRUE(p.query) << p.error;
        EXPECT_EQ(p.id, k.echoed) << k.id_json;
    }
    // Only the top-level id counts.
    EXPECT_TRUE(parse_line(R"({"x": {"id": 5}, )" + kBox + ", " + kCyl + "}", 1).id.empty());
}

TEST(JsonlId, EchoedOnBadLinesWhenReadable) {
    const RunOptions opt = make_run_options("oracle", "double");
    EXPECT_EQ(answer_line(R"({"id": "a", "box": {)", 4, opt).text,
              R"({"id": "a", "error": "line 4: invalid JSON: column 21: syntax error while parsing object key - unexpected end of input; expected string literal"})");
    EXPECT_EQ(answer_line(R"({"id": 5, )" + kBox + "}", 5, opt).text,
              R"({"id": 5, "error": "line 5: cylinder: missing"})");
    EXPECT_EQ(answer_line(R"({"id": true, )" + kBox + "}", 6, opt).text,
              R"({"error": "line 6: id: expected a string or a number"})");
}

// --- output format and the whole line ---

TEST(JsonlFormat, ExactText) {
    EXPECT_EQ(format_answer("", true), R"({"intersect": true})");
    EXPECT_EQ(format_answer("", false), R"({"intersect": false})");
    EXPECT_EQ(format_answer("\"x\"", true), R"({"id": "x", "intersect": true})");
    EXPECT_EQ(format_answer("12", false), R"({"id": 12, "intersect": false})");
    EXPECT_EQ(format_error("", "line 1: empty line"), R"({"error": "line 1: empty line"})");
    EXPECT_EQ(format_error("3", "a \"q\" \\ \n"), R"({"id": 3, "error": "a \"q\" \\ \n"})");
    // Invalid UTF-8 (only possible from echoed input in a message) is replaced, never a throw.
    EXPECT_EQ(format_error("", "bad \xff"), "{\"error\": \"bad \xEF\xBF\xBD\"}");
}

TEST(JsonlAnswer, AnswersWithTheChosenAlgorithm) {
    for (const char* alg : {"inequalities", "oracle"})
        for (const char* ari : {"float", "double"}) {
            const RunOptions opt = make_run_options(alg, ari);
            std::string line = R"({"id": 1, )" + kBox;
            line += ", " + kCyl + "}";
            EXPECT_EQ(answer_line(line, 1, opt).text,
                      R"({"id": 1, "intersect": true})")
                << alg << " " << ari;
            EXPECT_EQ(answer_line(R"({"id": 2, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [3, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}})",
                                  2, opt)
                          .text,
                      R"({"id": 2, "intersect": false})")
                << alg << " " << ari;
        }
}

// "margin": within that distance, exactly whatever the options; a bad margin names the field.
TEST(JsonlAnswer, MarginIsTheExactClearanceQuery) {
    // The box's corner (6, 0, 5) is exactly 5 from the rim point (3, 0, 1).
    const std::string shapes = R"("box": {"min": [6, 0, 5], "max": [7, 1, 6]}, )"
                               R"("cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 3, "height": 2})";
    for (const char* ari : {"exact", "float", "double"}) {
        const RunOptions opt = make_run_options("inequalities", ari);
        EXPECT_EQ(answer_line("{\"id\": 1, " + shapes + ", \"margin\": 5}", 1, opt).text, R"({"id": 1, "intersect": true})")
            << ari;
        EXPECT_EQ(answer_line("{\"id\": 2, " + shapes + ", \"margin\": 4.999999999999999}", 2, opt).text,
                  R"({"id": 2, "intersect": false})")
            << ari;
        EXPECT_EQ(answer_line("{\"id\": 3, " + shapes + ", \"margin\": 0}", 3, opt).text, R"({"id": 3, "intersect": false})")
            << ari;
    }
    const RunOptions opt = make_run_options("inequalities", "exact");
    EXPECT_EQ(answer_line("{" + shapes + ", \"margin\": -1}", 4, opt).text, R"({"error": "line 4: margin: is negative"})");
    EXPECT_EQ(answer_line("{" + shapes + ", \"margin\": \"1\"}", 5, opt).text,
              R"({"error": "line 5: margin: expected a number"})");
    EXPECT_EQ(answer_line("{" + shapes + ", \"margin\": 1e999}", 6, opt).text,
              R"({"error": "line 6: margin: out of double range"})");
}

TEST(JsonlOptions, TableMapping) {
    const RunOptions d = make_run_options(default_algorithm, default_arithmetic);
    EXPECT_EQ(d.query.algorithm, Algorithm::inequalities);
    EXPECT_EQ(d.query.arithmetic, Arithmetic::filtered);  // exact by default
    EXPECT_FALSE(d.rounds_to_float);
    const RunOptions f = make_run_options("inequalities", "float");
    EXPECT_EQ(f.query.arithmetic, Arithmetic::float32);
    EXPECT_TRUE(f.rounds_to_float);
    const RunOptions o = make_run_options("oracle", "float");
    EXPECT_EQ(o.query.algorithm, Algorithm::oracle);
    EXPECT_FALSE(o.rounds_to_float);  // exact: nothing is rounded
    const RunOptions h = make_run_options("hull", "exact");
    EXPECT_EQ(h.query.algorithm, Algorithm::hull);
    EXPECT_EQ(h.query.arithmetic, Arithmetic::exact);
    EXPECT_FALSE(h.rounds_to_float);
    EXPECT_EQ(make_run_options("lcp", "double").query.algorithm, Algorithm::lcp);
    EXPECT_EQ(find_algorithm("nope"), nullptr);
    EXPECT_EQ(find_arithmetic("nope"), nullptr);
}

TEST(JsonlOptions, FloatArithmeticRefusesInputsThatDoNotSurviveRounding) {
    const RunOptions f = make_run_options("inequalities", "float");
    const RunOptions d = make_run_options("inequalities", "double");
    const std::string big = "{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1e39, "height": 1}})";
    EXPECT_EQ(answer_line(big, 3, f).text,
              R"x({"error": "line 3: cylinder.radius: is +Inf after rounding to float (--arithmetic float)"})x");
    EXPECT_EQ(answer_line(big, 3, d).text, R"({"intersect": true})");
    const std::string tiny = "{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [1e-50, 0, 0], "radius": 1, "height": 1}})";
    EXPECT_EQ(answer_line(tiny, 4, f).text,
              R"x({"error": "line 4: cylinder.axis: is the zero vector after rounding to float (--arithmetic float)"})x");
    const std::string low = R"({"box": {"min": [-1e39, 0, 0], "max": [1, 1, 1]}, )" + kCyl + "}";
    EXPECT_EQ(answer_line(low, 5, f).text,
              R"x({"error": "line 5: box.min[0]: is -Inf after rounding to float (--arithmetic float)"})x");
    // Just below the float overflow threshold rounds to FLT_MAX: fine.
    const std::string edge = "{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 3.4028235e38, "height": 1}})";
    EXPECT_EQ(answer_line(edge, 6, f).text, R"({"intersect": true})");
}

// --- streams: one output line per input line ---

std::vector<std::string> lines_of(const std::string& s) {
    std::vector<std::string> v;
    std::istringstream in(s);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
}

TEST(JsonlStream, OneOutputLinePerInputLineInOrder) {
    const std::string good = "{" + kBox + ", " + kCyl + "}";
    const std::string input = good + "\n\n" + "garbage\n" + "\r\n" + good + "\r\n" + good;  // no final newline
    std::istringstream in(input);
    std::ostringstream out;
    const std::size_t bad = process_stream(in, out, make_run_options("inequalities", "double"));
    EXPECT_EQ(bad, 3u);
    const std::vector<std::string> got = lines_of(out.str());
    ASSERT_EQ(got.size(), 6u) << out.str();
    EXPECT_EQ(got[0], R"({"intersect": true})");
    EXPECT_EQ(got[1], R"({"error": "line 2: empty line"})");
    EXPECT_EQ(got[2].rfind(R"({"error": "line 3: invalid JSON: )", 0), 0u) << got[2];
    EXPECT_EQ(got[3], R"({"error": "line 4: empty line"})");
    EXPECT_EQ(got[4], R"({"intersect": true})");
    EXPECT_EQ(got[5], R"({"intersect": true})");
    EXPECT_EQ(out.str().back(), '\n');
}

TEST(JsonlStream, EmptyInputGivesNoOutput) {
    std::istringstream in("");
    std::ostringstream out;
    EXPECT_EQ(process_stream(in, out, make_run_options("oracle", "double")), 0u);
    EXPECT_EQ(out.str(), "");
}

TEST(JsonlStream, OnlyNewlinesAreEmptyLines) {
    std::istringstream in("\n\n\n");
    std::ostringstream out;
    EXPECT_EQ(process_stream(in, out, make_run_options("oracle", "double")), 3u);
    EXPECT_EQ(out.str(),
              "{\"error\": \"line 1: empty line\"}\n{\"error\": \"line 2: empty line\"}\n"
              "{\"error\": \"line 3: empty line\"}\n");
}

// Inputs around the block size of the multi-threaded path: good lines with varied answers, bad ones
// of every kind (empty, invalid JSON, invalid UTF-8, an invalid value) and one line longer than a
// block's byte budget. `n` lines; with `final_newline` false the last one has none.
std::string mixed_input(std::size_t n, bool final_newline) {
    std::string s;
    for (std::size_t i = 1; i <= n; ++i) {
        const std::string id = R"({"id": )" + std::to_string(i) + ", ";
        switch (i == n ? 1 : i % 13) {  // the last line is a query: empty and unterminated is no line
            case 0: break;                 // empty line
            case 5: s += id + kBox; break;  // truncated
            case 7: s += id; s += "\"note\": \"\xff\", "; s += kBox; s += ", "; s += kCyl; s += "}"; break;
            case 11: s += id + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 0], "radius": 1, "height": 1}})"; break;
            default: {
                // The cylinder's x slides across the box face x = 1 in steps of 1/8: hits, touches, misses.
                const double x = 1.0 + static_cast<double>(i % 9) / 8.0;
                s += id + kBox + R"(, "cylinder": {"center": [)" + std::to_string(x) +
                     R"(, 0.5, 0.5], "axis": [0, 0, 1], "radius": 0.5, "height": 1}})";
            }
        }
        if (i == 4100) s += std::string(stream_block_bytes + 10, ' ');  // trailing whitespace is fine JSON
        if (i < n || final_newline) s += '\n';
    }
    return s;
}

TEST(JsonlStream, ThreadedOutputIsByteIdenticalToSerial) {
    const RunOptions opt = make_run_options("inequalities", "filtered");
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, stream_block_lines - 1, stream_block_lines,
                                stream_block_lines + 1, 3 * stream_block_lines + 17}) {
        for (const bool final_newline : {true, false}) {
            const std::string input = mixed_input(n, final_newline);
            std::istringstream in1(input);
            std::ostringstream out1;
            const std::size_t bad1 = process_stream(in1, out1, opt, 1);
            ASSERT_EQ(lines_of(out1.str()).size(), n);
            if (n > 13) {
                EXPECT_GT(bad1, 0u);
                EXPECT_LT(bad1, n);
            }
            for (const unsigned threads : {2u, 8u}) {  // 0 (one per core): the CLI test
                std::istringstream in(input);
                std::ostringstream out;
                const std::size_t bad = process_stream(in, out, opt, threads);
                EXPECT_EQ(bad, bad1) << n << " lines, " << threads << " threads";
                EXPECT_TRUE(out.str() == out1.str())
                    << n << " lines (final newline " << final_newline << "), " << threads
                    << " threads: output differs from the single-threaded one";
            }
        }
    }
}


// --- hostile input: every bad line gets its error line, the run goes on ---

const std::string kGood = R"({"id": 1, )" + kBox + ", " + kCyl + "}";

// The output line must be one JSON object (nlohmann's parser also rejects invalid UTF-8) holding an
// "error" that starts with `prefix`; returns the error.
std::string error_text(const LineAnswer& a, const std::string& prefix) {
    EXPECT_FALSE(a.good) << a.text;
    const nlohmann::json j = nlohmann::json::parse(a.text, nullptr, false);
    EXPECT_TRUE(j.is_object()) << "not valid JSON: " << a.text;
    if (!j.is_object() || !j.contains("error") || !j["error"].is_string()) {
        ADD_FAILURE() << "no error in " << a.text;
        return {};
    }
    std::string e = j["error"].get<std::string>();
    EXPECT_EQ(e.rfind(prefix, 0), 0u) << "error '" << e << "' does not start with '" << prefix << "'";
    return e;
}

struct StreamResult {
    std::vector<std::string> lines;
    std::size_t bad;
};
StreamResult run_stream(const std::string& input, const RunOptions& opt = make_run_options("inequalities", "filtered")) {
    std::istringstream in(input);
    std::ostringstream out;
    const std::size_t bad = process_stream(in, out, opt);
    return {lines_of(out.str()), bad};
}

TEST(JsonlHostile, TruncatedLastLineAtEveryByteGetsItsErrorLine) {
    // A good line, then the same line cut after k bytes with no newline (a writer killed mid-line):
    // every cut is invalid JSON and must get exactly one error line naming line 2.
    for (std::size_t k = 1; k < kGood.size(); ++k) {
        const StreamResult r = run_stream(kGood + "\n" + kGood.substr(0, k));
        ASSERT_EQ(r.lines.size(), 2u) << "cut after " << k << " bytes";
        EXPECT_EQ(r.lines[0], R"({"id": 1, "intersect": true})");
        EXPECT_EQ(r.bad, 1u) << "cut after " << k << " bytes";
        error_text({r.lines[1], false}, "line 2: invalid JSON: ");
    }
    // The id is echoed once it is complete; a cut inside a number is named as such.
    EXPECT_EQ(answer_line(kGood.substr(0, kGood.find("\"radius\": 1") + 11) + ".", 2, make_run_options("inequalities", "filtered")).text,
              R"({"id": 1, "error": "line 2: invalid JSON: column 125: syntax error while parsing value - invalid number; expected digit after '.'; last read: '1.'"})");
}

TEST(JsonlHostile, InvalidUtf8IsABadLineAndTheOutputStaysValidUtf8) {
    const RunOptions opt = make_run_options("inequalities", "filtered");
    const std::string tail = ", " + kBox + ", " + kCyl + "}";
    const std::string cases[] = {
        R"({"id": ")" "\xff" R"(")" + tail,                 // a byte that is never UTF-8
        R"({"note": "caf)" "\xc3" R"(")" + tail,             // a truncated 2-byte sequence
        R"({"note": ")" "\xc0\xaf" R"(")" + tail,            // an overlong encoding of '/'
        R"({"note": ")" "\xed\xa0\x80" R"(")" + tail,        // a UTF-16 surrogate encoded in UTF-8
        R"({"note": ")" "\xf4\x90\x80\x80" R"(")" + tail,    // beyond U+10FFFF
        R"({"n)" "\xfe" R"(ote": 1)" + tail,                 // in a key
    };
    for (const std::string& line : cases) {
        const std::string e = error_text(answer_line(line, 3, opt), "line 3: invalid JSON: ");
        EXPECT_NE(e.find("ill-formed UTF-8 byte"), std::string::npos) << e;
    }
    // Outside strings an invalid byte is a syntax error like any other.
    error_text(answer_line("\xff" + tail, 4, opt), "line 4: invalid JSON: column 1: syntax error");
    // Valid non-ASCII text in a string is fine, and an id with it is echoed unchanged; a key with it
    // that the format does not have is named as written.
    EXPECT_EQ(answer_line(R"({"id": "Zürich ✓ 𝄞")" + tail, 5, opt).text, R"({"id": "Zürich ✓ 𝄞", "intersect": true})");
    EXPECT_EQ(answer_line(R"({"id": 5, "日本": 1)" + tail, 5, opt).text,
              R"x({"id": 5, "error": "line 5: 日本: unknown key (accepted: id, box, cylinder, margin)"})x");
    // A stream with invalid UTF-8 lines keeps its line count and order.
    const StreamResult r = run_stream(kGood + "\n" + cases[0] + "\n" + "\xc3\x28\n" + kGood + "\n");
    ASSERT_EQ(r.lines.size(), 4u);
    EXPECT_EQ(r.bad, 2u);
    error_text({r.lines[1], false}, "line 2: ");
    error_text({r.lines[2], false}, "line 3: ");
    EXPECT_EQ(r.lines[3], R"({"id": 1, "intersect": true})");
}

TEST(JsonlHostile, EmptyAndBlankLines) {
    const RunOptions opt = make_run_options("inequalities", "filtered");
    for (const char* blank : {"", " ", "\t", "\r", " \t \r", "\r\r"})
        EXPECT_EQ(answer_line(blank, 9, opt).text, R"({"error": "line 9: empty line"})") << '"' << blank << '"';
    // NUL bytes are not whitespace: a line of them is invalid JSON, not an empty line.
    error_text(answer_line(std::string(3, '\0'), 9, opt), "line 9: invalid JSON: ");
    const StreamResult r = run_stream("\n" + kGood + "\n\r\n  \n" + kGood);
    ASSERT_EQ(r.lines.size(), 5u);
    EXPECT_EQ(r.bad, 3u);
    EXPECT_EQ(r.lines[0], R"({"error": "line 1: empty line"})");
    EXPECT_EQ(r.lines[2], R"({"error": "line 3: empty line"})");
    EXPECT_EQ(r.lines[3], R"({"error": "line 4: empty line"})");
    EXPECT_EQ(r.lines[4], R"({"id": 1, "intersect": true})");
}

TEST(JsonlHostile, HugeLinesOf10MB) {
    const RunOptions opt = make_run_options("inequalities", "filtered");
    const std::size_t mb10 = 10u << 20;
    // Good queries padded to 10 MB (a long id, long whitespace) are answered.
    EXPECT_EQ(answer_line(R"({"id": ")" + std::string(mb10, 'x') + "\", " + kBox + ", " + kCyl + "}", 1, opt).text,
              R"({"id": ")" + std::string(mb10, 'x') + R"(", "intersect": true})");
    EXPECT_EQ(answer_line(kGood + std::string(mb10, ' '), 2, opt).text, R"({"id": 1, "intersect": true})");
    // A 10 MB decimal literal is still the nearest double: 0.000…0001 underflows to radius 0 (valid).
    EXPECT_EQ(answer_line("{" + kBox + R"(, "cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 0.)" +
                              std::string(mb10, '0') + R"(1, "height": 1}})",
                          3, opt)
                  .text,
              R"({"intersect": false})");
    // A 10 MB integer is beyond the double range.
    EXPECT_EQ(answer_line("{" + kBox + R"(, "cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1)" +
                              std::string(mb10, '0') + R"(, "height": 1}})",
                          4, opt)
                  .text,
              R"({"error": "line 4: cylinder.radius: out of double range"})");
    // 10 MB of nesting is refused early (no deep DOM, no deep recursion); 256 levels are fine.
    EXPECT_EQ(answer_line(std::string(mb10, '['), 5, opt).text,
              R"({"error": "line 5: invalid JSON: nested deeper than 256 levels"})");
    EXPECT_EQ(answer_line(R"({"id": 6, "deep": )" + std::string(255, '[') + std::string(255, ']') + ", " + kBox + ", " + kCyl + "}", 6, opt).text,
              R"x({"id": 6, "error": "line 6: deep: unknown key (accepted: id, box, cylinder, margin)"})x");  // parsed: only the key is wrong
    EXPECT_EQ(answer_line(R"({"id": 7, "deep": )" + std::string(256, '[') + std::string(256, ']') + ", " + kBox + ", " + kCyl + "}", 7, opt).text,
              R"({"id": 7, "error": "line 7: invalid JSON: nested deeper than 256 levels"})");
    // 10 MB of garbage between good lines changes nothing around it.
    const StreamResult r = run_stream(kGood + "\n" + std::string(mb10, '#') + "\n" + kGood + "\n");
    ASSERT_EQ(r.lines.size(), 3u);
    EXPECT_EQ(r.bad, 1u);
    EXPECT_EQ(r.lines[0], R"({"id": 1, "intersect": true})");
    error_text({r.lines[1], false}, "line 2: invalid JSON: column 1: syntax error");
    EXPECT_LT(r.lines[1].size(), 300u);  // the message quotes only a short piece of the line
    EXPECT_EQ(r.lines[2], R"({"id": 1, "intersect": true})");
}

// read_line gives std::getline's lines, whatever their length against its 64 KiB chunks, and keeps
// none longer than its limit.
TEST(JsonlLines, ReadLineMatchesGetlineAcrossChunkSizes) {
    const std::size_t chunk = std::size_t{64} * 1024;
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, chunk - 2, chunk - 1, chunk, chunk + 1, 3 * chunk - 1, 3 * chunk}) {
        for (const bool final_newline : {false, true}) {
            std::string input = "a\n" + std::string(n, 'x') + "\nb";
            if (final_newline) input += '\n';
            std::istringstream in(input);
            std::string line;
            std::vector<std::string> got;
            for (LineRead r; (r = read_line(in, line, 4 * chunk)) != LineRead::end;) {
                EXPECT_EQ(r, LineRead::line) << "n = " << n;
                got.push_back(line);
            }
            EXPECT_EQ(got, (std::vector<std::string>{"a", std::string(n, 'x'), "b"})) << "n = " << n;
            // The same with a limit just below the long line: it is skipped, the others kept.
            if (n < 2) continue;
            std::istringstream in2(input);
            EXPECT_EQ(read_line(in2, line, n - 1), LineRead::line);
            EXPECT_EQ(line, "a");
            EXPECT_EQ(read_line(in2, line, n - 1), LineRead::too_long) << "n = " << n;
            EXPECT_TRUE(line.empty());
            EXPECT_EQ(read_line(in2, line, n - 1), LineRead::line);
            EXPECT_EQ(line, "b");
            EXPECT_EQ(read_line(in2, line, n - 1), LineRead::end);
        }
    }
}

TEST(JsonlLines, LinesBeyondTheLimitGetAnErrorLineInPlace) {
    RunOptions opt = make_run_options("inequalities", "filtered");
    opt.max_line_bytes = kGood.size();
    const std::string input = kGood + "\n" + kGood + " \n" + kGood + "\n" + std::string(3 * 64 * 1024 + 5, 'y');
    for (const unsigned threads : {1u, 2u}) {
        std::istringstream in(input);
        std::ostringstream out;
        EXPECT_EQ(process_stream(in, out, opt, threads), 2u) << threads << " threads";
        const auto too_long = [](int line) {
            return "{\"error\": \"line " + std::to_string(line) + ": line is longer than " + std::to_string(kGood.size()) +
                   " bytes (--max-line-bytes)\"}";
        };
        EXPECT_EQ(lines_of(out.str()), (std::vector<std::string>{R"({"id": 1, "intersect": true})", too_long(2),
                                                                 R"({"id": 1, "intersect": true})", too_long(4)}))
            << threads << " threads";
    }
}

TEST(JsonlLines, ManySmallValuesAreRefusedBeforeTheyExhaustMemory) {
    // 1 MB of "[]," would make a DOM of ~32 MB; the parse stops at 4 bytes per byte of the line.
    const RunOptions opt = make_run_options("inequalities", "filtered");
    std::string many = R"({"id": 5, "pad": [)";
    while (many.size() < (1u << 20)) many += "[],";
    many += "[]], " + kBox + ", " + kCyl + "}";
    const std::string budget = std::to_string(std::size_t{64} * 1024 + 4 * many.size());
    EXPECT_EQ(answer_line(many, 5, opt).text,
              "{\"id\": 5, \"error\": \"line 5: too large to parse: its JSON values would take more than " + budget +
                  " bytes of memory\"}");
    // A thousand of them fit in the 64 KiB every line may use: the line is parsed, and only its key
    // (which the format does not have) is refused.
    std::string some = R"({"id": 6, "pad": [)";
    for (int i = 0; i < 1000; ++i) some += "[],";
    some += "[]], " + kBox + ", " + kCyl + "}";
    EXPECT_EQ(answer_line(some, 6, opt).text, R"x({"id": 6, "error": "line 6: pad: unknown key (accepted: id, box, cylinder, margin)"})x");
}

TEST(JsonlHostile, DuplicateKeysAnywhereMakeTheLineBad) {
    const std::string tail = ", " + kBox + ", " + kCyl + "}";
    EXPECT_EQ(error_of(R"({"id": 1, "id": 2)" + tail), "line 7: id: duplicate key");
    EXPECT_EQ(error_of(R"({"extra": {"a": 1, "a": 1})" + tail), "line 7: extra.a: duplicate key");  // found while parsing
    EXPECT_EQ(error_of(R"({"extra": [0, {"a": 1, "a": 1}])" + tail), "line 7: extra[1].a: duplicate key");
    // Keys are compared after unescaping: "r\u0061dius" is "radius".
    EXPECT_EQ(error_of("{" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "r\u0061dius": 2, "height": 1}})"),
              "line 7: cylinder.radius: duplicate key");
    EXPECT_EQ(error_of(R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, 1, 1]}})" +
                       (", " + kCyl + "}")),
              "line 7: box.axes: duplicate key");
    // The same key in different objects is no duplicate.
    EXPECT_TRUE(parse_line(R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, 1, 1]}, )" + kCyl + "}", 1).query);
}

TEST(JsonlHostile, NumbersOutOfRangeNameTheirField) {
    const std::string tail = ", " + kBox + ", " + kCyl + "}";
    // Built by appending: `"1" + std::string` trips GCC 12's false -Wrestrict (bug 105329).
    const std::string digits400 = std::string("1") + std::string(400, '0');
    EXPECT_EQ(error_of("{" + kBox + R"(, "cylinder": {"center": [0, 0, )" + digits400 + R"(], "axis": [0, 0, 1], "radius": 1, "height": 1}})"),
              "line 7: cylinder.center[2]: out of double range");
    EXPECT_EQ(error_of(R"({"box": {"min": [-)" + digits400 + R"(, 0, 0], "max": [1, 1, 1]}, )" + kCyl + "}"),
              "line 7: box.min[0]: out of double range");
    EXPECT_EQ(error_of(R"({"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, 1.8e308, 1]}, )" + kCyl + "}"),
              "line 7: box.extents[1]: out of double range");
    // Even in a key the format does not have, the number is reported first (found while parsing).
    EXPECT_EQ(error_of(R"({"extra": {"x": [1, -1e309]})" + tail), "line 7: extra.x[1]: out of double range");
    // Underflow is in range: the nearest double, possibly a signed zero.
    EXPECT_EQ(bits(parse_number("-1e-400")), bits(-0.0));
    EXPECT_EQ(bits(parse_number(std::string("-0.") + std::string(400, '0') + "1")), bits(-0.0));
    EXPECT_EQ(bits(parse_number(std::string("-") + std::string(308, '9'))), bits(-1e308));
}

// --- "kind": "parallelepiped": any axes, exactly as given ---

TEST(JsonlParallelepiped, MessagesNameTheField) {
    const std::string c = kCyl;
    const std::string frame = R"("center": [0, 0, 0], "axes": [[3, 4, 0], [-4, 3, 0], [0, 0, 5]], "extents": [1, 1, 1])";
    EXPECT_EQ(error_of(R"({"box": {"kind": "cube", )" + frame + "}, " + c + "}"),
              R"(line 7: box.kind: expected "aligned", "oriented" or "parallelepiped")");
    EXPECT_EQ(error_of(R"({"box": {"kind": 3, )" + frame + "}, " + c + "}"),
              R"(line 7: box.kind: expected "aligned", "oriented" or "parallelepiped")");
    EXPECT_EQ(error_of(R"({"box": {"kind": "parallelepiped", "min": [0, 0, 0], "max": [1, 1, 1]}, )" + c + "}"),
              "line 7: box: a parallelepiped has center/axes/extents, not min/max");
    EXPECT_EQ(error_of(R"({"box": {"kind": "parallelepiped", "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, 1, 1]}, )" + c + "}"),
              "line 7: box.center: missing");
    EXPECT_EQ(error_of(R"({"box": {"kind": "parallelepiped", "center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1], [0, 0, 1]], "extents": [1, 1, 1]}, )" + c + "}"),
              "line 7: box.axes[1]: expected an array of 3 numbers");
    EXPECT_EQ(error_of(R"({"box": {"kind": "parallelepiped", "center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0]], "extents": [1, 1, 1]}, )" + c + "}"),
              "line 7: box.axes: expected an array of 3 axes");
    EXPECT_EQ(error_of(R"({"box": {"kind": "parallelepiped", "center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}, )" + c + "}"),
              "line 7: box.extents: missing");
    EXPECT_EQ(error_of(R"({"box": {"kind": "parallelepiped", "center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, -1, 1]}, )" + c + "}"),
              "line 7: box.extents[1]: is negative");
    EXPECT_EQ(error_of(R"({"box": {"kind": "parallelepiped", "center": [0, 1e999, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1, 1, 1]}, )" + c + "}"),
              "line 7: box.center[1]: out of double range");
    EXPECT_EQ(error_of(R"({"box": {"kind": "aligned", )" + frame + "}, " + c + "}"),
              "line 7: box: an aligned box has min/max, not center/axes/extents");
    EXPECT_EQ(error_of(R"({"box": {"kind": "oriented", "min": [0, 0, 0], "max": [1, 1, 1]}, )" + c + "}"),
              "line 7: box: an oriented box has center/axes/extents, not min/max");
    // The same axes as an oriented box are refused, with a pointer to the parallelepiped.
    EXPECT_EQ(error_of(R"({"box": {)" + frame + "}, " + c + "}"),
              R"(line 7: box.axes[0]: is not unit length (|axes[0]|² = 25.000000, tolerance 1e-4); for axes of any length and angle use "kind": "parallelepiped")");
}

TEST(JsonlParallelepiped, GoodLinesAndAnswers) {
    const ParsedLine p = parse_line(
        R"({"box": {"kind": "parallelepiped", "center": [1, 2, 3], "axes": [[3, 4, 0], [-4, 3, 0], [0, 0, 0]], "extents": [1, 0.5, 7]}, )" + kCyl + "}",
        1);
    ASSERT_TRUE(p.query) << p.error;
    const auto& b = std::get<Parallelepiped<double>>(p.query->box);
    EXPECT_EQ(b.center, (Vec3<double>{1, 2, 3}));
    EXPECT_EQ(b.axes[0], (Vec3<double>{3, 4, 0}));
    EXPECT_EQ(b.axes[2], (Vec3<double>{0, 0, 0}));
    EXPECT_EQ(b.extents, (Vec3<double>{1, 0.5, 7}));
    // The box with integer vertices ±(3,4,0) ± (−4,3,0) ± (0,0,5): its face W0·X = 25 is touched by a
    // cylinder of radius 5 at distance 10, missed by one of radius 4.999.
    const std::string box = R"("box": {"kind": "parallelepiped", "center": [0, 0, 0], "axes": [[3, 4, 0], [-4, 3, 0], [0, 0, 5]], "extents": [1, 1, 1]})";
    for (const char* alg : {"inequalities", "hull", "oracle"}) {
        const RunOptions opt = make_run_options(alg, "filtered");
        EXPECT_EQ(answer_line("{\"id\": 1, " + box + R"(, "cylinder": {"center": [6, 8, 0], "axis": [0, 0, 1], "radius": 5, "height": 2}})", 1, opt).text,
                  R"({"id": 1, "intersect": true})") << alg;
        EXPECT_EQ(answer_line("{\"id\": 2, " + box + R"(, "cylinder": {"center": [6, 8, 0], "axis": [0, 0, 1], "radius": 4.999, "height": 2}})", 2, opt).text,
                  R"({"id": 2, "intersect": false})") << alg;
    }
}

// --- rounded arithmetic on frames that are not orthonormal ---

// An oriented box whose axes are 4e-5 from orthonormal (valid: within 1e-4) is the parallelepiped they
// span: its face x0 = 1000 passes x = 1000.03996 at y = 999. A cylinder overlapping it by 0.02 meets
// the box in every algorithm and arithmetic: in float and double the linear-inequalities and LCP
// methods, which take the axes as an orthonormal frame (they would see a gap of 0.02), hand the query
// to the convex-hull method.
TEST(JsonlFrames, AxesOffOrthonormalAreAnsweredForTheParallelepipedTheySpan) {
    const std::string box =
        R"("box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [4e-5, 1, 0], [0, 0, 1]], "extents": [1000, 1000, 1000]})";
    const std::string hit = "{" + box + R"(, "cylinder": {"center": [1000.51996, 999, 0], "axis": [0, 0, 1], "radius": 0.5, "height": 10}})";
    const std::string miss = "{" + box + R"(, "cylinder": {"center": [1000.55996, 999, 0], "axis": [0, 0, 1], "radius": 0.5, "height": 10}})";
    for (const char* alg : {"inequalities", "hull", "lcp", "oracle"})
        for (const char* ari : {"filtered", "double", "float"}) {
            const RunOptions opt = make_run_options(alg, ari);
            EXPECT_EQ(answer_line(hit, 1, opt).text, R"({"intersect": true})") << alg << " " << ari;
            EXPECT_EQ(answer_line(miss, 1, opt).text, R"({"intersect": false})") << alg << " " << ari;
        }
    const ParsedLine p = parse_line(hit, 1);
    ASSERT_TRUE(p.query) << p.error;
    EXPECT_TRUE(needs_hull_for_frame(*p.query, make_run_options("inequalities", "double").query));
    EXPECT_TRUE(needs_hull_for_frame(*p.query, make_run_options("lcp", "float").query));
    EXPECT_FALSE(needs_hull_for_frame(*p.query, make_run_options("hull", "double").query));
    EXPECT_FALSE(needs_hull_for_frame(*p.query, make_run_options("inequalities", "filtered").query));
    EXPECT_FALSE(needs_hull_for_frame(*p.query, make_run_options("oracle", "double").query));
}

// Axes orthonormal to within rounding (rotations computed in double, or rounded to float) keep the
// chosen method; an aligned box always does.
TEST(JsonlFrames, RotationsComputedInDoubleKeepTheChosenMethod) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    const RunOptions d = make_run_options("inequalities", "double"), f = make_run_options("lcp", "float");
    for (int k = 0; k < 2000; ++k) {
        double w = u(rng), a = u(rng), b = u(rng), c = u(rng);
        const double s = std::sqrt(w * w + a * a + b * b + c * c);
        w /= s, a /= s, b /= s, c /= s;
        Query q{OrientedBox<double>{{0, 0, 0},
                                    {Vec3<double>{1 - 2 * (b * b + c * c), 2 * (a * b + w * c), 2 * (a * c - w * b)},
                                     Vec3<double>{2 * (a * b - w * c), 1 - 2 * (a * a + c * c), 2 * (b * c + w * a)},
                                     Vec3<double>{2 * (a * c + w * b), 2 * (b * c - w * a), 1 - 2 * (a * a + b * b)}},
                                    {1, 1, 1}},
                Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 1}, std::nullopt};
        EXPECT_FALSE(needs_hull_for_frame(q, d.query)) << k;
        EXPECT_FALSE(needs_hull_for_frame(q, f.query)) << k;
        q.box = Parallelepiped<double>{std::get<OrientedBox<double>>(q.box).center, std::get<OrientedBox<double>>(q.box).axes,
                                       {1, 1, 1}};
        EXPECT_FALSE(needs_hull_for_frame(q, d.query)) << k;
    }
    const Query aligned{AlignedBox<double>{{0, 0, 0}, {1, 1, 1}}, Cylinder<double>{{0, 0, 0}, {0, 0, 1}, 1, 1}, std::nullopt};
    EXPECT_FALSE(needs_hull_for_frame(aligned, d.query));
}

// --- stop signals: the lines read in full are answered, in order; a line cut short is not ---

// Serves `text` in pieces ending at the given offsets; after the last piece, "receives" SIGTERM and
// ends the input, as the tool's reader does on a stop signal.
class SignalAfter : public std::streambuf {
public:
    SignalAfter(std::string text, std::vector<std::size_t> cuts) : text_(std::move(text)), cuts_(std::move(cuts)) {}

protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        if (next_ >= cuts_.size()) {
            set_stop_signal_for_testing(SIGTERM);
            return traits_type::eof();
        }
        char* base = text_.data();
        setg(base + begin_, base + begin_, base + cuts_[next_]);
        begin_ = cuts_[next_++];
        return gptr() < egptr() ? traits_type::to_int_type(*gptr()) : underflow();
    }

private:
    std::string text_;
    std::vector<std::size_t> cuts_;
    std::size_t next_ = 0, begin_ = 0;
};

TEST(JsonlStream, StopSignalAnswersTheLinesReadInFullAndNoMore) {
    const RunOptions opt = make_run_options("inequalities", "filtered");
    const std::string input = mixed_input(3 * stream_block_lines + 17, true);
    std::istringstream whole(input);
    std::ostringstream all;
    process_stream(whole, all, opt, 1);
    const std::vector<std::string> want = lines_of(all.str());
    // Offsets of the line starts.
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 0; i < input.size(); ++i)
        if (input[i] == '\n') starts.push_back(i + 1);
    for (const std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{100}, stream_block_lines + 3}) {
        for (const bool cut_mid_line : {false, true}) {
            // Lines 1..k in full, then (maybe) half of line k + 1, then the signal.
            std::vector<std::size_t> cuts;
            for (std::size_t i = 1; i <= k; ++i) cuts.push_back(starts[i]);
            if (cut_mid_line) cuts.push_back(starts[k] + (starts[k + 1] - starts[k]) / 2);
            for (const unsigned threads : {1u, 3u}) {
                SignalAfter buf(input, cuts);
                std::istream in(&buf);
                std::ostringstream out;
                const StreamCounts c = answer_stream(in, out, opt, threads);
                set_stop_signal_for_testing(0);
                EXPECT_EQ(c.lines, k) << k << " lines, cut " << cut_mid_line << ", " << threads << " threads";
                const std::vector<std::string> got = lines_of(out.str());
                ASSERT_EQ(got.size(), k) << k << " lines, cut " << cut_mid_line << ", " << threads << " threads";
                EXPECT_TRUE(std::equal(got.begin(), got.end(), want.begin())) << k << " lines, " << threads << " threads";
                EXPECT_TRUE(out.str().empty() || out.str().back() == '\n');
            }
        }
    }
    // A signal already received: nothing is read.
    set_stop_signal_for_testing(SIGINT);
    std::istringstream in(input);
    std::ostringstream out;
    EXPECT_EQ(answer_stream(in, out, opt, 1).lines, 0u);
    EXPECT_EQ(answer_stream(in, out, opt, 2).lines, 0u);
    set_stop_signal_for_testing(0);
    EXPECT_EQ(out.str(), "");
}

// A stream that fails to write stops the run: the rest of the input is not read.
TEST(JsonlStream, WriteErrorStopsReading) {
    class Failing : public std::streambuf {
    protected:
        int_type overflow(int_type) override { return traits_type::eof(); }
    };
    const RunOptions opt = make_run_options("inequalities", "filtered");
    const std::string input = mixed_input(12 * stream_block_lines, true);
    for (const unsigned threads : {1u, 2u}) {
        Failing buf;
        std::ostream out(&buf);
        std::istringstream in(input);
        const StreamCounts c = answer_stream(in, out, opt, threads);
        EXPECT_TRUE(out.bad());
        // One line (threads == 1); at most the blocks in flight and the one being filled (threads > 1).
        EXPECT_LE(c.lines, threads == 1 ? 1 : (2 * threads + 2) * stream_block_lines) << threads << " threads";
    }
}

// --- `boxcyl distance`: the same lines without "margin", a proved enclosure and a nearest pair ---

// The numbers of a distance line, read back (nlohmann reads each as the nearest double).
struct DistanceLine {
    double lower, upper;
    std::vector<double> on_box, on_cylinder;
};
DistanceLine read_distance(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text);
    return {j.at("lower").get<double>(), j.at("upper").get<double>(), j.at("on_box").get<std::vector<double>>(),
            j.at("on_cylinder").get<std::vector<double>>()};
}

TEST(JsonlDistance, ExactlyOneApartIsEnclosedTightly) {
    // The face x = 1 of the unit box and the cylinder's side at x = 2: distance exactly 1.
    const LineAnswer a = answer_distance_line(
        R"({"id": "one", "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, )"
        R"("cylinder": {"center": [3, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}})",
        1);
    ASSERT_TRUE(a.good) << a.text;
    EXPECT_EQ(a.text.rfind(R"({"id": "one", "lower": )", 0), 0u) << a.text;
    const DistanceLine d = read_distance(a.text);
    EXPECT_LE(d.lower, 1.0);
    EXPECT_GE(d.upper, 1.0);
    EXPECT_LE(bits(d.upper) - bits(d.lower), 4u) << a.text;  // at most 4 doubles apart
    ASSERT_EQ(d.on_box.size(), 3u);
    ASSERT_EQ(d.on_cylinder.size(), 3u);
    EXPECT_NEAR(d.on_box[0], 1.0, 1e-12);
    EXPECT_NEAR(d.on_cylinder[0], 2.0, 1e-12);
    // An oriented box and a parallelepiped spanning the same unit box: the same enclosure.
    for (const char* box : {R"({"center": [0.5, 0.5, 0.5], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [0.5, 0.5, 0.5]})",
                            R"({"kind": "parallelepiped", "center": [0.5, 0.5, 0.5], "axes": [[0.5, 0, 0], [0, 0.5, 0], [0, 0, 0.5]], "extents": [1, 1, 1]})"}) {
        const LineAnswer b = answer_distance_line(std::string(R"({"box": )") + box +
                                                      R"(, "cylinder": {"center": [3, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}})",
                                                  2);
        ASSERT_TRUE(b.good) << b.text;
        const DistanceLine e = read_distance(b.text);
        EXPECT_LE(e.lower, 1.0) << b.text;
        EXPECT_GE(e.upper, 1.0) << b.text;
        EXPECT_LE(bits(e.upper) - bits(e.lower), 4u) << b.text;
    }
}

TEST(JsonlDistance, TouchingIsExactlyZero) {
    // kCyl's side touches the face x = 1 along a segment.
    const LineAnswer a = answer_distance_line(R"({"id": 7, )" + kBox + ", " + kCyl + "}", 1);
    ASSERT_TRUE(a.good) << a.text;
    EXPECT_EQ(a.text.rfind(R"({"id": 7, "lower": 0, "upper": 0, "on_box": [)", 0), 0u) << a.text;
    const DistanceLine d = read_distance(a.text);
    EXPECT_EQ(bits(d.lower), bits(0.0));
    EXPECT_EQ(bits(d.upper), bits(0.0));
}

TEST(JsonlDistance, ExactTextAndNumbersThatRoundTrip) {
    Distance d;
    d.lower = 0.1;
    d.upper = 0.30000000000000004;
    d.on_box = {-0.0, 5e-324, 1.7976931348623157e308};
    d.on_cylinder = {1, -2.5, 1e23};
    EXPECT_EQ(format_distance("", d), R"({"lower": 0.1, "upper": 0.30000000000000004, "on_box": [-0, 5e-324, )"
                                      R"(1.7976931348623157e+308], "on_cylinder": [1, -2.5, 1e+23]})");
    // Beyond the largest double the upper bound is +inf: null, since JSON has no infinity.
    d.upper = std::numeric_limits<double>::infinity();
    const std::string text = format_distance("\"far\"", d);
    EXPECT_EQ(text.rfind(R"({"id": "far", "lower": 0.1, "upper": null, )", 0), 0u) << text;
    EXPECT_TRUE(nlohmann::json::parse(text).at("upper").is_null());
    // Random doubles read back bit for bit.
    std::mt19937_64 rng(11);
    for (int i = 0; i < 2000; ++i) {
        std::uint64_t b = rng();
        b &= ~(std::uint64_t{1} << 63);
        if ((b >> 52) == 0x7ff) continue;  // not finite
        d.lower = std::bit_cast<double>(b);
        d.upper = std::bit_cast<double>(b + 1);
        const DistanceLine r = read_distance(format_distance("", d));
        EXPECT_EQ(bits(r.lower), bits(d.lower));
        EXPECT_EQ(bits(r.upper), bits(d.upper));
    }
}

TEST(JsonlDistance, FarBeyondTheDoubleRangeHasNoUpperBound) {
    const LineAnswer a = answer_distance_line(
        R"({"box": {"min": [-1e308, 0, 0], "max": [-1e308, 1, 1]}, )"
        R"("cylinder": {"center": [1e308, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}})",
        1);
    ASSERT_TRUE(a.good) << a.text;
    const nlohmann::json j = nlohmann::json::parse(a.text);
    EXPECT_TRUE(j.at("upper").is_null()) << a.text;
    EXPECT_EQ(j.at("lower").get<double>(), std::numeric_limits<double>::max()) << a.text;
}

TEST(JsonlDistance, BadLinesAreReportedAsIntersectReportsThem) {
    const RunOptions opt = make_run_options(default_algorithm, default_arithmetic);
    for (const std::string& line :
         {std::string(), std::string("nope"), std::string(R"({"id": "a", "box": {)"), R"({"id": 5, )" + kBox + "}",
          R"({"id": 3, )" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": -1, "height": 1}})",
          R"({"id": 3, )" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 0], "radius": 1, "height": 1}})",
          "{" + kBox + ", " + kCyl + "} x"}) {
        const LineAnswer a = answer_distance_line(line, 9);
        EXPECT_FALSE(a.good) << line;
        EXPECT_EQ(a.text, answer_line(line, 9, opt).text) << line;
    }
    EXPECT_EQ(answer_distance_line(R"({"id": 5, )" + kBox + "}", 5).text, R"({"id": 5, "error": "line 5: cylinder: missing"})");
    // An unknown key is named with the keys a distance line accepts.
    EXPECT_EQ(answer_distance_line(R"({"id": 4, )" + kBox + ", " + kCyl + R"(, "radius": 1})", 6).text,
              R"x({"id": 4, "error": "line 6: radius: unknown key (accepted: id, box, cylinder)"})x");
}

TEST(JsonlDistance, AMarginIsRefusedWhateverItsValue) {
    for (const char* margin : {"1", "0", "-1", "\"x\""}) {
        const LineAnswer a = answer_distance_line("{\"id\": 2, " + kBox + ", " + kCyl + ", \"margin\": " + margin + "}", 3);
        EXPECT_FALSE(a.good);
        EXPECT_EQ(a.text, R"({"id": 2, "error": "line 3: margin: not a key of distance lines (the answer is the )"
                          R"x(distance itself; a margin belongs to `boxcyl intersect`)"})x")
            << margin;
    }
}

TEST(JsonlDistance, ThreadedOutputIsByteIdenticalToSerialInInputOrder) {
    for (const std::size_t n : {std::size_t{0}, std::size_t{40}, 2 * stream_block_lines + 17}) {
        const std::string input = mixed_input(n, n % 2 == 0);
        std::istringstream in1(input);
        std::ostringstream out1;
        DistanceOptions opt;
        opt.threads = 1;
        const StreamCounts c1 = process_distance_stream(in1, out1, opt);
        const std::vector<std::string> lines = lines_of(out1.str());
        ASSERT_EQ(lines.size(), n);
        EXPECT_EQ(c1.lines, n);
        // In input order: line i answers the query with id i, or names line i.
        for (std::size_t i = 0; i < n; ++i) {
            const std::string id = "{\"id\": " + std::to_string(i + 1) + ", ";
            const std::string where = "line " + std::to_string(i + 1) + ": ";
            EXPECT_TRUE(lines[i].rfind(id, 0) == 0 || lines[i].find(where) != std::string::npos) << lines[i];
        }
        for (const unsigned threads : {2u, 3u}) {
            std::istringstream in(input);
            std::ostringstream out;
            opt.threads = threads;
            const StreamCounts c = process_distance_stream(in, out, opt);
            EXPECT_EQ(c.lines, c1.lines);
            EXPECT_EQ(c.bad, c1.bad);
            EXPECT_TRUE(out.str() == out1.str()) << n << " lines, " << threads << " threads: output differs";
        }
    }
}

// --- `boxcyl distance --signed`: the same lines, the signed distance with a normal ---

// The box [-1, 1]^3 and a tall cylinder of radius 1 whose axis is x = 1.5: they overlap by 0.5 along x.
// The shapes' size L is the half height, 5: the bounds are at most 5·2^-43 apart.
const std::string kDeep = R"({"id": "deep", "box": {"min": [-1, -1, -1], "max": [1, 1, 1]}, )"
                          R"("cylinder": {"center": [1.5, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 10}})";

// The line without its "normal" key: what `boxcyl distance` writes for a pair that is apart.
std::string without_normal(std::string text) {
    const std::size_t at = text.find(R"(, "normal": [)");
    if (at != std::string::npos) text.erase(at, text.find(']', at) + 1 - at);
    return text;
}

TEST(JsonlDistance, SignedOverlapIsMinusTheDepth) {
    const LineAnswer a = answer_distance_line(kDeep, 1, true);
    ASSERT_TRUE(a.good) << a.text;
    EXPECT_EQ(a.text.rfind(R"({"id": "deep", "lower": )", 0), 0u) << a.text;
    const nlohmann::json j = nlohmann::json::parse(a.text);
    ASSERT_EQ(j.size(), 6u) << a.text;  // id, lower, upper, normal, on_box, on_cylinder
    const double lower = j.at("lower").get<double>(), upper = j.at("upper").get<double>();
    EXPECT_LE(lower, -0.5) << a.text;
    EXPECT_GE(upper, -0.5) << a.text;
    EXPECT_LE(upper - lower, 5 * 0x1p-43) << a.text;  // L: the half height
    const auto normal = j.at("normal").get<std::vector<double>>();
    const auto on_box = j.at("on_box").get<std::vector<double>>();
    const auto on_cylinder = j.at("on_cylinder").get<std::vector<double>>();
    ASSERT_EQ(normal.size(), 3u);
    ASSERT_EQ(on_box.size(), 3u);
    ASSERT_EQ(on_cylinder.size(), 3u);
    EXPECT_NEAR(normal[0], 1.0, 1e-9) << a.text;
    EXPECT_NEAR(normal[1], 0.0, 1e-9) << a.text;
    EXPECT_NEAR(normal[2], 0.0, 1e-9) << a.text;
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(on_cylinder[k] - on_box[k], -0.5 * normal[k], 1e-9) << a.text;
    // Without --signed the same line is 0 apart.
    EXPECT_EQ(answer_distance_line(kDeep, 1).text.rfind(R"({"id": "deep", "lower": 0, "upper": 0, "on_box": [)", 0), 0u);
}

TEST(JsonlDistance, SignedApartIsTheDistanceWithANormal) {
    const std::string line = R"({"id": "one", "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, )"
                             R"("cylinder": {"center": [3, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}})";
    const LineAnswer a = answer_distance_line(line, 1, true);
    ASSERT_TRUE(a.good) << a.text;
    EXPECT_EQ(without_normal(a.text), answer_distance_line(line, 1).text);
    const auto normal = nlohmann::json::parse(a.text).at("normal").get<std::vector<double>>();
    ASSERT_EQ(normal.size(), 3u);
    EXPECT_NEAR(normal[0], 1.0, 1e-12) << a.text;
    EXPECT_NEAR(std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]), 1.0, 1e-12);
}

TEST(JsonlDistance, SignedTextAndNumbersThatRoundTrip) {
    SignedDistance d;
    d.lower = -0.5000000000000001;
    d.upper = -0.5;
    d.normal = {1, 0, -0.0};
    d.on_box = {1, 5e-324, 1.7976931348623157e308};
    d.on_cylinder = {0.5, -2.5, 1e23};
    EXPECT_EQ(format_signed_distance("7", d),
              R"({"id": 7, "lower": -0.5000000000000001, "upper": -0.5, "normal": [1, 0, -0], "on_box": [1, 5e-324, )"
              R"(1.7976931348623157e+308], "on_cylinder": [0.5, -2.5, 1e+23]})");
    d.upper = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(nlohmann::json::parse(format_signed_distance("", d)).at("upper").is_null());
}

TEST(JsonlDistance, SignedBadLinesAreReportedAsWithoutIt) {
    const std::string with_margin = "{\"id\": 2, " + kBox + ", " + kCyl + ", \"margin\": 1}";
    for (const std::string& line :
         {std::string(), std::string("nope"), R"({"id": 5, )" + kBox + "}",
          R"({"id": 3, )" + kBox + R"(, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 0], "radius": 1, "height": 1}})",
          with_margin}) {
        const LineAnswer a = answer_distance_line(line, 9, true);
        EXPECT_FALSE(a.good) << line;
        EXPECT_EQ(a.text, answer_distance_line(line, 9).text) << line;
    }
}

TEST(JsonlDistance, SignedStreamIsByteIdenticalOnThreads) {
    std::string input;
    for (int i = 1; i <= 60; ++i) {
        // The cylinder's x slides from deep inside the box to beyond its face x = 1, with bad lines among them.
        const double x = 0.25 * static_cast<double>(i % 12);
        input += R"({"id": )";
        input += std::to_string(i);
        input += ", ";
        input += kBox;
        if (i % 17 == 0) {
            input += "}";  // no cylinder
        } else {
            input += R"(, "cylinder": {"center": [)";
            input += std::to_string(x);
            input += R"(, 0.5, 0.5], "axis": [0, 1, 1], "radius": 0.5, "height": 1}})";
        }
        input += '\n';
    }
    DistanceOptions opt;
    opt.signed_distance = true;
    std::istringstream in1(input);
    std::ostringstream out1;
    const StreamCounts c1 = process_distance_stream(in1, out1, opt);
    const std::vector<std::string> lines = lines_of(out1.str());
    ASSERT_EQ(lines.size(), 60u);
    EXPECT_EQ(c1.bad, 3u);
    for (const std::string& line : lines)
        EXPECT_TRUE(line.find(R"("normal": [)") != std::string::npos || line.find(R"("error": )") != std::string::npos)
            << line;
    for (const unsigned threads : {2u, 3u}) {
        std::istringstream in(input);
        std::ostringstream out;
        opt.threads = threads;
        const StreamCounts c = process_distance_stream(in, out, opt);
        EXPECT_EQ(c.lines, c1.lines);
        EXPECT_EQ(c.bad, c1.bad);
        EXPECT_TRUE(out.str() == out1.str()) << threads << " threads: output differs";
    }
}

}  // namespace
}  // namespace boxcyl::cli
