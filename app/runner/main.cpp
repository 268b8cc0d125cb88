// interplay-run: runs a scene without a window and prints a JSON report (see usageText()).

#include "report.h"
#include "runner_options.h"

#include "simcore/io/mesh_import.h"
#include "simcore/io/scene_io.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <utility>
#include <vector>

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
        const std::vector<simcore::BodyId> ids = world.bodyIds();
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const simcore::Vec3 p = world.position(ids[i]);
            const simcore::Quat q = world.orientation(ids[i]);
            const simcore::Vec3 v = world.linearVelocity(ids[i]);
            const simcore::Vec3 w = world.angularVelocity(ids[i]);
            std::fprintf(file_, "%llu,%.9g,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                         static_cast<unsigned long long>(world.stepCount()), world.simulatedTime(), i,
                         p.x, p.y, p.z, q.w, q.x, q.y, q.z, v.x, v.y, v.z, w.x, w.y, w.z);
        }
    }

private:
    std::FILE* file_ = nullptr;
};

int run(const runner::RunnerOptions& options) {
    simcore::SceneReadOptions reading;
    reading.loadMeshFile = simcore::importMeshFile;  // mesh files through assimp (mesh_file.h)
    simcore::SceneLoadResult loaded = simcore::loadSceneFile(options.scenePath, reading);
    for (const simcore::Diagnostic& d : loaded.diagnostics) std::cerr << d.toString() << '\n';
    if (!loaded.ok()) return kUnreadableScene;
    simcore::Scene& scene = *loaded.scene;

    // --dt, --substeps and --iterations are settings like any other: they go through the same
    // validation as the file (and --set), so the loader's limits hold for them too.
    std::vector<std::pair<std::string, std::string>> shortcuts;  // option, assignment
    if (options.timeStep) {
        char text[32];
        const auto written = std::to_chars(text, text + sizeof text, *options.timeStep);  // shortest: same float back
        shortcuts.emplace_back("--dt", "timeStep=" + std::string(text, written.ptr));
    }
    if (options.substeps) shortcuts.emplace_back("--substeps", "substeps=" + std::to_string(*options.substeps));
    if (options.velocityIterations)
        shortcuts.emplace_back("--iterations", "solver.velocityIterations=" + std::to_string(*options.velocityIterations));
    for (const auto& [option, assignment] : shortcuts) {
        if (auto error = simcore::applySettingOverride(scene, assignment)) {
            std::cerr << "interplay-run: " << option << ": " << *error << '\n';
            return kBadArguments;
        }
    }
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

    // --force: every body of that name; a name that matches none is a bad argument.
    std::vector<std::pair<simcore::BodyId, simcore::Vec3>> forces;
    for (const runner::ForceOption& f : options.forces) {
        bool found = false;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            if (scene.bodies[i].body.name != f.body) continue;
            forces.emplace_back(built->bodyIds[i], simcore::Vec3(f.force[0], f.force[1], f.force[2]));
            found = true;
        }
        if (!found) {
            std::cerr << "interplay-run: --force: the scene has no body named '" << f.body << "'\n";
            return kBadArguments;
        }
    }

    // Steps to cover the requested time; the relative slack keeps 2 s at dt = 0.01f (which is
    // 0.0099999998) at 200 steps, not 201.
    const double dt = world.settings().timeStep;
    const double wantedSteps = std::ceil(options.seconds.value_or(1.0) / dt * (1.0 - 1e-6));
    if (!options.steps && !(wantedSteps < 1e15)) {  // also keeps the conversion below defined
        std::cerr << "interplay-run: --seconds " << *options.seconds << " is more than 1e15 steps of " << dt << " s\n";
        return kBadArguments;
    }
    const std::uint64_t steps = options.steps ? *options.steps : static_cast<std::uint64_t>(wantedSteps);

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
        for (const auto& [id, force] : forces) world.addForce(id, force);
        const auto start = std::chrono::steady_clock::now();
        world.step();
        summary.wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        ++summary.steps;
        runner::addStepProfile(summary, world.lastStepProfile());
        if (world.jointCount() > 0) {
            const simcore::JointError jointError = world.worstJointError();
            summary.maxJointError.position = std::max(summary.maxJointError.position, jointError.position);
            summary.maxJointError.angle = std::max(summary.maxJointError.angle, jointError.angle);
        }

        if (auto bad = world.findNonFiniteBody()) {
            std::cerr << options.scenePath << ": error: body '" << bad->name << "' has a non-finite "
                      << bad->quantity << " at step " << world.stepCount() << '\n';
            return kNonFinite;
        }
        if (trace.isOpen()) trace.write(world);
    }

    if (summary.droppedPairs > 0)
        std::cerr << options.scenePath << ": warning: " << summary.droppedPairs
                  << " overlapping pairs (summed over steps) were not made into contacts: bodies at the contact cap "
                     "(settings.contact.maxContactsPerBody = "
                  << world.settings().contact.maxContactsPerBody << ") pass through them\n";
    if (summary.boundedVelocities > 0)
        std::cerr << options.scenePath << ": warning: a body's velocity was cut to the safety bound (1e5 m/s, a "
                     "quarter turn per substep) "
                  << summary.boundedVelocities
                  << " times (summed over steps), so the motion is not physical: bodies get there when the "
                     "simulation is unstable (a joint torn far apart, a violent overlap), where more substeps or a "
                     "smaller time step help\n";
    // Streamed, not dumped to a string first: for a thousand bodies the text was the process's
    // largest allocation (1.5 MB with its growth), larger than the world.
    const nlohmann::ordered_json report = runner::makeReport(world, summary);
    std::cout << std::setw(2) << report << '\n';
    if (!options.outPath.empty()) {
        std::ofstream out(options.outPath);
        out << std::setw(2) << report << '\n';
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
    if (parsed.options.listStages) {
        std::cout << runner::stageTable();
        return kSuccess;
    }
    if (!parsed.error.empty()) {
        std::cerr << "interplay-run: " << parsed.error << "\n\n" << runner::usageText();
        return kBadArguments;
    }
    return run(parsed.options);
}
