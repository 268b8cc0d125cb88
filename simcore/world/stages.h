#pragma once
// The stages of World::step, in order of execution: the one list the step, the profiler, the
// runner's report (and its --list-stages), the editor's Profiler panel and docs/architecture.md
// (checked by ctest check_stage_table) all follow.

#include <array>
#include <cstdint>
#include <string_view>

namespace simcore {

enum class Stage : std::uint8_t {
    Pairs,
    Collide,
    Islands,
    Prepare,
    IntegrateVelocities,
    WarmStart,
    Solve,
    IntegratePositions,
    Restitution,
    Relax,
    StoreImpulses,
    Continuous,
    Sleep,
    Count
};
constexpr int kStageCount = static_cast<int>(Stage::Count);

struct StageInfo {
    Stage stage;
    std::string_view key;  // camelCase, as in the runner's report
    std::string_view name;  // words, as the editor shows it
    bool perSubstep;        // runs in every substep; its time is the sum over them
    std::string_view doc;   // what it does, one line
    std::string_view skippedWhen;  // when step() leaves it out (the reasons are StageSkip's)
};

inline constexpr std::array<StageInfo, kStageCount> kStages{{
    {Stage::Pairs, "pairs", "pairs", false,
     "broad phase: the fat boxes of awake bodies move in the tree; new overlapping pairs become contacts",
     "contacts off, no awake dynamic body, or fewer than two bodies"},
    {Stage::Collide, "collide", "collide", false,
     "narrow phase: a manifold for every contact with an awake body (kept while the pair hardly moved), impulses carried over",
     "as pairs"},
    {Stage::Islands, "islands", "islands", false,
     "islands over contacts and joints: bodies touching an awake island wake with it",
     "neither contacts nor joints run"},
    {Stage::Prepare, "prepare", "prepare", false,
     "contact and joint constraints made for this step, with last step's impulses",
     "as islands"},
    {Stage::IntegrateVelocities, "integrateVelocities", "integrate velocities", true,
     "gravity, applied forces, gyroscopic torque, damping",
     "no awake dynamic or kinematic body (static and sleeping bodies are not visited)"},
    {Stage::WarmStart, "warmStart", "warm start", true, "last step's impulses applied, joints then contacts",
     "no contact constraint and no joint"},
    {Stage::Solve, "solve", "solve", true,
     "velocity iterations with position correction, joints then contacts", "as warm start"},
    {Stage::IntegratePositions, "integratePositions", "integrate positions", true,
     "centres of mass and orientations, by the chosen integrator", "as integrate velocities"},
    {Stage::Restitution, "restitution", "restitution", true,
     "contacts closing faster than the threshold bounce (in the first substep also before warm start)",
     "restitution off, no contact constraint, or none with restitution above zero"},
    {Stage::Relax, "relax", "relax", true,
     "the same constraints without the push, so it does not become bounce",
     "no constraint, or only contacts under Baumgarte position correction"},
    {Stage::StoreImpulses, "storeImpulses", "store impulses", false,
     "impulses kept for the next warm start; with joints, velocities held to the safety bound",
     "as warm start"},
    {Stage::Continuous, "continuous", "continuous", false,
     "a fast body that would pass through another stops at the time of impact",
     "ccd off, as pairs, or no body flagged ccd nor fast (moved over half its thinnest size)"},
    {Stage::Sleep, "sleep", "sleep", false, "islands that stayed slow long enough stop being simulated",
     "sleep off, or no awake dynamic body"},
}};

constexpr const StageInfo& stageInfo(Stage stage) { return kStages[static_cast<std::size_t>(stage)]; }
constexpr std::string_view stageName(Stage stage) { return stageInfo(stage).key; }

// The table is indexed by Stage: each row must sit at its own enumerator's place.
constexpr bool stagesInEnumOrder() {
    for (int s = 0; s < kStageCount; ++s)
        if (static_cast<int>(kStages[static_cast<std::size_t>(s)].stage) != s) return false;
    return true;
}
static_assert(stagesInEnumOrder(), "kStages must list the stages in the order of enum Stage");

// Why a stage did not run in a step (Ran when it did).
enum class StageSkip : std::uint8_t {
    Ran,
    ContactsOff,
    NothingAwake,
    NothingMoves,
    SingleBody,
    NothingToSolve,
    NoConstraint,
    RestitutionOff,
    NoBouncyContact,
    Baumgarte,
    CcdOff,
    NoFastBody,
    SleepOff,
    Count
};

inline constexpr std::array<std::string_view, static_cast<int>(StageSkip::Count)> kStageSkipReasons{{
    "ran",
    "contacts off in settings",
    "no awake dynamic body",
    "no awake dynamic or kinematic body",
    "fewer than two bodies",
    "no contacts and no joints to solve",
    "no contact constraint and no joint",
    "restitution off in settings",
    "no contact with restitution above zero",
    "Baumgarte position correction: contacts do not relax",
    "ccd off in settings",
    "no ccd body and none fast enough to need a sweep",
    "sleep off in settings",
}};

constexpr std::string_view stageSkipReason(StageSkip skip) { return kStageSkipReasons[static_cast<std::size_t>(skip)]; }

}  // namespace simcore
