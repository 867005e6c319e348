// See jsonl_query.hpp. Parsing goes through nlohmann-json's SAX interface into our own small DOM
// builder, for three things the plain DOM parser cannot give: the path of a number that overflows the
// double range (nlohmann reports it as a bare parse error), the exact text of a numeric "id" (echoed
// unchanged, e.g. 12345678901234567890123 or 1e2, which a double would rewrite), and a refusal of
// duplicate keys (the DOM parser silently keeps the last one).
//
// Numbers: nlohmann's lexer converts with strtod, which is correctly rounded (glibc), so every JSON
// number becomes the nearest double and 17-significant-digit values round-trip; integers that fit
// 64 bits are converted with a (correctly rounded) cast, larger ones go through strtod.
#include "jsonl_query.hpp"

#include "boxcyl/margin.hpp"  // a line's "margin"

#include <algorithm>           // std::max, std::min
#include <array>               // read_line's chunk
#include <condition_variable>  // process_stream's hand-offs between threads
#include <cstdint>             // integer SAX events
#include <deque>               // blocks in flight
#include <exception>           // failures of the library call
#include <istream>             // std::istream::getline
#include <memory>              // blocks
#include <new>                 // std::bad_alloc
#include <system_error>        // threads that cannot be started
#include <mutex>               // process_stream's shared state
#include <ostream>             // output lines
#include <thread>              // process_stream's workers
#include <utility>             // std::move
#include <vector>              // the DOM builder's stack

#include <nlohmann/json.hpp>

namespace boxcyl::cli {

namespace {

using json = nlohmann::json;

// Builds a nlohmann::json value from SAX events, tracking where in the document the parser is.
class DomBuilder {
public:
    // `budget`: about how many bytes of memory the DOM may take (see charge()).
    DomBuilder(json& root, std::size_t budget) : root_(root), budget_(budget) {}

    bool null() { return put(nullptr) != nullptr; }
    bool boolean(bool b) { return put(b) != nullptr; }
    bool number_integer(json::number_integer_t v) {
        note_id_text(std::to_string(v));
        return put(v) != nullptr;
    }
    bool number_unsigned(json::number_unsigned_t v) {
        note_id_text(std::to_string(v));
        return put(v) != nullptr;
    }
    bool number_float(json::number_float_t v, const json::string_t& text) {
        note_id_text(text);
        return put(v) != nullptr;
    }
    bool string(json::string_t& s) { return charge(s.size()) && put(std::move(s)) != nullptr; }
    bool binary(json::binary_t& b) { return put(json::binary(std::move(b))) != nullptr; }

    bool start_object(std::size_t) { return open(json::object()); }
    bool start_array(std::size_t) { return open(json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(json::string_t& k) {
        if (!charge(member_cost + k.size())) return false;
        Frame& f = stack_.back();
        f.key = k;
        if (f.node->contains(k)) {
            error_ = path() + ": duplicate key";
            return false;
        }
        return true;
    }

    bool parse_error(std::size_t position, const std::string&, const nlohmann::json::exception& ex) {
        error_position_ = position;
        // 406 is "number overflow": strtod gave ±Inf, i.e. the literal is beyond the double range.
        if (ex.id == 406) {
            const std::string where = path();
            error_ = (where.empty() ? std::string("value") : where) + ": out of double range";
        } else {
            error_ = "invalid JSON: " + strip_exception_prefix(ex.what());
        }
        return false;
    }

    const std::string& error() const { return error_; }
    const std::string& id_text() const { return id_text_; }
    // Bytes read when the parser reported its error (the offending byte included).
    std::size_t error_position() const { return error_position_; }

private:
    struct Frame {
        json* node;
        std::string key;  // objects: the key whose value is being read
    };

    // Adds a value where the parser is: the root, the next array element or the current key's value.
    template <class V>
    json* put(V&& v) {
        if (!charge(value_cost)) return nullptr;
        if (stack_.empty()) {
            root_ = json(std::forward<V>(v));
            return &root_;
        }
        Frame& f = stack_.back();
        if (f.node->is_array()) {
            f.node->push_back(json(std::forward<V>(v)));
            return &f.node->back();
        }
        json& slot = (*f.node)[f.key];
        slot = json(std::forward<V>(v));
        return &slot;
    }

    // Counts `bytes` against the budget; false (the parse stops) once it is spent. A hostile line of
    // many small values ("[[],[],..." or {"a":0,"b":0,...}) would otherwise cost ~23 bytes of DOM per
    // input byte.
    bool charge(std::size_t bytes) {
        used_ += bytes;
        if (used_ <= budget_) return true;
        if (error_.empty())
            error_ = "too large to parse: its JSON values would take more than " + std::to_string(budget_) +
                     " bytes of memory";
        return false;
    }

    bool open(json&& empty) {
        // A query needs depth 4; the limit keeps a hostile line ("[[[[...") from costing ~100 bytes of
        // DOM and stack per input byte.
        if (stack_.size() >= max_depth) {
            error_ = "invalid JSON: nested deeper than " + std::to_string(max_depth) + " levels";
            return false;
        }
        json* p = put(std::move(empty));
        if (p == nullptr) return false;
        stack_.push_back({p, {}});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    // The top-level "id" as written, when it is a number (strings are re-serialised from the DOM).
    void note_id_text(const std::string& text) {
        if (stack_.size() == 1 && stack_.back().node->is_object() && stack_.back().key == "id") id_text_ = text;
    }

    // Where the parser is, as a field name: "cylinder.center[2]". The innermost array's next element
    // is the one being read; enclosing arrays already hold the element being read.
    std::string path() const {
        std::string p;
        for (std::size_t i = 0; i < stack_.size(); ++i) {
            const Frame& f = stack_[i];
            if (f.node->is_array()) {
                std::size_t index = f.node->size();
                if (i + 1 < stack_.size()) --index;
                // Appended piecewise: `"[" + std::string` trips GCC 12's false -Wrestrict (bug 105329).
                p += '[';
                p += std::to_string(index);
                p += ']';
            } else {
                if (!p.empty()) p += ".";
                p += f.key;
            }
        }
        return p;
    }

    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." ->
    // "column 5: syntax error ...": the exception id and the always-1 line say nothing to the user.
    static std::string strip_exception_prefix(const std::string& what) {
        std::string m = what;
        if (!m.empty() && m.front() == '[') {
            const auto end = m.find("] ");
            if (end != std::string::npos) m.erase(0, end + 2);
        }
        const std::string line1 = "parse error at line 1, ";
        if (m.compare(0, line1.size(), line1) == 0) m.erase(0, line1.size());
        return m;
    }

    static constexpr std::size_t max_depth = 256;
    // What one value and one object member take, about (a json is 16 bytes; an array element with the
    // vector's growth up to 32; a member is a map node with its key and value).
    static constexpr std::size_t value_cost = 32;
    static constexpr std::size_t member_cost = 96;

    json& root_;
    std::size_t budget_;
    std::size_t used_ = 0;
    std::vector<Frame> stack_;
    std::string error_;
    std::size_t error_position_ = 0;
    std::string id_text_;
};

// Empties `v` bottom-up without allocating. nlohmann::json's destructor flattens a container's
// children into a std::vector first, which can fail (and terminate, from a destructor) when memory
// has just run out; destroying the emptied containers allocates nothing. Recursion depth is bounded
// by DomBuilder's max_depth.
void dismantle(json& v) noexcept {
    if (v.is_array()) {
        auto& a = v.get_ref<json::array_t&>();
        while (!a.empty()) {
            dismantle(a.back());
            a.pop_back();
        }
    } else if (v.is_object()) {
        auto& o = v.get_ref<json::object_t&>();
        for (auto it = o.begin(); it != o.end(); it = o.erase(it)) dismantle(it->second);
    }
}

struct DismantleOnExit {
    json& v;
    explicit DismantleOnExit(json& value) : v(value) {}
    DismantleOnExit(const DismantleOnExit&) = delete;
    DismantleOnExit& operator=(const DismantleOnExit&) = delete;
    ~DismantleOnExit() { dismantle(v); }
};

// Serialises a string as a JSON string; invalid UTF-8 (possible in echoed input) becomes U+FFFD.
std::string json_string(const std::string& s) {
    return json(s).dump(-1, ' ', false, json::error_handler_t::replace);
}

// Restricted Damerau–Levenshtein distance (insertions, deletions, substitutions, transpositions of
// neighbours) between `a` and `b`.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> prev2(b.size() + 1), prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) cur[j] = std::min(cur[j], prev2[j - 2] + 1);
        }
        std::swap(prev2, prev);
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string ascii_lower(std::string_view s) {
    std::string r(s);
    for (char& c : r)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return r;
}

// The accepted key an unknown one most likely meant: within 1 edit (2 for keys of 5 letters or more),
// ignoring case; else an accepted key of 3 letters or more that it contains ("half_height" holds
// "height"); else none.
std::string_view likely_key(std::string_view key, std::initializer_list<std::string_view> accepted) {
    if (key.size() > 64) return {};
    const std::string k = ascii_lower(key);
    std::string_view best;
    std::size_t best_distance = k.size() <= 4 ? 2 : 3;  // more than that is no match
    for (std::string_view a : accepted)
        if (const std::size_t d = edit_distance(k, a); d < best_distance) best = a, best_distance = d;
    if (!best.empty()) return best;
    for (std::string_view a : accepted)
        if (a.size() >= 3 && k.find(a) != std::string::npos && a.size() > best.size()) best = a;
    return best;
}

// "" when every key of the object `obj` is one of `accepted`, else "<field>.<key>: unknown key; did you
// mean ...? (accepted: ...)" for the first unknown one (in alphabetical order). `field` is the
// object's name ("cylinder"), empty for the line's top level.
std::string check_keys(const json& obj, const std::string& field, std::initializer_list<std::string_view> accepted) {
    for (const auto& member : obj.get_ref<const json::object_t&>()) {
        const std::string& key = member.first;
        bool known = false;
        for (std::string_view a : accepted) known = known || key == a;
        if (known) continue;
        // A key is any JSON string: a long one is named by its start.
        std::string shown = key.size() > 64 ? key.substr(0, 64) + "..." : key;
        std::string m = field;
        if (!m.empty()) m += '.';
        m += shown;
        m += ": unknown key";
        if (const std::string_view guess = likely_key(key, accepted); !guess.empty()) {
            m += "; did you mean \"" + std::string(guess) + "\"";
            if (guess == "height" && ascii_lower(key).find("half") != std::string::npos)
                m += " (the full height, end to end, not half of it)";
            if (guess == "extents" && ascii_lower(key).find("half") != std::string::npos)
                m += " (half the edge lengths, as you wrote)";
            m += "?";
        }
        m += " (accepted: ";
        bool first = true;
        for (std::string_view a : accepted) {
            m += first ? "" : ", ";
            m += a;
            first = false;
        }
        return m + ")";
    }
    return {};
}

// Structure checks. Each returns "" when fine, else "<field>: <reason>".
std::string read_number(const json& obj, const char* key, const std::string& field, double& out) {
    const auto it = obj.find(key);
    if (it == obj.end()) return field + ": missing";
    if (!it->is_number()) return field + ": expected a number";
    out = it->get<double>();
    return {};
}

bool is_vec3(const json& j) {
    return j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number();
}

Vec3<double> to_vec3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

std::string read_vec3(const json& obj, const char* key, const std::string& field, Vec3<double>& out) {
    const auto it = obj.find(key);
    if (it == obj.end()) return field + ": missing";
    if (!is_vec3(*it)) return field + ": expected an array of 3 numbers";
    out = to_vec3(*it);
    return {};
}

// center/axes/extents, the fields of oriented boxes and parallelepipeds.
template <class Box>
std::string read_frame_box(const json& b, Box& o) {
    if (auto e = read_vec3(b, "center", "box.center", o.center); !e.empty()) return e;
    const auto axes = b.find("axes");
    if (axes == b.end()) return "box.axes: missing";
    if (!axes->is_array() || axes->size() != 3) return "box.axes: expected an array of 3 axes";
    for (std::size_t i = 0; i < 3; ++i) {
        if (!is_vec3((*axes)[i])) return "box.axes[" + std::to_string(i) + "]: expected an array of 3 numbers";
        o.axes[i] = to_vec3((*axes)[i]);
    }
    return read_vec3(b, "extents", "box.extents", o.extents);
}

std::string read_box(const json& root, AnyBox& out) {
    const auto it = root.find("box");
    if (it == root.end()) return "box: missing";
    const json& b = *it;
    if (!b.is_object()) return "box: expected an object";
    if (auto e = check_keys(b, "box", {"kind", "min", "max", "center", "axes", "extents"}); !e.empty()) return e;
    const bool aligned = b.contains("min") || b.contains("max");
    const bool oriented = b.contains("center") || b.contains("axes") || b.contains("extents");
    if (const auto kind = b.find("kind"); kind != b.end()) {
        // An explicit kind: "aligned", "oriented" or "parallelepiped" (any axes, exactly as given).
        const std::string k = kind->is_string() ? kind->get<std::string>() : std::string();
        if (k == "parallelepiped") {
            if (aligned) return "box: a parallelepiped has center/axes/extents, not min/max";
            Parallelepiped<double> p;
            if (auto e = read_frame_box(b, p); !e.empty()) return e;
            out = p;
            return {};
        }
        if (k != "aligned" && k != "oriented")
            return "box.kind: expected \"aligned\", \"oriented\" or \"parallelepiped\"";
        if (k == "aligned" && oriented) return "box: an aligned box has min/max, not center/axes/extents";
        if (k == "oriented" && aligned) return "box: an oriented box has center/axes/extents, not min/max";
        if (k == "aligned" && !aligned) return "box.min: missing";
        if (k == "oriented" && !oriented) return "box.center: missing";
    }
    if (aligned && oriented) return "box: has both min/max and center/axes/extents";
    if (!aligned && !oriented)
        return "box: expected min/max (aligned box) or center/axes/extents (oriented box)";
    if (aligned) {
        AlignedBox<double> a;
        if (auto e = read_vec3(b, "min", "box.min", a.min); !e.empty()) return e;
        if (auto e = read_vec3(b, "max", "box.max", a.max); !e.empty()) return e;
        out = a;
        return {};
    }
    OrientedBox<double> o;
    if (auto e = read_frame_box(b, o); !e.empty()) return e;
    out = o;
    return {};
}

std::string read_cylinder(const json& root, Cylinder<double>& c) {
    const auto it = root.find("cylinder");
    if (it == root.end()) return "cylinder: missing";
    const json& j = *it;
    if (!j.is_object()) return "cylinder: expected an object";
    if (auto e = check_keys(j, "cylinder", {"center", "axis", "radius", "height"}); !e.empty()) return e;
    if (auto e = read_vec3(j, "center", "cylinder.center", c.center); !e.empty()) return e;
    if (auto e = read_vec3(j, "axis", "cylinder.axis", c.axis); !e.empty()) return e;
    if (auto e = read_number(j, "radius", "cylinder.radius", c.radius); !e.empty()) return e;
    if (auto e = read_number(j, "height", "cylinder.height", c.height); !e.empty()) return e;
    return {};
}

template <class U>
Vec3<U> round_vec(const Vec3<double>& v) {
    return {static_cast<U>(v[0]), static_cast<U>(v[1]), static_cast<U>(v[2])};
}
template <class U>
Cylinder<U> round_shape(const Cylinder<double>& c) {
    return {round_vec<U>(c.center), round_vec<U>(c.axis), static_cast<U>(c.radius), static_cast<U>(c.height)};
}
template <class U>
AlignedBox<U> round_shape(const AlignedBox<double>& b) {
    return {round_vec<U>(b.min), round_vec<U>(b.max)};
}
template <class U>
Parallelepiped<U> round_shape(const Parallelepiped<double>& b) {
    return {round_vec<U>(b.center), {round_vec<U>(b.axes[0]), round_vec<U>(b.axes[1]), round_vec<U>(b.axes[2])},
            round_vec<U>(b.extents)};
}
template <class U>
OrientedBox<U> round_shape(const OrientedBox<double>& b) {
    return {round_vec<U>(b.center), {round_vec<U>(b.axes[0]), round_vec<U>(b.axes[1]), round_vec<U>(b.axes[2])},
            round_vec<U>(b.extents)};
}

}  // namespace

ObjectLine parse_object_line(std::string_view text, std::size_t line_number,
                             const std::function<std::string(const json&)>& read_fields) {
    ObjectLine r;
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
        r.error = where + "empty line";
        return r;
    }

    json root;
    // A query takes about 2 KB of DOM; anything else may take 4 bytes per byte of the line.
    DomBuilder builder(root, std::size_t{64} * 1024 + 4 * text.size());
    const DismantleOnExit dismantle_root(root);
    const bool parsed = json::sax_parse(text.begin(), text.end(), &builder);
    // nlohmann's lexer takes a NUL byte for the end of the input: `{...}\0junk` would parse as `{...}`.
    // A NUL byte is never valid JSON text (inside a string it must be written \u0000), so the line is
    // bad, unless the parse failed before reaching it (then that error comes first).
    const std::size_t nul = text.find('\0');
    const bool nul_first = nul != std::string_view::npos && (parsed || builder.error_position() > nul);
    // The id is echoed whenever a valid one was read, even if the line fails later (a scalar enters
    // the DOM whole, so a present id is complete even in a partly parsed line).
    bool id_ok = true;
    if (root.is_object()) {
        if (const auto id = root.find("id"); id != root.end()) {
            if (id->is_string())
                r.id = json_string(id->get_ref<const std::string&>());
            else if (id->is_number())
                r.id = builder.id_text();
            else
                id_ok = false;
        }
    }
    if (nul_first) {
        r.error = where + "invalid JSON: column " + std::to_string(nul + 1) +
                  ": a NUL byte (not allowed in JSON text; inside a string write \\u0000)";
        return r;
    }
    if (!parsed) {
        r.error = where + builder.error();
        return r;
    }
    if (!root.is_object()) {
        r.error = where + "expected a JSON object";
        return r;
    }
    if (!id_ok) {
        r.error = where + "id: expected a string or a number";
        return r;
    }
    if (std::string e = read_fields(root); !e.empty()) r.error = where + e;
    return r;
}

std::string read_cylinder_field(const json& root, Cylinder<double>& out) { return read_cylinder(root, out); }

std::string check_keys_field(const json& obj, const std::string& field, std::initializer_list<std::string_view> accepted) {
    return check_keys(obj, field, accepted);
}

std::string read_vec3_field(const json& obj, const char* key, const std::string& field, Vec3<double>& out) {
    return read_vec3(obj, key, field, out);
}

namespace {

// parse_line and parse_distance_line: the same line without or with "margin".
ParsedLine parse_query_line(std::string_view text, std::size_t line_number, bool margin_allowed) {
    Query q;
    const ObjectLine o = parse_object_line(text, line_number, [&q, margin_allowed](const json& root) -> std::string {
        // Named before any other key: a margin on a distance line is a question for intersect.
        if (!margin_allowed && root.contains("margin"))
            return "margin: not a key of distance lines (the answer is the distance itself; a margin "
                   "belongs to `boxcyl intersect`)";
        if (auto e = margin_allowed ? check_keys(root, "", {"id", "box", "cylinder", "margin"})
                                    : check_keys(root, "", {"id", "box", "cylinder"});
            !e.empty())
            return e;
        if (auto e = read_box(root, q.box); !e.empty()) return e;
        if (auto e = read_cylinder(root, q.cylinder); !e.empty()) return e;
        if (root.contains("margin")) {
            double m = 0;
            if (auto e = read_number(root, "margin", "margin", m); !e.empty()) return e;
            q.margin = m;
        }
        const Validity vb = std::visit([](const auto& b) { return validate(b); }, q.box);
        if (!vb.ok()) {
            // Axes off orthonormal are a valid parallelepiped: say how to ask for one.
            if (std::holds_alternative<OrientedBox<double>>(q.box) && vb.field.rfind("box.axes", 0) == 0 &&
                (vb.reason.find("unit length") != std::string::npos || vb.reason.find("orthogonal") != std::string::npos))
                return vb.message() + "; for axes of any length and angle use \"kind\": \"parallelepiped\"";
            return vb.message();
        }
        if (const Validity vc = validate(q.cylinder); !vc.ok()) return vc.message();
        if (q.margin)
            if (const Validity vm = validate_margin(*q.margin); !vm.ok()) return vm.message();
        return {};
    });
    ParsedLine r;
    r.id = o.id;
    r.error = o.error;
    if (o.error.empty()) r.query = q;
    return r;
}

}  // namespace

ParsedLine parse_line(std::string_view text, std::size_t line_number) { return parse_query_line(text, line_number, true); }

ParsedLine parse_distance_line(std::string_view text, std::size_t line_number) {
    return parse_query_line(text, line_number, false);
}

Validity check_arithmetic(const Query& q, const RunOptions& opt) {
    if (!opt.rounds_to_float) return {};
    Validity v = std::visit([](const auto& b) { return validate(round_shape<float>(b)); }, q.box);
    if (v.ok()) v = validate(round_shape<float>(q.cylinder));
    if (!v.ok()) v.reason += " after rounding to float (--arithmetic float)";
    return v;
}

std::string format_answer(const std::string& id, bool intersect) {
    std::string s = "{";
    if (!id.empty()) s += "\"id\": " + id + ", ";
    s += intersect ? "\"intersect\": true}" : "\"intersect\": false}";
    return s;
}

std::string format_error(const std::string& id, const std::string& message) {
    std::string s = "{";
    if (!id.empty()) s += "\"id\": " + id + ", ";
    s += "\"error\": " + json_string(message) + "}";
    return s;
}

LineRead read_line(std::istream& in, std::string& line, std::size_t max_bytes, std::ostream* flush_if_long,
                   bool* ended_by_newline) {
    line.clear();
    if (ended_by_newline) *ended_by_newline = false;
    // istream::getline into a fixed buffer, chunk by chunk: the bytes beyond max_bytes are read and
    // dropped, never kept (std::getline would grow the string to the whole line).
    std::array<char, std::size_t{64} * 1024> chunk;
    std::size_t length = 0;  // bytes of the line so far, kept or not
    LineRead status = LineRead::line;
    bool flushed = false;
    for (bool first = true;; first = false) {
        in.getline(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const auto got = static_cast<std::size_t>(in.gcount());
        const bool newline = !in.fail() && !in.eof();  // the line ended with its newline (extracted)
        const bool full = in.fail() && !in.eof() && !in.bad();  // the chunk filled up: more follows
        if (in.bad() || (first && got == 0 && in.eof())) return LineRead::end;
        const std::size_t n = newline ? got - 1 : got;  // bytes stored in the chunk
        if (flush_if_long && !flushed && length + n >= risky_line_bytes) {
            flush_if_long->flush();
            flushed = true;
        }
        length += n;
        if (status == LineRead::line) {
            if (length > max_bytes) {
                status = LineRead::too_long;
                std::string().swap(line);
            } else {
                try {
                    line.append(chunk.data(), n);
                } catch (const std::bad_alloc&) {
                    status = LineRead::no_memory;
                    std::string().swap(line);
                }
            }
        }
        if (!full) {  // newline or end of input
            if (ended_by_newline) *ended_by_newline = newline;
            return status;
        }
        in.clear(in.rdstate() & ~std::ios::failbit);
    }
}

std::string unread_line_message(LineRead r, std::size_t line_number, std::size_t max_bytes) {
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (r == LineRead::too_long)
        return where + "line is longer than " + std::to_string(max_bytes) + " bytes (--max-line-bytes)";
    return where + "out of memory reading the line";
}

LineAnswer unread_line_answer(LineRead r, std::size_t line_number, std::size_t max_bytes) {
    return {format_error({}, unread_line_message(r, line_number, max_bytes)), false};
}

namespace {

LineAnswer answer_line_unguarded(std::string_view text, std::size_t line_number, const RunOptions& opt) {
    ParsedLine p = parse_line(text, line_number);
    if (!p.query) return {format_error(p.id, p.error), false};
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (const Validity v = check_arithmetic(*p.query, opt); !v.ok())
        return {format_error(p.id, where + v.message()), false};
    try {
        return {format_answer(p.id, run_query(*p.query, opt.query)), true};
    } catch (const std::exception& e) {
        // Not expected for validated input; reported per line rather than ending the run.
        return {format_error(p.id, where + "query failed: " + e.what()), false};
    }
}

}  // namespace

LineAnswer answer_line(std::string_view text, std::size_t line_number, const RunOptions& opt) {
    try {
        return answer_line_unguarded(text, line_number, opt);
    } catch (const std::bad_alloc&) {
        // The parse of a long line needs ~23 bytes per byte; what it held is freed by now.
        return {format_error({}, "line " + std::to_string(line_number) + ": out of memory answering the line"), false};
    } catch (const std::exception& e) {
        return {format_error({}, "line " + std::to_string(line_number) + ": " + e.what()), false};
    }
}

namespace {

// Consecutive input lines and, once a worker has answered them, their output lines.
struct Block {
    Block() {
        // Reserved up front, so that adding a line (whose text may have taken most of the memory
        // left) never allocates.
        lines.reserve(stream_block_lines);
        status.reserve(stream_block_lines);
    }
    std::size_t first_line = 0;  // the number of lines[0], from 1
    std::vector<std::string> lines;
    std::vector<LineRead> status;  // per line: LineRead::line, or why lines[i] is empty
    std::size_t bytes = 0;
    std::string out;  // one newline-terminated output line per input line
    std::size_t bad = 0;
    bool done = false;                // guarded by the mutex
    std::exception_ptr failure;       // what answering threw (e.g. std::bad_alloc): the run stops
};

// This thread reads and cuts the input into blocks; `threads` workers answer blocks in any order; one
// writer thread writes the answered blocks strictly in input order. Reading, answering and writing
// overlap, and at most 2 * threads blocks exist between reader and writer (memory bound).
StreamCounts process_stream_parallel(std::istream& in, std::ostream& out, std::size_t max_line_bytes, unsigned threads,
                                     const LineAnswerer& answer) {
    const std::size_t max_in_flight = 2 * std::size_t{threads};
    std::mutex m;
    std::condition_variable work_ready;  // workers: a block in `todo`, or the end
    std::condition_variable front_done;  // writer: the oldest block is answered, or the end
    std::condition_variable space;       // reader: fewer than max_in_flight blocks, or a failure
    std::deque<std::unique_ptr<Block>> in_flight;  // input order; owned here until written
    std::deque<Block*> todo;                       // not yet taken by a worker
    bool end_of_input = false;
    std::exception_ptr failure;
    bool write_failed = false;  // `out` went bad: the reader stops, the writer writes no more
    std::size_t bad = 0;  // the writer's

    auto worker = [&] {
        for (;;) {
            Block* b = nullptr;
            {
                std::unique_lock lk(m);
                work_ready.wait(lk, [&] { return !todo.empty() || end_of_input; });
                if (todo.empty()) return;
                b = todo.front();
                todo.pop_front();
            }
            try {
                for (std::size_t i = 0; i < b->lines.size(); ++i) {
                    const std::size_t n = b->first_line + i;
                    const LineAnswer a = b->status[i] == LineRead::line
                                             ? answer(b->lines[i], n)
                                             : unread_line_answer(b->status[i], n, max_line_bytes);
                    b->out += a.text;
                    b->out += '\n';
                    if (!a.good) ++b->bad;
                }
            } catch (...) {
                b->failure = std::current_exception();
            }
            b->lines = {};  // the input is no longer needed
            b->status = {};
            {
                std::lock_guard lk(m);
                b->done = true;
            }
            front_done.notify_one();
        }
    };

    auto writer = [&] {
        const auto ready = [&] {
            return (!in_flight.empty() && in_flight.front()->done) || (end_of_input && in_flight.empty());
        };
        for (;;) {
            std::unique_ptr<Block> b;
            {
                std::unique_lock lk(m);
                if (!ready()) {
                    // Nothing more to write yet: an interactive caller sees everything answered so far.
                    lk.unlock();
                    out.flush();
                    lk.lock();
                    if (!out) write_failed = true;
                    front_done.wait(lk, ready);
                }
                if (in_flight.empty()) return;
                b = std::move(in_flight.front());
                in_flight.pop_front();
                if (b->failure && !failure) failure = b->failure;
            }
            space.notify_one();
            if (failure || write_failed) continue;  // written so far: a prefix of the output
            out.write(b->out.data(), static_cast<std::streamsize>(b->out.size()));
            bad += b->bad;
            if (!out) {
                std::lock_guard lk(m);
                write_failed = true;
            }
        }
    };

    // Hands `b` to the workers once there is room; false when the run must stop.
    const auto dispatch = [&](std::unique_ptr<Block>& b) {
        std::unique_lock lk(m);
        space.wait(lk, [&] { return in_flight.size() < max_in_flight || failure || write_failed; });
        if (failure || write_failed) return false;
        todo.push_back(b.get());
        in_flight.push_back(std::move(b));
        b = std::make_unique<Block>();
        lk.unlock();
        work_ready.notify_one();
        return true;
    };

    // A tied stream would be flushed by this thread's reads while the writer writes to it.
    std::ostream* const tied = in.tie(nullptr);
    std::vector<std::thread> pool;
    std::thread writing;
    const auto finish = [&] {
        {
            std::lock_guard lk(m);
            end_of_input = true;
        }
        work_ready.notify_all();
        front_done.notify_all();
        for (std::thread& t : pool) t.join();
        if (writing.joinable()) writing.join();
        in.tie(tied);
    };
    std::size_t line_number = 0;
    try {
        try {
            pool.reserve(threads);
            for (unsigned i = 0; i < threads; ++i) pool.emplace_back(worker);
            writing = std::thread(writer);
        } catch (const std::system_error& e) {
            throw ThreadsUnavailable("cannot start the threads of --threads " + std::to_string(threads) + ": " +
                                     e.what());
        }
        auto block = std::make_unique<Block>();
        std::string line;
        // A read that waits in the middle of a line hands over the lines before it first.
        std::exception_ptr hook_failure;
        const BeforeWait hand_over(in, [&] {
            try {
                if (!block->lines.empty()) dispatch(block);
            } catch (...) {
                hook_failure = std::current_exception();
            }
        });
        for (;;) {
            // Hand over a partial block before a read could block: an interactive caller waits for it.
            if (!block->lines.empty() && (in.rdbuf() == nullptr || in.rdbuf()->in_avail() <= 0) && !dispatch(block))
                break;
            // A stop signal: the lines read in full are answered (the partial block too), no more are read.
            if (stop_signal() != 0) {
                if (!block->lines.empty()) dispatch(block);
                break;
            }
            bool newline = false;
            const LineRead r = read_line(in, line, max_line_bytes, nullptr, &newline);
            if (hook_failure) std::rethrow_exception(hook_failure);
            if (r == LineRead::end || (!newline && stop_signal() != 0)) {
                if (!block->lines.empty()) dispatch(block);
                break;
            }
            // A long line (or one not kept) gets a block of its own: the lines before it are answered
            // and written whatever happens to it.
            if (r != LineRead::line || line.size() >= risky_line_bytes)
                if (!block->lines.empty() && !dispatch(block)) break;
            if (block->lines.empty()) block->first_line = line_number + 1;
            ++line_number;
            block->bytes += line.size();
            block->lines.push_back(std::move(line));  // no allocation: the block reserved its lines
            block->status.push_back(r);
            line = std::string();
            if ((block->lines.size() >= stream_block_lines || block->bytes >= stream_block_bytes) && !dispatch(block))
                break;
        }
    } catch (...) {
        finish();
        throw;
    }
    finish();
    out.flush();
    if (failure) std::rethrow_exception(failure);
    return {line_number, bad};
}

}  // namespace

StreamCounts answer_lines(std::istream& in, std::ostream& out, std::size_t max_line_bytes, unsigned threads,
                          const LineAnswerer& answer) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    return threads == 1 ? process_lines(in, out, max_line_bytes, answer)
                        : process_stream_parallel(in, out, max_line_bytes, threads, answer);
}

StreamCounts answer_stream(std::istream& in, std::ostream& out, const RunOptions& opt, unsigned threads) {
    return answer_lines(in, out, opt.max_line_bytes, threads,
                        [&opt](std::string_view line, std::size_t n) { return answer_line(line, n, opt); });
}

}  // namespace boxcyl::cli
