// JSON Lines in, JSON Lines out: the parsing, checking and formatting behind `boxcyl intersect`.
// Separate from main.cpp so that tests can drive it directly. The geometry is the library's: this only
// turns one line of text into a box and a cylinder (or a message naming what is wrong) and an answer
// back into one line of text.
#pragma once

#include <cstddef>      // std::size_t
#include <functional>   // parse_object_line's field reader
#include <istream>      // std::istream, std::getline (process_lines)
#include <ostream>      // std::ostream
#include <optional>     // a line may not yield a query
#include <string>       // JSON text, messages
#include <string_view>  // input lines
#include <variant>      // aligned or oriented box, or parallelepiped

#include <nlohmann/json_fwd.hpp>  // nlohmann::json, for the readers shared with other subcommands

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "options.hpp"

namespace boxcyl::cli {

using AnyBox = std::variant<AlignedBox<double>, OrientedBox<double>, Parallelepiped<double>>;

struct Query {
    AnyBox box;
    Cylinder<double> cylinder;
};

// The outcome of reading one input line.
struct ParsedLine {
    std::string id;              // the "id" value as JSON text (echoed as is); empty when absent or bad
    std::optional<Query> query;  // set exactly when the line is good
    std::string error;           // "line N: <what>" when the line is bad
};

// Reads one line (without its newline; a trailing '\r' is JSON whitespace and harmless) as a query:
// JSON syntax, structure, number range and boxcyl::validate(). `line_number` counts from 1.
ParsedLine parse_line(std::string_view text, std::size_t line_number);

// The JSON half of parse_line, for other subcommands (`boxcyl grid`): reads `text` as one JSON object
// under the same rules and messages (empty line, syntax, numbers beyond the double range, duplicate
// keys, the "id" echoed as written), then hands the object to `read_fields`, which returns "" or
// "<field>: <reason>". `error` is "line N: <what>" when anything failed, else empty.
struct ObjectLine {
    std::string id;  // as ParsedLine::id
    std::string error;
};
ObjectLine parse_object_line(std::string_view text, std::size_t line_number,
                             const std::function<std::string(const nlohmann::json&)>& read_fields);

// Readers for read_fields, as parse_line reads these fields: "" or "<field>: <reason>". They check
// the structure only; validate() the result.
std::string read_cylinder_field(const nlohmann::json& root, Cylinder<double>& out);  // root["cylinder"]
std::string read_vec3_field(const nlohmann::json& obj, const char* key, const std::string& field, Vec3<double>& out);

// A query that is valid in double may not survive rounding to float (overflow to ±Inf, an axis that
// underflows to zero, ...). When `opt.rounds_to_float`, says which field breaks; otherwise ok().
Validity check_arithmetic(const Query& q, const RunOptions& opt);

// The one place the tool asks the library (boxcyl::intersects from boxcyl/query.hpp).
bool run_query(const Query& q, const QueryOptions& opt);

// Output lines, without the newline. `id` is JSON text or empty (no "id" key).
std::string format_answer(const std::string& id, bool intersect);
std::string format_error(const std::string& id, const std::string& message);

// Answers one line: the output line (without newline) and whether the input line was good.
struct LineAnswer {
    std::string text;
    bool good;
};
LineAnswer answer_line(std::string_view text, std::size_t line_number, const RunOptions& opt);

// The serial line loop shared by the subcommands: answer(line, line_number) → LineAnswer for each
// input line, in order; flushes `out` before a read could block, so that a caller feeding lines one by
// one sees each answer. Returns the number of bad lines.
template <class Answer>
std::size_t process_lines(std::istream& in, std::ostream& out, Answer&& answer) {
    std::size_t line_number = 0;
    std::size_t bad = 0;
    std::string line;
    for (;;) {
        if (in.rdbuf() == nullptr || in.rdbuf()->in_avail() <= 0) out.flush();
        if (!std::getline(in, line)) break;
        const LineAnswer a = answer(std::string_view(line), ++line_number);
        out << a.text << '\n';
        if (!a.good) ++bad;
    }
    out.flush();
    return bad;
}

// Reads `in` line by line, writes one output line per input line in input order. Returns the number
// of bad lines. Flushes `out` whenever no more input is buffered (threads == 1) or no further answer
// is ready (threads > 1), so that the tool also works as an interactive filter.
// threads == 1: one line at a time, memory bounded by the longest line. threads > 1: that many
// workers answer blocks of up to stream_block_lines lines (or stream_block_bytes bytes) while this
// thread reads; at most 2 * threads blocks are in flight, so memory stays bounded too, and the
// output is byte for byte the single-threaded one. threads == 0: std::thread::hardware_concurrency().
inline constexpr std::size_t stream_block_lines = 4096;
inline constexpr std::size_t stream_block_bytes = std::size_t{1} << 20;
std::size_t process_stream(std::istream& in, std::ostream& out, const RunOptions& opt, unsigned threads = 1);

}  // namespace boxcyl::cli
