#pragma once
// Internal to simcore/io (not part of the public API): JSON text to a DOM with exact syntax-error
// positions, and a validating Reader that turns every problem into a Diagnostic with a JSON
// pointer, so the v1 loader and the thesis importer report problems the same way.

#include "simcore/io/scene_io.h"
#include "simcore/math/math.h"
#include "simcore/settings_schema.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace simcore::io_detail {

using Json = nlohmann::json;

// At most this many diagnostics are kept; one more line summarises the rest. A hostile file with a
// million bad entries still gets a readable answer, quickly.
constexpr std::size_t kMaxDiagnostics = 100;

// Deeper nesting than this is refused: no scene needs it, and it bounds memory and time.
constexpr int kMaxNestingDepth = 64;

// Limits enforced while the text is parsed, before any of it is interpreted, so that memory stays
// bounded whatever the file holds (the text itself is limited to kMaxTextBytes):
//  - a string (value or key) longer than kMaxStringBytes is refused: names and keys are short,
//    and every message that quotes a string stays readable;
//  - an array of more than kMaxArrayElements elements is refused (the body limit: no other array
//    of a scene comes near it);
//  - a document of more than kMaxJsonValues values (numbers, strings, objects, ... counted one
//    each) is refused: enough for kMaxArrayElements fully written bodies, and it caps the parsed
//    document at a few hundred MB.
constexpr std::size_t kMaxTextBytes = kMaxSceneFileBytes;
constexpr std::size_t kMaxStringBytes = 4096;
constexpr std::size_t kMaxArrayElements = 100000;
constexpr std::size_t kMaxJsonValues = 4000000;

// Parses `text` as strict JSON (no comments, no NaN/Infinity). Syntax errors become an error with
// 1-based line and byte column; duplicate object keys become warnings (the last value is used, as
// in most JSON readers, but the loss is reported). Returns nothing on a syntax error.
std::optional<Json> parseJson(std::string_view text, const std::string& file, std::vector<Diagnostic>& out);

// JSON pointer building (RFC 6901 escaping of '~' and '/').
std::string childPath(const std::string& parent, std::string_view key);
std::string childPath(const std::string& parent, std::size_t index);

// "an object", "a number", ... for "expected X, got Y" messages.
std::string typeName(const Json& value);

using simcore::formatNumber;

// Accepted range of a number (settings_schema.h); its unit is shown in messages.
using Range = NumberRange;

class Reader {
public:
    // Diagnostics already in `out` (e.g. duplicate-key warnings) count towards the cap.
    Reader(std::string file, std::vector<Diagnostic>& out) : file_(std::move(file)), out_(out), kept_(out.size()) {}
    Reader(const Reader&) = delete;
    Reader& operator=(const Reader&) = delete;

    void error(const std::string& path, std::string message);
    void warning(const std::string& path, std::string message);

    int errorCount() const { return errors_; }
    // True once enough errors were found that looking further is pointless.
    bool full() const { return errors_ >= static_cast<int>(kMaxDiagnostics); }
    // Appends one line summarising suppressed diagnostics, if any. Call once, when done.
    void finish();

    const std::string& file() const { return file_; }

    // Object helpers. `find` returns null when the key is absent; `require` also reports it.
    bool expectObject(const Json& value, const std::string& path);
    bool expectArray(const Json& value, const std::string& path);
    static const Json* find(const Json& object, std::string_view key);
    const Json* require(const Json& object, const std::string& path, std::string_view key);
    // Warns about every key of `object` not in `known` ("unknown key 'foo' (ignored)").
    void checkKeys(const Json& object, const std::string& path, std::initializer_list<std::string_view> known,
                   std::string_view context = {});
    void checkKeys(const Json& object, const std::string& path, const std::vector<std::string_view>& known,
                   std::string_view context = {});

    // Typed reads. On failure the problem is reported at `path` and nothing is returned.
    std::optional<float> readFloat(const Json& value, const std::string& path, const Range& range);
    std::optional<int> readInt(const Json& value, const std::string& path, int min, int max);
    std::optional<bool> readBool(const Json& value, const std::string& path);
    std::optional<std::string> readString(const Json& value, const std::string& path);
    // [x, y, z] with every component in `range`.
    std::optional<Vec3> readVec3(const Json& value, const std::string& path, const Range& range);
    // {"x": .., "y": .., "z": ..} (the thesis app's vectors); missing components are errors.
    std::optional<Vec3> readXyz(const Json& value, const std::string& path, const Range& range);

    // Range check of an already computed value, reported at `path`.
    bool checkRange(double value, const std::string& path, const Range& range);

    // Convenience for optional keys: when `key` is present in `object`, reads it into `target`.
    // Returns false only when the key is present and invalid.
    bool optionalFloat(const Json& object, const std::string& path, std::string_view key, const Range& range,
                       float& target);
    bool optionalInt(const Json& object, const std::string& path, std::string_view key, int min, int max,
                     int& target);
    bool optionalBool(const Json& object, const std::string& path, std::string_view key, bool& target);
    bool optionalVec3(const Json& object, const std::string& path, std::string_view key, const Range& range,
                      Vec3& target);

private:
    void add(Diagnostic::Severity severity, const std::string& path, std::string message);

    std::string file_;
    std::vector<Diagnostic>& out_;
    std::size_t kept_ = 0;
    int errors_ = 0;
    int suppressedErrors_ = 0;
    int suppressedWarnings_ = 0;
    bool finished_ = false;
};

// Limits of the loader beyond the schema's (settings_schema.h has the ranges of values).
namespace limits {
using namespace simcore::limits;
inline constexpr std::size_t kMaxBodies = kMaxArrayElements;
// Smallest principal moment of inertia of a dynamic body, from its shape and mass: its inverse must
// stay far inside float range. The engine inverts the tensor in double and solves the gyroscopic
// term on a normalised tensor, so the smallest bodies the mass and size limits allow (about 4e-15
// kg m^2) simulate; this only guards a hull thinner than any the hull builder accepts. (No upper
// limit is needed: the mass and size limits keep every moment below 7e18.)
inline constexpr double kMinMomentOfInertia = 1e-30;  // kg m^2
}  // namespace limits

// Quaternion from the JSON orientation value; reported at `path` when it cannot be normalised.
// Shared so thesis import and v1 agree on what a usable rotation is.
std::optional<Quat> normalisedOrientation(Reader& reader, const Quat& q, const std::string& path);

// What a dynamic body's mass and shape come to, which no single value in the file shows: the mass
// a density gives (density x volume, against limits::kMass) and the smallest principal moment of
// inertia (against limits::kMinMomentOfInertia). Reported at `path` (the body); returns false when refused. Static
// and kinematic bodies have no mass in the simulation and always pass.
bool checkMassProperties(Reader& reader, const BodyCreationSettings& body, const std::string& path);

// Builds the hull shape of `points`, reporting a failure at `path`.
std::optional<Shape> hullShape(Reader& reader, const std::vector<Vec3>& points, const std::string& path);

// The thesis importer, given the parsed document (a top-level object with "objects").
std::optional<Scene> importThesisScene(const Json& root, Reader& reader);

}  // namespace simcore::io_detail
