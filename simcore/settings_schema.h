#pragma once
// The one description of what a scene may hold: every WorldSettings field (its key in a scene
// file's "settings" object, type, accepted range, unit, panel group, label and documentation, and
// how to read and write it), and the accepted ranges of body, shape and joint properties. The
// loader, the writer, the runner's --set, the editor's Simulation panel and its Inspector all
// derive from these tables, so adding a setting means adding a row here (and the code that uses
// the new field), nothing else. Outside these ranges float precision, or the solver, would give
// garbage, so a clear refusal is kinder than a strange simulation.

#include "simcore/math/math.h"
#include "simcore/world_settings.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace simcore {

// The shortest text that reads back as the same double, in plain decimals when that is short
// (0.0001, 100000) and with an exponent otherwise (1e-09, 1e+300): numbers in messages and docs.
std::string formatNumber(double value);

// Accepted values of a number. Both ends are included, except a minimum of 0 marked exclusive
// (the value must be positive, not merely non-negative).
struct NumberRange {
    double min;
    double max;
    bool minExclusive = false;
    std::string_view unit = {};  // SI unit as written in messages and docs ("m/s^2"); empty: none

    bool contains(double value) const;
    // "[-10000, 10000] m/s^2", "(0, 10000] Hz": the interval as the docs write it.
    std::string describe() const;
};

// Why `value` is outside `range`, as the loader reports it ("gravity[1] must be between -10000 and
// 10000 m/s^2, got 1e+09"), or nothing when it is inside. `label` names the value.
std::optional<std::string> rangeProblem(std::string_view label, double value, const NumberRange& range);
// The same for an integer setting or count ("substeps must be between 1 and 64, got 65").
std::optional<std::string> integerRangeProblem(std::string_view label, double value, const NumberRange& range);

// Limits of body, shape and joint values (and of the settings that share them).
namespace limits {
inline constexpr NumberRange kSize{1e-4, 1e5, false, "m"};         // half-extents, radii, half-heights
inline constexpr NumberRange kCoordinate{-1e6, 1e6, false, "m"};  // positions, hull points, anchors, axes
inline constexpr NumberRange kMass{1e-6, 1e9, false, "kg"};
inline constexpr NumberRange kDensity{1e-3, 1e6, false, "kg/m^3"};
inline constexpr NumberRange kFriction{0.0, 100.0};
inline constexpr NumberRange kRestitution{0.0, 1.0};
inline constexpr NumberRange kRollingResistance{0.0, 100.0};
inline constexpr NumberRange kLinearSpeed{-1e4, 1e4, false, "m/s"};
inline constexpr NumberRange kAngularSpeed{-1e4, 1e4, false, "rad/s"};
inline constexpr NumberRange kColor{0.0, 1.0};
inline constexpr NumberRange kQuaternionComponent{-1e6, 1e6};
inline constexpr NumberRange kHingeAngle{-static_cast<double>(kPi), static_cast<double>(kPi), false, "rad"};
inline constexpr NumberRange kMotorForce{0.0, 1e12, false, "N or N m"};
inline constexpr NumberRange kJointLength{0.0, 1e6, false, "m"};
inline constexpr NumberRange kSpringHertz{0.0, 1e4, true, "Hz"};
inline constexpr NumberRange kDampingRatio{0.0, 1e4};
inline constexpr std::size_t kMaxHullPoints = 4096;
// A compound's children: the mid-phase scans them as a list, and a pair of compounds can hold a
// contact per pair of children (64 x 64 at most).
inline constexpr std::size_t kMaxCompoundChildren = 64;
// Static surfaces: a hostile file cannot exhaust memory, and a 1e6 m coordinate keeps float
// precision where the rest of a scene keeps it. A height field's triangles are 2 (rows - 1)(columns - 1).
inline constexpr std::size_t kMaxMeshTriangles = 2'000'000;
inline constexpr std::size_t kMaxMeshVertices = 3 * kMaxMeshTriangles;
inline constexpr int kMaxHeightFieldSamples = 1'000'001;  // per side; the triangle limit binds first
inline constexpr NumberRange kHeightFieldSamples{2, kMaxHeightFieldSamples};
}  // namespace limits

// ---- world settings ----

enum class SettingType { Bool, Int, Float, Vec3, Choice };
// Where the editor's Simulation panel shows a setting, in the panel's order.
enum class SettingGroup { World, Solver, Contacts, Joints, Damping, Sleep, Effects };
std::string_view settingGroupName(SettingGroup group);  // "World", "Solver", ...

// A setting's value: bool, int (Int, and Choice as its index in `choices`), float, or Vec3.
using SettingValue = std::variant<bool, int, float, Vec3>;

struct SettingInfo {
    std::string_view key;    // dotted path in the file's "settings" object: "solver.contactHertz"
    SettingType type;
    SettingGroup group;
    NumberRange range;       // Int, Float and each Vec3 component; unused for Bool and Choice
    std::span<const std::string_view> choices;  // Choice: the names the file uses, in enum order
    std::string_view label;  // short, for the panel: "Contact stiffness"
    std::string_view doc;    // one line: what it does
    SettingValue (*get)(const WorldSettings&);
    void (*set)(WorldSettings&, const SettingValue&);  // the value must have the setting's type
    std::span<const std::string_view> choiceLabels = {};  // Choice: what the panel shows, as `choices`

    // A Choice's names as a sentence lists them: "softStep or baumgarte".
    std::string choiceList() const;
    // The part of `key` after the last dot: what the loader's messages call it.
    std::string_view name() const;
};

// Every WorldSettings field, in the order a saved file writes them. `preset` (quality_preset.h) is
// not a field but a label applied before them, and is handled by its users.
std::span<const SettingInfo> settingsSchema();
const SettingInfo* findSetting(std::string_view key);  // null for an unknown key

// ---- body, shape and joint properties ----

// What a property belongs to. Each joint type's and shape type's keys come on top of the
// common ones (Joint, Shape). CompoundChild is one entry of a compound's "children".
enum class PropertyOwner {
    Body, Shape, Box, Sphere, Capsule, Cylinder, ConvexHull, Compound, Mesh, HeightField, CompoundChild, Joint, Hinge,
    Slider, Distance
};

// "body", "shape", "box", ..., "compound", "mesh", "heightField", "compoundChild", "joint", "hinge", "slider", "distance": qualifies a key in docs and
// tests ("hinge.limits.lower").
std::string_view propertyOwnerName(PropertyOwner owner);

struct PropertyInfo {
    PropertyOwner owner;
    std::string_view key;                // in the owner's JSON object; "limits.lower" inside "limits"
    std::optional<NumberRange> range;    // numbers (a vector's components); none for names, flags, enums
    std::string_view doc;
};

// Every key a body, shape or joint object may have, in the order files write them.
std::span<const PropertyInfo> propertySchema();
// The range of a numeric property; aborts on a key that has none, so a typo fails at once.
const NumberRange& propertyRange(PropertyOwner owner, std::string_view key);
// The keys an object of `owner` takes at its top level (for a joint or shape type including the
// common Joint / Shape keys), in table order: what the loader accepts without a warning.
std::vector<std::string_view> propertyKeys(PropertyOwner owner);
// The keys inside a nested object of `owner`, e.g. ("limits") -> lower, upper.
std::vector<std::string_view> propertyKeys(PropertyOwner owner, std::string_view object);

}  // namespace simcore
