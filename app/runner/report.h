#pragma once
// The JSON report interplay-run prints: timings from the engine's profiler stage by stage (and
// which stages a scene skipped, and why), which effects ran, counters, physical metrics and the
// final state of every body. Also the stage table --list-stages prints.

#include "simcore/world/world.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <string>

namespace runner {

// What the runner measured while stepping.
struct RunSummary {
    std::uint64_t steps = 0;
    double wallMs = 0.0;                                     // stepping loop only
    std::array<double, simcore::kStageCount> stageMs{};     // summed over all steps
    std::array<std::uint64_t, simcore::kStageCount> stageSkips{};  // steps that skipped each stage
    std::array<std::uint64_t, simcore::kStageCount> stepsWithWorkers{};  // steps that ran it on workers too
    std::array<std::uint64_t, simcore::kStageCount> handOvers{};         // jobs it offered the workers, summed
    std::array<simcore::StageSkip, simcore::kStageCount> lastSkip{};  // why, in the latest of them
    double initialEnergy = 0.0;                              // kinetic + potential before step 1 (J)
    float maxPenetration = 0.0f;                             // deepest contact overlap seen in any step (m)
    simcore::JointError maxJointError;                       // worst joint position / angle error of any step
    std::uint64_t droppedPairs = 0;                          // pairs refused by the contact cap, summed over steps
    std::uint64_t boundedVelocities = 0;                     // velocities cut to the safety bound, summed over steps
};

// Adds one step's profile to the summary (the caller times the step and counts it).
void addStepProfile(RunSummary& summary, const simcore::StepProfile& profile);

nlohmann::ordered_json makeReport(const simcore::World& world, const RunSummary& summary);

// The stages of a step as the Markdown table docs/architecture.md holds (ctest check_stage_table).
std::string stageTable();

}  // namespace runner
