// interplay-run: runs a scene without a window and prints a JSON report (see usageText()).

#include "report.h"
#include "runner_options.h"

#include "simcore/io/scene_io.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

namespace {

enum ExitCode { kSuccess = 0, kBadArguments = 2, kUnreadableScene = 3, kNonFinite = 4 };

// One row per body per step; step 0 is the state before the first step.
class TraceWriter {
public:
    bool open(const std::string& path) {
        file_ = std::fopen(path.c_str(), "w");
        if (!file_) return false;
        std::fputs("step,time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n", file_);
        return true;
    }
    ~TraceWriter() {
        if (file_) std::fclose(file_);
    }
    bool isOpen() const { return file_ != nullptr; }

    void write(const simcore::World& world) {
        const simcore::BodyStorage& b = world.bodies();
        for (std::size_t i = 0; i < b.size(); ++i) {
            const simcore::Vec3 p = b.origin(i);
            const simcore::Quat& q = b.orientation[i];
            const simcore::Vec3& v = b.linearVelocity[i];
            const simcore::Vec3& w = b.angularVelocity[i];
            std::fprintf(file_, "%llu,%.9g,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                         static_cast<unsigned long long>(world.stepCount()), world.simulatedTime(), i,
                         p.x, p.y, p.z, q.w, q.x, q.y, q.z, v.x, v.y, v.z, w.x, w.y, w.z);
        }
    }

private:
    std::FILE* file_ = nullptr;
};

int run(const runner::RunnerOptions& options) {
    simcore::SceneLoadResult loaded = simcore::loadSceneFile(options.scenePath);
    for (const simcore::Diagnostic& d : loaded.diagnostics) std::cerr << d.toString() << '\n';
    if (!loaded.ok()) return kUnreadableScene;
    simcore::Scene& scene = *loaded.scene;

    if (options.timeStep) scene.settings.timeStep = *options.timeStep;
    if (options.substeps) scene.settings.substeps = *options.substeps;
    if (options.velocityIterations) scene.settings.solver.velocityIterations = *options.velocityIterations;
    for (const std::string& assignment : options.settingOverrides) {
        if (auto error = simcore::applySettingOverride(scene, assignment)) {
            std::cerr << "interplay-run: --set " << assignment << ": " << *error << '\n';
            return kBadArguments;
        }
    }

    if (!options.savePath.empty()) {
        if (auto error = simcore::saveSceneFile(scene, options.savePath)) {
            std::cerr << "interplay-run: --save: " << *error << '\n';
            return kBadArguments;
        }
    }

    std::optional<simcore::BuiltWorld> built;
    try {
        built.emplace(simcore::buildWorld(scene));
    } catch (const std::exception& e) {
        // The loader validates everything the world checks, so this would be a loader gap.
        std::cerr << options.scenePath << ": error: " << e.what() << '\n';
        return kUnreadableScene;
    }
    simcore::World& world = built->world;

    // Steps to cover the requested time; the relative slack keeps 2 s at dt = 0.01f (which is
    // 0.0099999998) at 200 steps, not 201.
    const double dt = world.settings().timeStep;
    auto stepsFor = [dt](double seconds) { return static_cast<std::uint64_t>(std::ceil(seconds / dt * (1.0 - 1e-6))); };
    const std::uint64_t steps = options.steps ? *options.steps : stepsFor(options.seconds.value_or(1.0));

    TraceWriter trace;
    if (!options.tracePath.empty()) {
        if (!trace.open(options.tracePath)) {
            std::cerr << "interplay-run: cannot write trace file " << options.tracePath << '\n';
            return kBadArguments;
        }
        trace.write(world);
    }

    runner::RunSummary summary;
    summary.initialEnergy = world.kineticEnergy() + world.potentialEnergy();
    for (std::uint64_t s = 0; s < steps; ++s) {
        const auto start = std::chrono::steady_clock::now();
        world.step();
        summary.wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        ++summary.steps;
        const simcore::StepProfile& profile = world.lastStepProfile();
        for (int stage = 0; stage < simcore::kStageCount; ++stage) summary.stageMs[stage] += profile.stageMs[stage];
        summary.maxPenetration = std::max(summary.maxPenetration, profile.maxPenetration);

        if (auto bad = world.findNonFiniteBody()) {
            std::cerr << options.scenePath << ": error: body '" << bad->name << "' has a non-finite "
                      << bad->quantity << " at step " << world.stepCount() << '\n';
            return kNonFinite;
        }
        if (trace.isOpen()) trace.write(world);
    }

    const nlohmann::ordered_json report = runner::makeReport(world, summary);
    const std::string text = report.dump(2);
    std::cout << text << '\n';
    if (!options.outPath.empty()) {
        std::ofstream out(options.outPath);
        out << text << '\n';
        if (!out) {
            std::cerr << "interplay-run: cannot write report file " << options.outPath << '\n';
            return kBadArguments;
        }
    }
    return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
    const runner::ParseResult parsed = runner::parseArguments({argv + 1, argv + argc});
    if (parsed.options.help) {
        std::cout << runner::usageText();
        return kSuccess;
    }
    if (!parsed.error.empty()) {
        std::cerr << "interplay-run: " << parsed.error << "\n\n" << runner::usageText();
        return kBadArguments;
    }
    return run(parsed.options);
}
