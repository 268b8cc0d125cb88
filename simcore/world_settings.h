#pragma once
// Everything that parametrises a world, as one plain struct with defaulted, unit-annotated members.
// A scene file's "settings" object maps onto it key for key.

#include "simcore/math/math.h"

#include <array>
#include <cstdint>
#include <string_view>

// The default of WorldSettings::threads; set only by the CMake option of the same name.
#ifndef SIMCORE_DEFAULT_THREADS
#define SIMCORE_DEFAULT_THREADS 1
#endif

namespace simcore {

// Physical effects a step can include. An effect runs only when enabled here *and* something in
// the world needs it (see World::step), so switching one off is also a way to buy speed.
enum class Effect : std::uint8_t {
    Gravity,
    Damping,
    Gyroscopic,
    Contacts,
    Friction,
    Restitution,
    Joints,
    Ccd,
    Sleeping,
    Count
};
constexpr int kEffectCount = static_cast<int>(Effect::Count);
// The names scene files use, in the enum's order (here, and in the enums below).
inline constexpr std::array<std::string_view, kEffectCount> kEffectNames{
    "gravity", "damping", "gyroscopic", "contacts", "friction", "restitution", "joints", "ccd", "sleeping"};
std::string_view effectName(Effect effect);  // "gravity", "damping", ... as in the scene file

struct EffectFlags {
    std::array<bool, kEffectCount> enabled{true, true, true, true, true, true, true, true, true};

    bool operator[](Effect e) const { return enabled[static_cast<int>(e)]; }
    bool& operator[](Effect e) { return enabled[static_cast<int>(e)]; }
    friend bool operator==(const EffectFlags&, const EffectFlags&) = default;
};

// How contacts remove overlap.
enum class PositionCorrection : std::uint8_t {
    // Soft contacts (Box2D v3's soft step): overlap is pushed out by a stiff, heavily damped spring
    // solved inside the velocity iterations, then relax passes remove the push velocity so it
    // does not turn into bounce. Stable in stacks; the default.
    SoftStep,
    // Classic Baumgarte stabilisation: a bias velocity proportional to the overlap beyond the
    // slop, no relax passes. Cheaper per iteration, adds energy, jitters in tall stacks.
    Baumgarte,
};
inline constexpr std::array<std::string_view, 2> kPositionCorrectionNames{"softStep", "baumgarte"};
std::string_view positionCorrectionName(PositionCorrection method);  // "softStep", "baumgarte"

// How a substep moves positions once constraints have set the velocities. All three update
// velocities the same way (forces, then constraints); they differ in which velocity moves the body.
enum class Integrator : std::uint8_t {
    // Semi-implicit (symplectic) Euler: the end-of-substep velocity, which the constraints just
    // made consistent. Energy stays bounded and contacts hold; the default.
    SymplecticEuler,
    // Explicit Euler: the start-of-substep velocity. First order and energy-gaining; kept to show
    // what the symplectic update buys (the thesis compared the two).
    ExplicitEuler,
    // Velocity Verlet: the mean of start and end velocities, exact for constant forces (a free
    // flight's parabola) but it lets bodies move half a substep against a constraint's fix.
    VelocityVerlet,
};
inline constexpr std::array<std::string_view, 3> kIntegratorNames{"symplecticEuler", "explicitEuler", "velocityVerlet"};
std::string_view integratorName(Integrator integrator);  // "symplecticEuler", "explicitEuler", "velocityVerlet"

struct SolverSettings {
    int velocityIterations = 2;  // sequential-impulse passes per substep
    int positionIterations = 1;  // per substep: relax passes (soft step); unused by Baumgarte
    PositionCorrection positionCorrection = PositionCorrection::SoftStep;
    float contactHertz = 60.0f;         // soft-contact stiffness (Hz), capped at a quarter of the substep rate;
                                        // loaded contacts up to 1.41 times that (ContactSolver::kStiffLoad)
    float contactDampingRatio = 10.0f;  // soft-contact damping ratio (overdamped: no spring-back)
    float maxPushVelocity = 3.0f;       // m/s: overlap is never removed faster than this
    float baumgarte = 0.2f;             // fraction of the overlap removed per substep (Baumgarte only)
    friend bool operator==(const SolverSettings&, const SolverSettings&) = default;
};

struct ContactSettings {
    float speculativeDistance = 0.02f;   // m: points closer than this are solved before they touch
    float linearSlop = 0.005f;           // m: overlap Baumgarte leaves alone, so resting contacts don't jitter
    float restitutionThreshold = 1.0f;   // m/s: slower approaches do not bounce
    // A dynamic body has contacts with at most this many other dynamic bodies; overlapping pairs
    // beyond it are not made (and counted, StepCounters::droppedPairs). Bounds a crowd of n
    // overlapping bodies to O(n) pairs instead of n^2 / 2 - memory and time per step - far above
    // what resting bodies need (a box in a pile touches about ten others). Contacts with static and
    // kinematic bodies are not capped: a floor carries any number of bodies.
    int maxContactsPerBody = 128;
    friend bool operator==(const ContactSettings&, const ContactSettings&) = default;
};

// Stiffness of every joint's rigid rows: position error is removed by a soft constraint (as
// contacts are), a spring of this frequency for the mass the row moves, solved implicitly inside
// the velocity iterations. A load stretches it by about (load / row mass) / (2 pi hertz)^2: 0.07 mm
// for a body hanging at 60 Hz, (M/m) times that for a heavy body on light links. Stiffer joints
// need more substeps (the cap), e.g. 8 substeps and 120 Hz halve a 20-link chain's stretch.
struct JointSettings {
    float hertz = 60.0f;        // Hz, capped at a quarter of the substep rate like contacts
    float dampingRatio = 1.0f;  // critically damped: the error goes fastest without ringing
    friend bool operator==(const JointSettings&, const JointSettings&) = default;
};

struct DampingSettings {
    // Exponential velocity decay rates (1/s): v(t + dt) = v(t) * exp(-rate * dt).
    float linear = 0.0f;
    float angular = 0.0f;
    friend bool operator==(const DampingSettings&, const DampingSettings&) = default;
};

struct SleepSettings {
    bool enabled = true;
    float linearVelocity = 0.05f;   // below this speed (m/s) a body may sleep
    float angularVelocity = 0.05f;  // below this angular speed (rad/s) a body may sleep
    float timeToSleep = 0.5f;       // a body must stay slow this long (s) before it sleeps
    friend bool operator==(const SleepSettings&, const SleepSettings&) = default;
};

struct WorldSettings {
    Vec3 gravity{0.0f, -9.81f, 0.0f};  // m/s^2
    float timeStep = 1.0f / 60.0f;     // s, one call to World::step
    int substeps = 4;                  // the step is split into this many equal substeps
    // Threads the step's data-parallel stages run on, the caller's included; 0: one per core.
    // Results are the same bits for any count. 1 (no worker threads) by default: on a 2-core machine
    // 2 threads gain 1.6-1.8x on pyramid20 but little or nothing on the piles and the resting
    // pyramid of base 10 (bench/results/threads.md, box3d-threads.md). Only the
    // ThreadSanitizer build changes the default (CMake option SIMCORE_DEFAULT_THREADS), so that
    // every world its suites build, in code or from a file without "threads", steps on workers.
    int threads = SIMCORE_DEFAULT_THREADS;
    Integrator integrator = Integrator::SymplecticEuler;
    SolverSettings solver;
    ContactSettings contact;
    JointSettings joint;
    DampingSettings damping;
    SleepSettings sleep;
    EffectFlags effects;
    friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

}  // namespace simcore
