#include "simcore/io/json_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace simcore::io_detail {

namespace {

// Builds the DOM from nlohmann's SAX events. We parse through SAX rather than json::parse because
// only the SAX interface reports the byte position of *every* error, including "number overflow"
// (1e999), which json::parse throws as an out_of_range exception with no position at all. It also
// lets us see duplicate keys, which the DOM parser silently collapses.
class DomBuilder {
public:
    using number_integer_t = Json::number_integer_t;
    using number_unsigned_t = Json::number_unsigned_t;
    using number_float_t = Json::number_float_t;
    using string_t = Json::string_t;
    using binary_t = Json::binary_t;

    DomBuilder(std::string_view text, const std::string& file, std::vector<Diagnostic>& out)
        : text_(text), file_(file), out_(out) {}

    bool null() { return insert(nullptr); }
    bool boolean(bool v) { return insert(v); }
    bool number_integer(number_integer_t v) { return insert(v); }
    bool number_unsigned(number_unsigned_t v) { return insert(v); }
    bool number_float(number_float_t v, const string_t&) { return insert(v); }
    bool string(string_t& v) {
        if (v.size() > kMaxStringBytes)
            return limitExceeded(nextPath(), "a string of " + std::to_string(v.size()) + " bytes is longer than the limit of " +
                                                 std::to_string(kMaxStringBytes) + " bytes");
        return insert(std::move(v));
    }
    bool binary(binary_t& v) { return insert(Json::binary(static_cast<const binary_t::container_type&>(v))); }

    bool start_object(std::size_t) { return open(Json::object()); }
    bool start_array(std::size_t) { return open(Json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(string_t& k) {
        if (k.size() > kMaxStringBytes)
            return limitExceeded(currentPath(), "a key of " + std::to_string(k.size()) + " bytes is longer than the limit of " +
                                                    std::to_string(kMaxStringBytes) + " bytes");
        if (stack_.back()->contains(k)) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Warning;
            d.file = file_;
            d.path = childPath(currentPath(), k);
            d.message = "duplicate key '" + k + "'; only its last value is used";
            if (out_.size() < kMaxDiagnostics) out_.push_back(std::move(d));
        }
        key_ = std::move(k);
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const nlohmann::detail::exception& ex) {
        std::size_t offset = position > 0 ? position - 1 : 0;  // 0-based index of the offending byte
        std::string message;
        if (ex.id == 406) {
            // Number overflow: the lexer has read the whole number; point at its first character.
            offset = position >= lastToken.size() ? position - lastToken.size() : 0;
            message = "number " + lastToken + " is too large (JSON numbers must be finite)";
        } else if (std::all_of(text_.begin(), text_.end(), [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; })) {
            // Not a position problem: report it for the whole file.
            Diagnostic d;
            d.file = file_;
            d.message = "the file is empty";
            out_.push_back(std::move(d));
            failed_ = true;
            return false;
        } else {
            message = cleanMessage(ex.what());
        }
        offset = std::min(offset, text_.size());
        const std::string_view before = text_.substr(0, offset);
        const std::size_t lastNewline = before.rfind('\n');
        Diagnostic d;
        d.file = file_;
        d.line = 1 + static_cast<int>(std::count(before.begin(), before.end(), '\n'));
        d.column = 1 + static_cast<int>(lastNewline == std::string_view::npos ? offset : offset - lastNewline - 1);
        d.message = std::move(message);
        out_.push_back(std::move(d));
        failed_ = true;
        return false;
    }

    bool failed() const { return failed_; }
    Json& root() { return root_; }

private:
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line 1, column 5: syntax
    // error while parsing ..."; we report our own position, so keep only the explanation.
    static std::string cleanMessage(std::string_view what) {
        if (what.starts_with("[json.exception.")) {
            const std::size_t close = what.find("] ");
            if (close != std::string_view::npos) what.remove_prefix(close + 2);
        }
        if (what.starts_with("parse error")) {
            const std::size_t colon = what.find(": ");
            if (colon != std::string_view::npos) what.remove_prefix(colon + 2);
        }
        return std::string(what);
    }

    std::string currentPath() const {
        std::string path;
        for (std::size_t i = 1; i < segments_.size(); ++i) path += segments_[i];
        return path;
    }

    // Refuses the document for exceeding one of the parse-time limits (see json_reader.h): an error
    // at `path`, and parsing stops.
    bool limitExceeded(const std::string& path, std::string message) {
        Diagnostic d;
        d.file = file_;
        d.path = path;
        d.message = std::move(message);
        out_.push_back(std::move(d));
        failed_ = true;
        return false;
    }

    // The pointer of the value about to be placed.
    std::string nextPath() const {
        if (stack_.empty()) return {};
        const Json& parent = *stack_.back();
        return parent.is_array() ? childPath(currentPath(), parent.size()) : childPath(currentPath(), key_);
    }

    // Counts a value about to be placed against the size limits.
    bool admit() {
        if (++values_ > kMaxJsonValues)
            return limitExceeded({}, "the document has more than " + std::to_string(kMaxJsonValues) +
                                         " values (numbers, strings, arrays, objects); that is beyond any scene this "
                                         "program accepts");
        if (!stack_.empty() && stack_.back()->is_array() && stack_.back()->size() >= kMaxArrayElements) {
            const std::string path = currentPath();
            std::string message = "the array has more than " + std::to_string(kMaxArrayElements) + " elements";
            if (path == "/bodies" || path == "/objects")
                message += "; a scene may have at most " + std::to_string(limits::kMaxBodies) + " bodies";
            return limitExceeded(path, std::move(message));
        }
        return true;
    }

    // Places a value in the current container and returns it (or the root).
    Json* place(Json&& value, std::string& segment) {
        if (stack_.empty()) {
            root_ = std::move(value);
            return &root_;
        }
        Json& parent = *stack_.back();
        if (parent.is_array()) {
            segment = childPath({}, parent.size());
            parent.push_back(std::move(value));
            return &parent.back();
        }
        segment = childPath({}, key_);
        Json& slot = parent[key_];
        slot = std::move(value);
        return &slot;
    }

    bool insert(Json&& value) {
        if (!admit()) return false;
        std::string segment;
        place(std::move(value), segment);
        return true;
    }

    bool open(Json&& container) {
        if (static_cast<int>(stack_.size()) >= kMaxNestingDepth) {
            Diagnostic d;
            d.file = file_;
            d.message = "the document is nested more than " + std::to_string(kMaxNestingDepth) + " levels deep";
            out_.push_back(std::move(d));
            failed_ = true;
            return false;
        }
        if (!admit()) return false;
        std::string segment;
        stack_.push_back(place(std::move(container), segment));
        segments_.push_back(std::move(segment));
        return true;
    }

    bool close() {
        stack_.pop_back();
        segments_.pop_back();
        return true;
    }

    std::string_view text_;
    const std::string& file_;
    std::vector<Diagnostic>& out_;
    Json root_;
    std::vector<Json*> stack_;
    std::vector<std::string> segments_;  // segments_[i]: the pointer segment of stack_[i] in its parent
    std::string key_;
    std::size_t values_ = 0;
    bool failed_ = false;
};

// "radius", or "halfExtents[1]" for an array element, from the last segments of a pointer.
std::string labelFromPath(const std::string& path) {
    auto unescape = [](std::string_view s) {
        std::string r;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (s[i] == '~' && i + 1 < s.size()) {
                r += s[i + 1] == '1' ? '/' : '~';
                ++i;
            } else {
                r += s[i];
            }
        }
        return r;
    };
    const std::size_t last = path.rfind('/');
    if (last == std::string::npos) return "value";
    const std::string_view tail = std::string_view(path).substr(last + 1);
    const bool isIndex = !tail.empty() && std::all_of(tail.begin(), tail.end(), [](char c) { return c >= '0' && c <= '9'; });
    const bool isAxis = tail == "x" || tail == "y" || tail == "z";  // thesis vectors: say "scale.y"
    if ((isIndex || isAxis) && last > 0) {
        std::size_t end = last;
        std::size_t previous = path.rfind('/', end - 1);
        std::string_view parent = std::string_view(path).substr(previous + 1, end - previous - 1);
        std::string suffix = isIndex ? "[" + std::string(tail) + "]" : "." + std::string(tail);
        // Nested indices, as in hull points: "points[3][2]", not "3[2]".
        while (previous != std::string::npos && previous > 0 && !parent.empty() &&
               std::all_of(parent.begin(), parent.end(), [](char c) { return c >= '0' && c <= '9'; })) {
            suffix = "[" + std::string(parent) + "]" + suffix;
            end = previous;
            previous = path.rfind('/', end - 1);
            parent = std::string_view(path).substr(previous + 1, end - previous - 1);
        }
        return unescape(parent) + suffix;
    }
    return unescape(tail);
}

}  // namespace

std::optional<Json> parseJson(std::string_view text, const std::string& file, std::vector<Diagnostic>& out) {
    if (text.size() > kMaxTextBytes) {
        Diagnostic d;
        d.file = file;
        d.message = "the file is larger than " + std::to_string(kMaxTextBytes >> 20) + " MiB; it is not a scene";
        out.push_back(std::move(d));
        return std::nullopt;
    }
    DomBuilder builder(text, file, out);
    const bool ok = Json::sax_parse(text.begin(), text.end(), &builder, nlohmann::detail::input_format_t::json,
                                    /*strict=*/true, /*ignore_comments=*/false);
    if (!ok || builder.failed()) return std::nullopt;
    return std::move(builder.root());
}

std::string childPath(const std::string& parent, std::string_view key) {
    std::string path = parent;
    path += '/';
    for (char c : key) {
        if (c == '~') path += "~0";
        else if (c == '/') path += "~1";
        else path += c;
    }
    return path;
}

std::string childPath(const std::string& parent, std::size_t index) { return parent + "/" + std::to_string(index); }

std::string typeName(const Json& value) {
    switch (value.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::object: return "an object";
        case Json::value_t::array: return "an array";
        case Json::value_t::string: return "a string";
        case Json::value_t::boolean: return "a boolean";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float: return "a number";
        default: return "an unsupported value";
    }
}

// ---- Reader ----

void Reader::add(Diagnostic::Severity severity, const std::string& path, std::string message) {
    if (severity == Diagnostic::Severity::Error) ++errors_;
    if (kept_ >= kMaxDiagnostics) {
        ++(severity == Diagnostic::Severity::Error ? suppressedErrors_ : suppressedWarnings_);
        return;
    }
    ++kept_;
    Diagnostic d;
    d.severity = severity;
    d.file = file_;
    d.path = path;
    d.message = std::move(message);
    out_.push_back(std::move(d));
}

void Reader::error(const std::string& path, std::string message) {
    add(Diagnostic::Severity::Error, path, std::move(message));
}

void Reader::warning(const std::string& path, std::string message) {
    add(Diagnostic::Severity::Warning, path, std::move(message));
}

void Reader::finish() {
    if (finished_) return;
    finished_ = true;
    const int suppressed = suppressedErrors_ + suppressedWarnings_;
    if (suppressed == 0) return;
    Diagnostic d;
    d.severity = suppressedErrors_ > 0 ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning;
    d.file = file_;
    d.message = std::to_string(suppressed) + " more problem" + (suppressed == 1 ? "" : "s") + " not shown (" +
                std::to_string(suppressedErrors_) + " errors, " + std::to_string(suppressedWarnings_) + " warnings)";
    out_.push_back(std::move(d));
}

bool Reader::expectObject(const Json& value, const std::string& path) {
    if (value.is_object()) return true;
    error(path, "expected an object, got " + typeName(value));
    return false;
}

bool Reader::expectArray(const Json& value, const std::string& path) {
    if (value.is_array()) return true;
    error(path, "expected an array, got " + typeName(value));
    return false;
}

const Json* Reader::find(const Json& object, std::string_view key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const Json* Reader::require(const Json& object, const std::string& path, std::string_view key) {
    if (const Json* value = find(object, key)) return value;
    error(childPath(path, key), "required key '" + std::string(key) + "' is missing");
    return nullptr;
}

void Reader::checkKeys(const Json& object, const std::string& path, std::initializer_list<std::string_view> known,
                       std::string_view context) {
    checkKeys(object, path, std::vector<std::string_view>(known), context);
}

void Reader::checkKeys(const Json& object, const std::string& path, const std::vector<std::string_view>& known,
                       std::string_view context) {
    for (const auto& item : object.items()) {
        if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
        std::string message = "unknown key '" + item.key() + "'";
        if (!context.empty()) message += " " + std::string(context);
        message += " (ignored)";
        warning(childPath(path, item.key()), std::move(message));
    }
}

bool Reader::checkRange(double value, const std::string& path, const Range& range) {
    if (auto problem = rangeProblem(labelFromPath(path), value, range)) {
        error(path, std::move(*problem));
        return false;
    }
    return true;
}

std::optional<float> Reader::readFloat(const Json& value, const std::string& path, const Range& range) {
    if (!value.is_number()) {
        error(path, "expected a number, got " + typeName(value));
        return std::nullopt;
    }
    const double d = value.get<double>();
    // The range check happens on the double, before narrowing: every range lies well inside float's,
    // so the cast below can neither overflow nor silently turn a huge value into infinity.
    if (!checkRange(d, path, range)) return std::nullopt;
    return static_cast<float>(d);
}

std::optional<int> Reader::readInt(const Json& value, const std::string& path, int min, int max) {
    if (!value.is_number()) {
        error(path, "expected an integer, got " + typeName(value));
        return std::nullopt;
    }
    const double d = value.get<double>();
    // 8.0 is accepted as 8: JSON has one number type and some writers always add a fraction.
    if (!value.is_number_integer() && d != std::floor(d)) {
        error(path, "expected an integer, got " + formatNumber(d));
        return std::nullopt;
    }
    if (auto problem = integerRangeProblem(labelFromPath(path), d, {static_cast<double>(min), static_cast<double>(max)})) {
        error(path, std::move(*problem));
        return std::nullopt;
    }
    return static_cast<int>(d);
}

std::optional<bool> Reader::readBool(const Json& value, const std::string& path) {
    if (!value.is_boolean()) {
        error(path, "expected true or false, got " + typeName(value));
        return std::nullopt;
    }
    return value.get<bool>();
}

std::optional<std::string> Reader::readString(const Json& value, const std::string& path) {
    if (!value.is_string()) {
        error(path, "expected a string, got " + typeName(value));
        return std::nullopt;
    }
    return value.get<std::string>();
}

std::optional<Vec3> Reader::readVec3(const Json& value, const std::string& path, const Range& range) {
    if (!value.is_array()) {
        error(path, "expected an array of 3 numbers, got " + typeName(value));
        return std::nullopt;
    }
    if (value.size() != 3) {
        error(path, "expected 3 numbers, got " + std::to_string(value.size()));
        return std::nullopt;
    }
    Vec3 v{0.0f};
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
        if (auto c = readFloat(value[static_cast<std::size_t>(i)], childPath(path, static_cast<std::size_t>(i)), range))
            v[i] = *c;
        else
            ok = false;
    }
    if (!ok) return std::nullopt;
    return v;
}

std::optional<Vec3> Reader::readXyz(const Json& value, const std::string& path, const Range& range) {
    if (!value.is_object()) {
        error(path, "expected an object {\"x\", \"y\", \"z\"}, got " + typeName(value));
        return std::nullopt;
    }
    checkKeys(value, path, {"x", "y", "z"});
    Vec3 v{0.0f};
    bool ok = true;
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
        const Json* c = require(value, path, names[i]);
        std::optional<float> f;
        if (c) f = readFloat(*c, childPath(path, names[i]), range);
        if (f) v[i] = *f;
        else ok = false;
    }
    if (!ok) return std::nullopt;
    return v;
}

bool Reader::optionalFloat(const Json& object, const std::string& path, std::string_view key, const Range& range,
                           float& target) {
    const Json* value = find(object, key);
    if (!value) return true;
    const auto f = readFloat(*value, childPath(path, key), range);
    if (f) target = *f;
    return f.has_value();
}

bool Reader::optionalInt(const Json& object, const std::string& path, std::string_view key, int min, int max,
                         int& target) {
    const Json* value = find(object, key);
    if (!value) return true;
    const auto i = readInt(*value, childPath(path, key), min, max);
    if (i) target = *i;
    return i.has_value();
}

bool Reader::optionalBool(const Json& object, const std::string& path, std::string_view key, bool& target) {
    const Json* value = find(object, key);
    if (!value) return true;
    const auto b = readBool(*value, childPath(path, key));
    if (b) target = *b;
    return b.has_value();
}

bool Reader::optionalVec3(const Json& object, const std::string& path, std::string_view key, const Range& range,
                          Vec3& target) {
    const Json* value = find(object, key);
    if (!value) return true;
    const auto v = readVec3(*value, childPath(path, key), range);
    if (v) target = *v;
    return v.has_value();
}

// ---- shared shape and rotation checks ----

std::optional<Quat> normalisedOrientation(Reader& reader, const Quat& q, const std::string& path) {
    if (!isFinite(q)) {
        reader.error(path, "orientation must be finite");
        return std::nullopt;
    }
    // In double: components up to the coordinate limit would overflow float when squared.
    const double length = std::sqrt(double(q.w) * q.w + double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z);
    if (!(length > 1e-6)) {
        reader.error(path, "orientation cannot be normalised: the quaternion has zero length");
        return std::nullopt;
    }
    // Within float rounding of unit length the value is kept bit for bit, so saving and reloading a
    // scene never drifts; a visibly non-unit quaternion is normalised and, if far off, reported.
    if (std::abs(length - 1.0) <= 1e-5) return q;
    if (std::abs(length - 1.0) > 1e-3)
        reader.warning(path, "orientation is not a unit quaternion (length " + formatNumber(length) + "); it was normalised");
    const double inv = 1.0 / length;
    return Quat(static_cast<float>(q.w * inv), static_cast<float>(q.x * inv), static_cast<float>(q.y * inv),
                static_cast<float>(q.z * inv));
}

namespace {

// Eigenvalues of a symmetric 3x3 matrix, smallest first (the closed form by the trigonometric
// method, in double; exact enough to compare against a limit spanning orders of magnitude).
std::array<double, 3> symmetricEigenvalues(const Mat3& m) {
    const double a00 = m[0][0], a11 = m[1][1], a22 = m[2][2];
    const double a01 = 0.5 * (double(m[0][1]) + m[1][0]), a02 = 0.5 * (double(m[0][2]) + m[2][0]),
                 a12 = 0.5 * (double(m[1][2]) + m[2][1]);
    const double offDiagonal = a01 * a01 + a02 * a02 + a12 * a12;
    std::array<double, 3> e{a00, a11, a22};
    if (offDiagonal > 0.0) {
        const double q = (a00 + a11 + a22) / 3.0;
        const double b00 = a00 - q, b11 = a11 - q, b22 = a22 - q;
        const double p = std::sqrt((b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * offDiagonal) / 6.0);
        const double det = b00 * (b11 * b22 - a12 * a12) - a01 * (a01 * b22 - a12 * a02) + a02 * (a01 * a12 - b11 * a02);
        const double r = std::clamp(det / (2.0 * p * p * p), -1.0, 1.0);
        const double phi = std::acos(r) / 3.0;
        const double third = 2.0943951023931954923;  // 2 pi / 3
        e[0] = q + 2.0 * p * std::cos(phi);
        e[2] = q + 2.0 * p * std::cos(phi + third);
        e[1] = 3.0 * q - e[0] - e[2];
    }
    std::sort(e.begin(), e.end());
    return e;
}

}  // namespace

// Four significant digits (8e-09, 4.189e+21): for derived values, which no one typed in.
std::string approx(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", value);
    return buffer;
}

bool checkMassProperties(Reader& reader, const BodyCreationSettings& body, const std::string& path) {
    if (body.motion != MotionType::Dynamic) return true;
    const MassProperties props = body.mass ? massPropertiesForMass(body.shape, *body.mass)
                                           : massProperties(body.shape, body.density);
    if (!body.mass) {
        const double mass = double(body.density) * double(volume(body.shape));
        if (!(mass >= limits::kMass.min && mass <= limits::kMass.max)) {
            reader.error(path, "density " + formatNumber(body.density) + " " + std::string(limits::kDensity.unit) + " gives this " +
                                   std::string(shapeTypeName(body.shape.type)) + " a mass of " + approx(mass) +
                                   " kg; the mass must be between " + formatNumber(limits::kMass.min) + " and " +
                                   formatNumber(limits::kMass.max) + " kg (give another density, or a mass)");
            return false;
        }
    }
    const double smallest = symmetricEigenvalues(props.inertia)[0];
    if (!(smallest >= limits::kMinMomentOfInertia)) {
        reader.error(path, "the smallest moment of inertia of this body, " + approx(smallest) + " kg m^2 (from its mass " +
                               approx(props.mass) + " kg and its shape), is below " +
                               formatNumber(limits::kMinMomentOfInertia) +
                               " kg m^2: its inverse is beyond float arithmetic (make it larger or heavier)");
        return false;
    }
    return true;
}

std::optional<Shape> hullShape(Reader& reader, const std::vector<Vec3>& points, const std::string& path) {
    if (points.size() < 4) {
        reader.error(path, "a convex hull needs at least 4 points, got " + std::to_string(points.size()));
        return std::nullopt;
    }
    if (points.size() > limits::kMaxHullPoints) {
        reader.error(path, "a convex hull may have at most " + std::to_string(limits::kMaxHullPoints) +
                               " points, got " + std::to_string(points.size()));
        return std::nullopt;
    }
    ConvexHull::BuildResult built = ConvexHull::build(points);
    if (!built.hull) {
        reader.error(path, "cannot build a convex hull: " +
                               (built.error.empty() ? std::string("the points enclose no volume") : built.error));
        return std::nullopt;
    }
    return Shape::convexHull(std::move(built.hull));
}

}  // namespace simcore::io_detail
