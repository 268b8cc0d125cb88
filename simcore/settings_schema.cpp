#include "simcore/settings_schema.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <type_traits>

namespace simcore {

std::string formatNumber(double value) {
    char buffer[400];
    const auto shortest = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, shortest.ptr);
    // For people, 0.0001 and 100000 read better than 1e-04 and 1e+05; keep exponents for the rest.
    if (text.find('e') != std::string::npos) {
        const auto fixed = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
        if (fixed.ec == std::errc() && fixed.ptr - buffer <= 8) text.assign(buffer, fixed.ptr);
    }
    return text;
}

bool NumberRange::contains(double value) const {
    return std::isfinite(value) && value <= max && (minExclusive ? value > min : value >= min);
}

std::string NumberRange::describe() const {
    std::string text(minExclusive ? "(" : "[");
    text += formatNumber(min);
    text += ", ";
    text += formatNumber(max);
    text += ']';
    if (!unit.empty()) (text += ' ') += unit;
    return text;
}

std::optional<std::string> rangeProblem(std::string_view label, double value, const NumberRange& range) {
    const std::string name(label);
    std::string unit;  // " m/s", or nothing
    if (!range.unit.empty()) (unit += ' ') += range.unit;
    const std::string got = ", got " + formatNumber(value);
    const std::string between = name + " must be between " + formatNumber(range.min) + " and " + formatNumber(range.max) + unit + got;
    if (!std::isfinite(value)) return name + " must be a finite number";
    if (value < range.min || (range.minExclusive && value == range.min)) {
        if (range.min < 0.0) return between;
        if (value < 0.0 && range.min == 0.0 && !range.minExclusive) return name + " must not be negative" + got;
        if (value <= 0.0) return name + " must be positive" + got;
        return name + " must be at least " + formatNumber(range.min) + unit + got;
    }
    if (value > range.max) {
        if (range.min < 0.0) return between;
        return name + " must be at most " + formatNumber(range.max) + unit + got;
    }
    return std::nullopt;
}

std::optional<std::string> integerRangeProblem(std::string_view label, double value, const NumberRange& range) {
    if (value >= range.min && value <= range.max) return std::nullopt;
    // Whole numbers in full (an iteration count of 100000000000 reads better than 1e+11).
    const bool whole = std::abs(value) < 1e15 && value == std::floor(value);
    return std::string(label) + " must be between " + formatNumber(range.min) + " and " + formatNumber(range.max) +
           ", got " + (whole ? std::to_string(static_cast<long long>(value)) : formatNumber(value));
}

std::string_view settingGroupName(SettingGroup group) {
    switch (group) {
        case SettingGroup::World: return "World";
        case SettingGroup::Solver: return "Solver";
        case SettingGroup::Contacts: return "Contacts";
        case SettingGroup::Joints: return "Joints";
        case SettingGroup::Damping: return "Damping";
        case SettingGroup::Sleep: return "Sleep";
        case SettingGroup::Effects: return "Effects";
    }
    return "unknown";
}

std::string SettingInfo::choiceList() const {
    std::string list;
    for (std::size_t i = 0; i < choices.size(); ++i)
        list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + std::string(choices[i]);
    return list;
}

std::string_view SettingInfo::name() const {
    const std::size_t dot = key.rfind('.');
    return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

namespace {

// Accessors of one member, given as a pointer-to-member path: member<&WorldSettings::solver,
// &SolverSettings::contactHertz>(s) is s.solver.contactHertz. Enums travel as their index.
template <auto First, auto... Rest, typename Settings>
auto& member(Settings& s) {
    if constexpr (sizeof...(Rest) == 0) return s.*First;
    else return ((s.*First) .* ... .* Rest);
}

template <auto... Path>
SettingValue getMember(const WorldSettings& s) {
    const auto& field = member<Path...>(s);
    using Field = std::remove_cvref_t<decltype(field)>;
    if constexpr (std::is_enum_v<Field>) return static_cast<int>(field);
    else return field;
}

template <auto... Path>
void setMember(WorldSettings& s, const SettingValue& value) {
    auto& field = member<Path...>(s);
    using Field = std::remove_cvref_t<decltype(field)>;
    if constexpr (std::is_enum_v<Field>) field = static_cast<Field>(std::get<int>(value));
    else field = std::get<Field>(value);
}

template <Effect E>
SettingValue getEffect(const WorldSettings& s) { return s.effects[E]; }
template <Effect E>
void setEffect(WorldSettings& s, const SettingValue& value) { s.effects[E] = std::get<bool>(value); }

constexpr std::string_view kIntegratorLabels[] = {"Semi-implicit Euler", "Explicit Euler", "Velocity Verlet"};
static_assert(std::size(kIntegratorLabels) == kIntegratorNames.size());
constexpr std::string_view kPositionCorrectionLabels[] = {"Soft step", "Baumgarte"};
static_assert(std::size(kPositionCorrectionLabels) == kPositionCorrectionNames.size());

constexpr NumberRange kNone{0.0, 0.0};
constexpr NumberRange kDampingRate{0.0, 1e3, false, "1/s"};
constexpr NumberRange kStiffness{0.0, 1e4, true, "Hz"};
constexpr NumberRange kContactDistance{0.0, 10.0, false, "m"};

using W = WorldSettings;
using G = SettingGroup;
using T = SettingType;

#define SIMCORE_MEMBER(...) &getMember<__VA_ARGS__>, &setMember<__VA_ARGS__>
#define SIMCORE_EFFECT(name, label, effect, doc)                                                        \
    SettingInfo {                                                                                        \
        "effects." name, T::Bool, G::Effects, kNone, {}, label, doc, &getEffect<effect>, &setEffect<effect> \
    }

constexpr SettingInfo kSettings[] = {
    {"gravity", T::Vec3, G::World, {-1e4, 1e4, false, "m/s^2"}, {}, "Gravity",
     "acceleration of every dynamic body", SIMCORE_MEMBER(&W::gravity)},
    {"timeStep", T::Float, G::World, {1e-6, 1.0, false, "s"}, {}, "Time step",
     "simulated time of one step (1/60 s: 60 steps per second)", SIMCORE_MEMBER(&W::timeStep)},
    {"substeps", T::Int, G::World, {1, 64}, {}, "Substeps",
     "equal parts a step is split into; more is stiffer and more accurate", SIMCORE_MEMBER(&W::substeps)},
    {"threads", T::Int, G::World, {0, 256}, {}, "Threads",
     "threads the step runs on (0: one per core); results do not depend on it", SIMCORE_MEMBER(&W::threads)},
    {"integrator", T::Choice, G::Solver, kNone, kIntegratorNames, "Integrator",
     "which velocity moves positions in a substep (end, start or mean)", SIMCORE_MEMBER(&W::integrator),
     kIntegratorLabels},
    {"solver.velocityIterations", T::Int, G::Solver, {1, 1000}, {}, "Velocity iterations",
     "sequential-impulse passes per substep", SIMCORE_MEMBER(&W::solver, &SolverSettings::velocityIterations)},
    {"solver.positionIterations", T::Int, G::Solver, {0, 1000}, {}, "Position iterations",
     "relax passes per substep (soft step); 0 switches them off",
     SIMCORE_MEMBER(&W::solver, &SolverSettings::positionIterations)},
    {"solver.positionCorrection", T::Choice, G::Solver, kNone, kPositionCorrectionNames, "Position correction",
     "how overlap is removed: soft contacts or Baumgarte bias",
     SIMCORE_MEMBER(&W::solver, &SolverSettings::positionCorrection), kPositionCorrectionLabels},
    {"solver.contactHertz", T::Float, G::Solver, kStiffness, {}, "Contact stiffness",
     "soft-contact spring frequency, capped at a quarter of the substep rate; up to 1.41 times that where loaded",
     SIMCORE_MEMBER(&W::solver, &SolverSettings::contactHertz)},
    {"solver.contactDampingRatio", T::Float, G::Solver, {0.0, 1e4}, {}, "Contact damping",
     "soft-contact damping ratio (above 1: no spring-back)",
     SIMCORE_MEMBER(&W::solver, &SolverSettings::contactDampingRatio)},
    {"solver.maxPushVelocity", T::Float, G::Solver, {0.0, 1e4, true, "m/s"}, {}, "Max push speed",
     "overlap is never removed faster than this", SIMCORE_MEMBER(&W::solver, &SolverSettings::maxPushVelocity)},
    {"solver.baumgarte", T::Float, G::Solver, {0.0, 1.0}, {}, "Baumgarte factor",
     "fraction of the overlap removed per substep (Baumgarte only)",
     SIMCORE_MEMBER(&W::solver, &SolverSettings::baumgarte)},
    {"contact.speculativeDistance", T::Float, G::Contacts, kContactDistance, {}, "Speculative distance",
     "points closer than this are solved before they touch",
     SIMCORE_MEMBER(&W::contact, &ContactSettings::speculativeDistance)},
    {"contact.linearSlop", T::Float, G::Contacts, kContactDistance, {}, "Slop",
     "overlap Baumgarte leaves alone, so resting contacts do not jitter",
     SIMCORE_MEMBER(&W::contact, &ContactSettings::linearSlop)},
    {"contact.restitutionThreshold", T::Float, G::Contacts, {0.0, 1e4, false, "m/s"}, {}, "Bounce threshold",
     "slower approaches do not bounce", SIMCORE_MEMBER(&W::contact, &ContactSettings::restitutionThreshold)},
    {"contact.maxContactsPerBody", T::Int, G::Contacts, {1, 1e6}, {}, "Contact cap",
     "most other dynamic bodies one dynamic body has contacts with",
     SIMCORE_MEMBER(&W::contact, &ContactSettings::maxContactsPerBody)},
    {"joint.hertz", T::Float, G::Joints, kStiffness, {}, "Joint stiffness",
     "spring frequency of joints' rigid rows, capped like contacts", SIMCORE_MEMBER(&W::joint, &JointSettings::hertz)},
    {"joint.dampingRatio", T::Float, G::Joints, {0.0, 1e4}, {}, "Joint damping",
     "damping ratio of joints' rigid rows (1: critically damped)",
     SIMCORE_MEMBER(&W::joint, &JointSettings::dampingRatio)},
    {"damping.linear", T::Float, G::Damping, kDampingRate, {}, "Linear damping",
     "exponential decay rate of every body's velocity", SIMCORE_MEMBER(&W::damping, &DampingSettings::linear)},
    {"damping.angular", T::Float, G::Damping, kDampingRate, {}, "Angular damping",
     "exponential decay rate of every body's angular velocity",
     SIMCORE_MEMBER(&W::damping, &DampingSettings::angular)},
    {"sleep.enabled", T::Bool, G::Sleep, kNone, {}, "Sleeping allowed",
     "resting bodies may sleep (cost nothing until touched)", SIMCORE_MEMBER(&W::sleep, &SleepSettings::enabled)},
    {"sleep.linearVelocity", T::Float, G::Sleep, {0.0, 1e3, false, "m/s"}, {}, "Sleep speed",
     "below this speed a body may sleep", SIMCORE_MEMBER(&W::sleep, &SleepSettings::linearVelocity)},
    {"sleep.angularVelocity", T::Float, G::Sleep, {0.0, 1e3, false, "rad/s"}, {}, "Sleep spin",
     "below this angular speed a body may sleep", SIMCORE_MEMBER(&W::sleep, &SleepSettings::angularVelocity)},
    {"sleep.timeToSleep", T::Float, G::Sleep, {0.0, 1e6, false, "s"}, {}, "Time to sleep",
     "how long a body must stay slow before it sleeps", SIMCORE_MEMBER(&W::sleep, &SleepSettings::timeToSleep)},
    // In Effect's order, which is the order files write them.
    SIMCORE_EFFECT("gravity", "Gravity", Effect::Gravity, "apply gravity"),
    SIMCORE_EFFECT("damping", "Damping", Effect::Damping, "apply velocity damping"),
    SIMCORE_EFFECT("gyroscopic", "Gyroscopic", Effect::Gyroscopic, "solve the gyroscopic torque of spinning bodies"),
    SIMCORE_EFFECT("contacts", "Contacts", Effect::Contacts, "find and solve contacts"),
    SIMCORE_EFFECT("friction", "Friction", Effect::Friction, "solve contact friction"),
    SIMCORE_EFFECT("restitution", "Restitution", Effect::Restitution, "let contacts bounce"),
    SIMCORE_EFFECT("joints", "Joints", Effect::Joints, "solve joints"),
    SIMCORE_EFFECT("ccd", "CCD", Effect::Ccd, "sweep fast bodies marked ccd so they do not tunnel"),
    SIMCORE_EFFECT("sleeping", "Sleeping", Effect::Sleeping, "put resting bodies to sleep"),
};

#undef SIMCORE_MEMBER
#undef SIMCORE_EFFECT

// The effect rows come last, one per Effect, in its order and keyed by its name.
constexpr bool effectRowsMatchEffects() {
    constexpr std::string_view kPrefix = "effects.";
    const std::size_t first = std::size(kSettings) - kEffectNames.size();
    for (std::size_t i = 0; i < std::size(kSettings); ++i) {
        const bool isEffect = kSettings[i].key.starts_with(kPrefix);
        if (isEffect != (i >= first)) return false;
        if (isEffect && kSettings[i].key.substr(kPrefix.size()) != kEffectNames[i - first]) return false;
    }
    return true;
}
static_assert(effectRowsMatchEffects(), "effect rows in Effect's order, keyed by effectName");

using P = PropertyOwner;
namespace L = limits;

constexpr PropertyInfo kProperties[] = {
    {P::Body, "name", std::nullopt, "unique within the scene when a joint names the body"},
    {P::Body, "motion", std::nullopt, "static, dynamic (default) or kinematic"},
    {P::Body, "shape", std::nullopt, "the collision shape, an object with a type"},
    {P::Body, "position", L::kCoordinate, "origin of the body (world frame)"},
    {P::Body, "orientation", L::kQuaternionComponent, "unit quaternion [w, x, y, z]"},
    {P::Body, "linearVelocity", L::kLinearSpeed, "velocity of the centre of mass"},
    {P::Body, "angularVelocity", L::kAngularSpeed, "angular velocity (world frame)"},
    {P::Body, "mass", L::kMass, "dynamic bodies: the mass (exclusive with density)"},
    {P::Body, "density", L::kDensity, "dynamic bodies: mass per volume (default 1000)"},
    {P::Body, "friction", L::kFriction, "Coulomb coefficient (default 0.5)"},
    {P::Body, "restitution", L::kRestitution, "bounciness (default 0)"},
    {P::Body, "rollingResistance", L::kRollingResistance, "coefficient of rolling resistance (default 0)"},
    {P::Body, "ccd", std::nullopt, "continuous collision: sweep the body so it does not tunnel"},
    {P::Body, "color", L::kColor, "linear RGB for the viewer"},
    {P::Shape, "type", std::nullopt, "box, sphere, capsule, cylinder, convexHull, compound, mesh or heightField"},
    {P::Box, "halfExtents", L::kSize, "half the box's size along each axis"},
    {P::Sphere, "radius", L::kSize, "the sphere's radius"},
    {P::Capsule, "radius", L::kSize, "radius of the capsule's caps and body"},
    {P::Capsule, "halfHeight", L::kSize, "half the straight part, along local Y"},
    {P::Cylinder, "radius", L::kSize, "the cylinder's radius"},
    {P::Cylinder, "halfHeight", L::kSize, "half the cylinder's height, along local Y"},
    {P::ConvexHull, "points", L::kCoordinate, "4 to 4096 points spanning a volume, in the body frame"},
    {P::Compound, "children", std::nullopt, "1 to 64 convex child shapes, each placed in the body frame"},
    {P::Mesh, "vertices", L::kCoordinate, "vertex positions [x, y, z] in the body frame"},
    {P::Mesh, "triangles", std::nullopt, "vertex index triples [i, j, k], counter-clockwise seen from the front; 1 to 2 000 000"},
    {P::Mesh, "file", std::nullopt, "instead of vertices and triangles: an OBJ, STL, glTF or GLB file, relative to the scene's folder"},
    {P::Mesh, "scale", NumberRange{-1e5, 1e5}, "a file mesh: factor per axis after the up-axis turn (not 0; negative mirrors)"},
    {P::Mesh, "upAxis", std::nullopt, "a file mesh: the file's up axis, y (default), z or x"},
    {P::HeightField, "rows", L::kHeightFieldSamples, "samples along +z (at least 2)"},
    {P::HeightField, "columns", L::kHeightFieldSamples, "samples along +x (at least 2)"},
    {P::HeightField, "cellSize", L::kSize, "distance between neighbouring samples"},
    {P::HeightField, "heightScale", L::kSize, "factor on every height (default 1)"},
    {P::HeightField, "heights", L::kCoordinate, "rows x columns heights, row by row, before heightScale"},
    {P::CompoundChild, "shape", std::nullopt, "the child's shape: any convex shape (compounds do not nest)"},
    {P::CompoundChild, "position", L::kCoordinate, "the child's origin in the body frame (default 0)"},
    {P::CompoundChild, "orientation", L::kQuaternionComponent, "unit quaternion [w, x, y, z] in the body frame"},
    {P::Joint, "name", std::nullopt, "the joint's name"},
    {P::Joint, "type", std::nullopt, "ball, hinge, slider, fixed or distance"},
    {P::Joint, "bodyA", std::nullopt, "name of the first body"},
    {P::Joint, "bodyB", std::nullopt, "name of the second body, or null for the world"},
    {P::Joint, "anchor", L::kCoordinate, "where the joint holds (world frame, at rest)"},
    {P::Joint, "collideConnected", std::nullopt, "whether the two bodies collide"},
    {P::Hinge, "axis", L::kCoordinate, "the hinge axis (world frame, not zero)"},
    {P::Hinge, "limits", std::nullopt, "angle limits {lower, upper}"},
    {P::Hinge, "limits.lower", L::kHingeAngle, "lowest angle"},
    {P::Hinge, "limits.upper", L::kHingeAngle, "highest angle"},
    {P::Hinge, "motor", std::nullopt, "motor {speed, maxTorque}"},
    {P::Hinge, "motor.speed", L::kAngularSpeed, "target angular speed"},
    {P::Hinge, "motor.maxTorque", NumberRange{0.0, 1e12, false, "N m"}, "most torque the motor applies"},
    {P::Slider, "axis", L::kCoordinate, "the slide axis (world frame, not zero)"},
    {P::Slider, "limits", std::nullopt, "travel limits {lower, upper}"},
    {P::Slider, "limits.lower", L::kCoordinate, "lowest travel"},
    {P::Slider, "limits.upper", L::kCoordinate, "highest travel"},
    {P::Slider, "motor", std::nullopt, "motor {speed, maxForce}"},
    {P::Slider, "motor.speed", L::kLinearSpeed, "target speed"},
    {P::Slider, "motor.maxForce", NumberRange{0.0, 1e12, false, "N"}, "most force the motor applies"},
    {P::Distance, "anchorB", L::kCoordinate, "where the joint holds bodyB (world frame, 0.1 mm from anchor)"},
    {P::Distance, "spring", std::nullopt, "a spring {hertz, dampingRatio} instead of a rigid length"},
    {P::Distance, "spring.hertz", L::kSpringHertz, "spring frequency"},
    {P::Distance, "spring.dampingRatio", L::kDampingRatio, "spring damping ratio"},
    {P::Distance, "minLength", L::kJointLength, "shortest length (default: the rest length)"},
    {P::Distance, "maxLength", L::kJointLength, "longest length (default: the rest length)"},
};

bool isShapeType(PropertyOwner owner) {
    return owner >= P::Box && owner <= P::HeightField;
}
bool isJointType(PropertyOwner owner) {
    return owner >= P::Hinge;
}
bool takes(PropertyOwner owner, const PropertyInfo& p) {
    return p.owner == owner || (isShapeType(owner) && p.owner == P::Shape) ||
           (isJointType(owner) && p.owner == P::Joint);
}

}  // namespace

std::span<const SettingInfo> settingsSchema() { return kSettings; }

const SettingInfo* findSetting(std::string_view key) {
    for (const SettingInfo& s : kSettings)
        if (s.key == key) return &s;
    return nullptr;
}

std::span<const PropertyInfo> propertySchema() { return kProperties; }

std::string_view propertyOwnerName(PropertyOwner owner) {
    switch (owner) {
        case P::Body: return "body";
        case P::Shape: return "shape";
        case P::Box: return "box";
        case P::Sphere: return "sphere";
        case P::Capsule: return "capsule";
        case P::Cylinder: return "cylinder";
        case P::ConvexHull: return "convexHull";
        case P::Compound: return "compound";
        case P::Mesh: return "mesh";
        case P::HeightField: return "heightField";
        case P::CompoundChild: return "compoundChild";
        case P::Joint: return "joint";
        case P::Hinge: return "hinge";
        case P::Slider: return "slider";
        case P::Distance: return "distance";
    }
    return "unknown";
}

const NumberRange& propertyRange(PropertyOwner owner, std::string_view key) {
    for (const PropertyInfo& p : kProperties)
        if (p.owner == owner && p.key == key && p.range) return *p.range;
    std::abort();  // a caller named a property the table does not have: a programming error
}

std::vector<std::string_view> propertyKeys(PropertyOwner owner) {
    std::vector<std::string_view> keys;
    for (const PropertyInfo& p : kProperties)
        if (takes(owner, p) && p.key.find('.') == std::string_view::npos) keys.push_back(p.key);
    return keys;
}

std::vector<std::string_view> propertyKeys(PropertyOwner owner, std::string_view object) {
    std::vector<std::string_view> keys;
    for (const PropertyInfo& p : kProperties) {
        const std::size_t dot = p.key.find('.');
        if (takes(owner, p) && dot != std::string_view::npos && p.key.substr(0, dot) == object)
            keys.push_back(p.key.substr(dot + 1));
    }
    return keys;
}

}  // namespace simcore
