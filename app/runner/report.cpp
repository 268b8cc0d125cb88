#include "report.h"

#include <algorithm>

namespace runner {

namespace {

nlohmann::ordered_json toJson(const simcore::Vec3& v) { return {v.x, v.y, v.z}; }
nlohmann::ordered_json toJson(const simcore::Quat& q) { return {q.w, q.x, q.y, q.z}; }

}  // namespace

void addStepProfile(RunSummary& summary, const simcore::StepProfile& profile) {
    for (std::size_t s = 0; s < summary.stageMs.size(); ++s) {
        summary.stageMs[s] += profile.stageMs[s];
        summary.handOvers[s] += profile.handOvers[s];
        if (profile.skipped[s] == simcore::StageSkip::Ran) {
            if (profile.withWorkers) ++summary.stepsWithWorkers[s];
            continue;
        }
        ++summary.stageSkips[s];
        summary.lastSkip[s] = profile.skipped[s];
    }
    summary.maxPenetration = std::max(summary.maxPenetration, profile.maxPenetration);
    summary.droppedPairs += profile.counters.droppedPairs;
    summary.boundedVelocities += profile.counters.boundedVelocities;
}

nlohmann::ordered_json makeReport(const simcore::World& world, const RunSummary& summary) {
    using namespace simcore;
    const double perStep = summary.steps > 0 ? 1.0 / static_cast<double>(summary.steps) : 0.0;

    nlohmann::ordered_json report;
    report["steps"] = summary.steps;
    report["dt"] = world.settings().timeStep;
    report["substeps"] = world.settings().substeps;
    report["simulatedTime"] = world.simulatedTime();
    report["wallMs"] = summary.wallMs;
    report["msPerStep"] = summary.wallMs * perStep;

    // In order of execution; a stage skipped in some step says why (the latest step's reason).
    nlohmann::ordered_json stages = nlohmann::ordered_json::array();
    for (const StageInfo& info : kStages) {
        const auto s = static_cast<std::size_t>(info.stage);
        nlohmann::ordered_json stage = {{"stage", info.key},
                                        {"msPerStep", summary.stageMs[s] * perStep},
                                        {"stepsRun", summary.steps - summary.stageSkips[s]},
                                        {"stepsWithWorkers", summary.stepsWithWorkers[s]},
                                        {"handOversPerStep", static_cast<double>(summary.handOvers[s]) * perStep}};
        if (summary.stageSkips[s] > 0) stage["skipped"] = stageSkipReason(summary.lastSkip[s]);
        stages.push_back(stage);
    }
    report["stages"] = stages;

    nlohmann::ordered_json effects = nlohmann::ordered_json::object();  // did the stage run in any step?
    for (int e = 0; e < kEffectCount; ++e)
        effects[std::string(effectName(static_cast<Effect>(e)))] = world.effectUsage().ran(static_cast<Effect>(e));
    report["effects"] = effects;

    const StepCounters& c = world.lastStepProfile().counters;  // of the last step
    report["counters"] = {{"bodies", c.bodies},          {"dynamicBodies", c.dynamicBodies},
                          {"awakeBodies", c.awakeBodies}, {"pairs", c.pairs},
                          {"manifolds", c.manifolds},     {"contactPoints", c.contactPoints},
                          {"islands", c.islands},         {"droppedPairs", c.droppedPairs},
                          {"boundedVelocities", c.boundedVelocities}};

    const double kinetic = world.kineticEnergy();
    const double potential = world.potentialEnergy();
    report["metrics"] = {
        {"maxPenetration", summary.maxPenetration},
        {"droppedPairs", summary.droppedPairs},  // pairs refused by the contact cap, summed over steps
        {"boundedVelocities", summary.boundedVelocities},  // cut to the safety bound, summed over steps
        {"kineticEnergy", kinetic},
        {"potentialEnergy", potential},
        {"totalEnergy", kinetic + potential},
        {"energyChange", kinetic + potential - summary.initialEnergy},
        {"linearMomentum", toJson(world.linearMomentum())},
        {"angularMomentum", toJson(world.angularMomentum())},
    };
    const JointError jointError = world.worstJointError();
    report["metrics"]["jointCount"] = world.jointCount();
    report["metrics"]["worstJointError"] = {{"position", jointError.position}, {"angle", jointError.angle}};
    report["metrics"]["maxJointError"] = {{"position", summary.maxJointError.position},
                                          {"angle", summary.maxJointError.angle}};

    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (const BodyId id : world.bodyIds()) {
        bodies.push_back({{"name", world.name(id)},
                          {"position", toJson(world.position(id))},
                          {"orientation", toJson(world.orientation(id))},
                          {"linearVelocity", toJson(world.linearVelocity(id))},
                          {"angularVelocity", toJson(world.angularVelocity(id))},
                          {"awake", world.isAwake(id)}});
    }
    report["bodies"] = bodies;
    return report;
}

std::string stageTable() {
    std::string table = "| # | stage | runs | what it does | skipped when |\n|---|---|---|---|---|\n";
    for (const simcore::StageInfo& info : simcore::kStages) {
        table += "| " + std::to_string(static_cast<int>(info.stage) + 1) + " | `" + std::string(info.key) + "` | " +
                 (info.perSubstep ? "per substep" : "per step") + " | " + std::string(info.doc) + " | " +
                 std::string(info.skippedWhen) + " |\n";
    }
    return table;
}

}  // namespace runner
