#pragma once
// The JSON report interplay-run prints: timings from the engine's profiler, which effects ran,
// counters, physical metrics and the final state of every body.

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
    double initialEnergy = 0.0;                              // kinetic + potential before step 1 (J)
    float maxPenetration = 0.0f;                             // deepest contact overlap seen in any step (m)
    simcore::JointError maxJointError;                       // worst joint position / angle error of any step
    std::uint64_t droppedPairs = 0;                          // pairs refused by the contact cap, summed over steps
    std::uint64_t boundedVelocities = 0;                     // velocities cut to the safety bound, summed over steps
};

nlohmann::ordered_json makeReport(const simcore::World& world, const RunSummary& summary);

}  // namespace runner
