// JSON Lines in, JSON Lines out: the parsing, checking and formatting behind `boxcyl intersect`.
// Separate from main.cpp so that tests can drive it directly. The geometry is the library's: this only
// turns one line of text into a box and a cylinder (or a message naming what is wrong) and an answer
// back into one line of text.
#pragma once

#include <cstddef>      // std::size_t
#include <functional>   // parse_object_line's field reader
#include <initializer_list>  // accepted keys
#include <istream>      // std::istream (process_lines)
#include <ostream>      // std::ostream
#include <optional>     // a line may not yield a query
#include <stdexcept>    // ThreadsUnavailable
#include <string>       // JSON text, messages
#include <string_view>  // input lines
#include <variant>      // aligned or oriented box, or parallelepiped

#include <nlohmann/json_fwd.hpp>  // nlohmann::json, for the readers shared with other subcommands

#include "boxcyl/distance_types.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "io.hpp"  // stop_signal
#include "options.hpp"

namespace boxcyl::cli {

using AnyBox = std::variant<AlignedBox<double>, OrientedBox<double>, Parallelepiped<double>>;

struct Query {
    AnyBox box;
    Cylinder<double> cylinder;
    std::optional<double> margin;  // "margin": within that distance (always answered exactly)
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

// The same for `boxcyl distance`, whose lines have no "margin" (the distance is the answer): a line
// with one is bad, and its message says where a margin belongs.
ParsedLine parse_distance_line(std::string_view text, std::size_t line_number);

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
// Every key of the object `obj` must be one of `accepted`: "" or "<field>.<key>: unknown key; did you
// mean "<nearest>"? (accepted: ...)". `field` names the object ("" for the top level).
std::string check_keys_field(const nlohmann::json& obj, const std::string& field,
                             std::initializer_list<std::string_view> accepted);

// A query that is valid in double may not survive rounding to float (overflow to ±Inf, an axis that
// underflows to zero, ...). When `opt.rounds_to_float`, says which field breaks; otherwise ok().
Validity check_arithmetic(const Query& q, const RunOptions& opt);

// The one place the tool asks the library (boxcyl::intersects; boxcyl::within_distance for a line with a
// margin, exact whatever the options). In float or double arithmetic the
// linear-inequalities and LCP methods take a box's axes as an orthonormal frame; a box whose axes are
// further from orthonormal than that arithmetic's rounding (needs_hull_for_frame: |Ai·Aj − δij| above
// 2^-49 in double, 2^-20 in float) is answered by the convex-hull method instead, in the same
// arithmetic, for the parallelepiped its axes span exactly as given.
bool run_query(const Query& q, const QueryOptions& opt);
bool needs_hull_for_frame(const Query& q, const QueryOptions& opt);

// boxcyl::distance for the query's box and cylinder (`boxcyl distance`; the margin is not looked at).
// Needs the exact backend: without it, throws std::invalid_argument saying so.
Distance run_distance_query(const Query& q);
// boxcyl::signed_distance for the same (`boxcyl distance --signed`), under the same conditions.
SignedDistance run_signed_distance_query(const Query& q);

// Output lines, without the newline. `id` is JSON text or empty (no "id" key).
std::string format_answer(const std::string& id, bool intersect);
std::string format_error(const std::string& id, const std::string& message);

// Answers one line: the output line (without newline) and whether the input line was good. Never
// throws: running out of memory on a line (or any other failure) is that line's error.
struct LineAnswer {
    std::string text;
    bool good;
};
LineAnswer answer_line(std::string_view text, std::size_t line_number, const RunOptions& opt);

// Reading lines with a bound on memory. A line's parse needs about 23 bytes of memory per input byte,
// so one huge line could exhaust memory and take the answers of every other line with it; the tool
// instead reads at most max_line_bytes of a line (--max-line-bytes), skips the rest of a longer one
// without keeping it, and answers it with an error line in place (default_max_line_bytes: options.hpp).
// Before reading or answering a line this long, the answers so far are flushed (it may fail).
inline constexpr std::size_t risky_line_bytes = std::size_t{1} << 20;

enum class LineRead {
    line,       // `line` holds the line (without its newline)
    too_long,   // longer than max_bytes: skipped to its newline, `line` empty
    no_memory,  // memory ran out while keeping it: skipped to its newline, `line` empty
    end,        // no more input (or a read error: see in.bad())
};

// Reads one line of `in` into `line` (as std::getline does, a last line without newline included),
// keeping at most `max_bytes` bytes of it. When the line reaches risky_line_bytes and `flush_if_long`
// is set, flushes that stream first. `newline` (if given) says whether the line ended with its newline.
LineRead read_line(std::istream& in, std::string& line, std::size_t max_bytes, std::ostream* flush_if_long = nullptr,
                   bool* newline = nullptr);

// The error line for a line that read_line could not keep (too_long or no_memory), and its message.
LineAnswer unread_line_answer(LineRead r, std::size_t line_number, std::size_t max_bytes);
std::string unread_line_message(LineRead r, std::size_t line_number, std::size_t max_bytes);

// What a run over a stream did: the input lines it answered (each with one output line) and how many
// of them were bad.
struct StreamCounts {
    std::size_t lines = 0;
    std::size_t bad = 0;
};

// The serial line loop shared by the subcommands: answer(line, line_number) → LineAnswer for each
// input line, in order (lines longer than max_line_bytes get an error line instead); flushes `out`
// before a read could block, so that a caller feeding lines one by one sees each answer, and before a
// long line. `answer` must not throw (answer_line reports a resource error as the line's error).
// Stops early, with every line read so far answered, when writing `out` fails (out.bad()) or a stop
// signal arrives (stop_signal(); then a last line without its newline was cut short and is not
// answered). Reading stops at a read error too (in.bad()).
template <class Answer>
StreamCounts process_lines(std::istream& in, std::ostream& out, std::size_t max_line_bytes, Answer&& answer) {
    StreamCounts counts;
    std::string line;
    // Also before a read waits in the middle of a line (the answers before it are complete).
    const BeforeWait flush_before_wait(in, [&out] { out.flush(); });
    while (out && stop_signal() == 0) {
        if (in.rdbuf() == nullptr || in.rdbuf()->in_avail() <= 0) out.flush();
        if (!out) break;
        bool newline = false;
        const LineRead r = read_line(in, line, max_line_bytes, &out, &newline);
        if (r == LineRead::end || (!newline && stop_signal() != 0)) break;
        const std::size_t line_number = ++counts.lines;
        const LineAnswer a = r == LineRead::line ? answer(std::string_view(line), line_number)
                                                 : unread_line_answer(r, line_number, max_line_bytes);
        out << a.text << '\n';
        if (!a.good) ++counts.bad;
        if (line.capacity() > risky_line_bytes) std::string().swap(line);  // do not keep a long line's memory
    }
    out.flush();
    return counts;
}

// Thrown by process_stream when the threads of threads > 1 cannot be started (std::system_error from
// std::thread): nothing has been read or written then.
struct ThreadsUnavailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Reads `in` line by line, writes one output line per input line in input order. Returns the counts
// (process_stream: the number of bad lines). Flushes `out` whenever no more input is buffered (threads == 1) or no further answer
// is ready (threads > 1), so that the tool also works as an interactive filter.
// threads == 1: one line at a time, memory bounded by opt.max_line_bytes. threads > 1: that many
// workers answer blocks of up to stream_block_lines lines (or stream_block_bytes bytes) while this
// thread reads; at most 2 * threads blocks are in flight, so memory stays bounded too, and the
// output is byte for byte the single-threaded one. A line of risky_line_bytes or more starts a block
// of its own. threads == 0: std::thread::hardware_concurrency().
// As process_lines, it stops early when writing fails or a stop signal arrives: every line read in full
// by then is answered and written, in input order. Throws ThreadsUnavailable (see above).
inline constexpr std::size_t stream_block_lines = 4096;
inline constexpr std::size_t stream_block_bytes = std::size_t{1} << 20;
StreamCounts answer_stream(std::istream& in, std::ostream& out, const RunOptions& opt, unsigned threads = 1);
inline std::size_t process_stream(std::istream& in, std::ostream& out, const RunOptions& opt, unsigned threads = 1) {
    return answer_stream(in, out, opt, threads).bad;
}

// answer_stream for any subcommand: answer(line, line_number) answers each line that read_line kept,
// on `threads` threads as above; it must not throw (answer_line reports a resource error as the
// line's error) and may be called from several threads at once.
using LineAnswerer = std::function<LineAnswer(std::string_view, std::size_t)>;
StreamCounts answer_lines(std::istream& in, std::ostream& out, std::size_t max_line_bytes, unsigned threads,
                          const LineAnswerer& answer);

}  // namespace boxcyl::cli
