// See distance.hpp. The lines are read by jsonl_query (parse_distance_line) and answered through
// query_call (run_distance_query, run_signed_distance_query); this file writes the answers and holds
// the subcommand.
#include "distance.hpp"

#include <array>         // to_chars' buffer
#include <charconv>      // std::to_chars: the shortest text that reads back as the same double
#include <cmath>         // std::isfinite
#include <exception>     // failures of the library call
#include <initializer_list>  // the refused options
#include <istream>       // the input
#include <memory>        // the input file
#include <new>           // std::bad_alloc
#include <ostream>       // output lines
#include <string>        // help text, output lines

#include <CLI/CLI.hpp>

#include "app.hpp"  // exit codes, open_input, end_of_run

namespace boxcyl::cli {

namespace {

constexpr const char* distance_help = R"(INPUT
  JSON Lines (UTF-8): one query per line, a JSON object
    {"id": ID, "box": BOX, "cylinder": CYLINDER}
  ID, BOX, CYLINDER, numbers, other keys and duplicate keys are read exactly as by
  `boxcyl intersect` (see `boxcyl intersect --help`): aligned and oriented boxes and any
  parallelepiped. A "margin" key makes the line bad: here the distance itself is the answer
  (`boxcyl intersect` answers whether the box comes within a margin).

SEMANTICS
  The Euclidean distance between the closed solids (0 when they touch or overlap), for the
  numbers as read (each the nearest double to the text). Every answer is certified, so there
  is no --algorithm or --arithmetic to choose (given, they are refused).
  With --signed, the signed distance: the distance when the solids are apart, minus the
  penetration depth (the length of the shortest translation of the box that separates
  them) when they overlap, 0 when they touch.

OUTPUT
  Exactly one JSON line per input line, in input order:
    {"id": ID, "lower": L, "upper": U, "on_box": [x, y, z], "on_cylinder": [x, y, z]}
    {"id": ID, "error": "line N: FIELD: REASON"}       for a bad line, as `boxcyl intersect`
  ("id" only when the line has a valid one). L <= distance <= U is proved; L and U are at
  most 4 doubles apart (so U - L <= 4 units in the last place of U), and both are exactly 0
  when the solids touch or overlap. U is null when the distance exceeds the largest double
  (about 1.8e308): JSON has no infinity, and no double bounds it. on_box and on_cylinder are
  a nearest pair, one point near each solid: approximate, not proved (for solids that meet,
  near a common point). Every number is written in the shortest form that reads back as the
  same double (1, 0.1, 5e-324). Bad lines, long lines and memory as for `boxcyl intersect`.
  With --signed each answer has a "normal" too:
    {"id": ID, "lower": L, "upper": U, "normal": [x, y, z], "on_box": [x, y, z],
     "on_cylinder": [x, y, z]}
  L <= signed distance <= U is proved: apart, the bounds above; overlapping, U - L is at
  most 2^-43 times the shapes' size (the largest of the box centre's offset from the
  cylinder's centre, the half axes' components, the radius and the half height). normal is a unit vector from the box towards the cylinder (the box moves along
  -normal to separate); on_box and on_cylinder are a witness pair, on_cylinder - on_box
  about the signed distance times normal (approximate, not proved).

EXAMPLE
  echo '{"box":{"min":[0,0,0],"max":[1,1,1]},"cylinder":{"center":[3,0.5,0.5],"axis":[0,0,1],"radius":1,"height":1}}' | boxcyl distance
  {"lower": 1, "upper": 1, "on_box": [1, 0.5, 1], "on_cylinder": [2, 0.5, 1]}
)";

void append_number(std::string& s, double x) {
    if (!std::isfinite(x)) {
        s += "null";
        return;
    }
    std::array<char, 32> buffer;  // the longest shortest form, -2.2250738585072014e-308, has 24
    const auto r = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
    s.append(buffer.data(), r.ptr);
}

void append_point(std::string& s, const Vec3<double>& p) {
    s += '[';
    append_number(s, p[0]);
    s += ", ";
    append_number(s, p[1]);
    s += ", ";
    append_number(s, p[2]);
    s += ']';
}

LineAnswer answer_distance_line_unguarded(std::string_view text, std::size_t line_number, bool signed_distance) {
    const ParsedLine p = parse_distance_line(text, line_number);
    if (!p.query) return {format_error(p.id, p.error), false};
    const std::string where = "line " + std::to_string(line_number) + ": ";
    try {
        if (signed_distance) return {format_signed_distance(p.id, run_signed_distance_query(*p.query)), true};
        return {format_distance(p.id, run_distance_query(*p.query)), true};
    } catch (const std::bad_alloc&) {
        return {format_error(p.id, where + "out of memory answering the line"), false};
    } catch (const std::exception& e) {
        // Not expected for validated input; reported per line rather than ending the run.
        return {format_error(p.id, where + "query failed: " + e.what()), false};
    }
}

}  // namespace

namespace {

// One answer line: the enclosure, the direction where there is one (the signed distance's), the pair.
std::string format_answer(const std::string& id, double lower, double upper, const Vec3<double>* normal,
                          const Vec3<double>& on_box, const Vec3<double>& on_cylinder) {
    std::string s = "{";
    if (!id.empty()) s += "\"id\": " + id + ", ";
    s += "\"lower\": ";
    append_number(s, lower);
    s += ", \"upper\": ";
    append_number(s, upper);
    if (normal) {
        s += ", \"normal\": ";
        append_point(s, *normal);
    }
    s += ", \"on_box\": ";
    append_point(s, on_box);
    s += ", \"on_cylinder\": ";
    append_point(s, on_cylinder);
    s += '}';
    return s;
}

}  // namespace

std::string format_distance(const std::string& id, const Distance& d) {
    return format_answer(id, d.lower, d.upper, nullptr, d.on_box, d.on_cylinder);
}

std::string format_signed_distance(const std::string& id, const SignedDistance& d) {
    return format_answer(id, d.lower, d.upper, &d.normal, d.on_box, d.on_cylinder);
}

LineAnswer answer_distance_line(std::string_view text, std::size_t line_number, bool signed_distance) {
    try {
        return answer_distance_line_unguarded(text, line_number, signed_distance);
    } catch (const std::bad_alloc&) {
        return {format_error({}, "line " + std::to_string(line_number) + ": out of memory answering the line"), false};
    } catch (const std::exception& e) {
        return {format_error({}, "line " + std::to_string(line_number) + ": " + e.what()), false};
    }
}

StreamCounts process_distance_stream(std::istream& in, std::ostream& out, const DistanceOptions& opt) {
    return answer_lines(in, out, opt.max_line_bytes, opt.threads, [&opt](std::string_view line, std::size_t n) {
        return answer_distance_line(line, n, opt.signed_distance);
    });
}

void add_distance_command(CLI::App& app, DistanceCommand& cmd) {
    cmd.app = app.add_subcommand(
        "distance", "Answer one query per input line: how far apart are the box and the cylinder (proved bounds; "
                    "--signed: or how deep they overlap)?");
    cmd.app->footer(std::string(distance_help) + "\n" + exit_status_help);
    cmd.app->add_option("--threads", cmd.options.threads,
                        "Threads answering lines (default 1; 0: one per core); the output is the same, in input order")
        ->check(CLI::Range(0u, 1024u));
    cmd.app->add_flag("--signed", cmd.options.signed_distance,
                      "The signed distance: minus the penetration depth where the solids overlap; each answer "
                      "has a \"normal\" too");
    cmd.app->add_option("file", cmd.file, "JSON Lines input; '-' or none: standard input");
    add_max_line_bytes_option(*cmd.app, cmd.options.max_line_bytes);
    // Accepted only to be refused with a reason (run_distance): intersect's users will try them.
    cmd.app->add_option("--algorithm", cmd.refused)->group("");
    cmd.app->add_option("--arithmetic", cmd.refused)->group("");
}

int run_distance(const DistanceCommand& cmd, std::istream& in, std::ostream& out, std::ostream& err) {
    for (const char* option : {"--algorithm", "--arithmetic"})
        if (cmd.app->count(option) > 0) {
            err << "boxcyl: distance: " << option
                << " does not apply: every distance is certified (proved bounds), whatever the arithmetic\n";
            return exit_usage;
        }
#if !defined(BOXCYL_CLI_EXACT)
    (void)in, (void)out;
    err << "boxcyl: distance needs the exact backend (GMP); this build has none\n";
    return exit_usage;
#else
    std::unique_ptr<std::istream> f;
    if (cmd.file != "-") {
        f = open_input(cmd.file, err);
        if (!f) return exit_usage;
    }
    std::istream& input = f ? *f : in;
    return end_of_run(process_distance_stream(input, out, cmd.options), input, input_name(cmd.file), out, err);
#endif
}

}  // namespace boxcyl::cli
