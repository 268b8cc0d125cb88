// interplay-sweep: what accuracy costs for one scene. Runs the scene over a grid of settings,
// compares every run with a converged reference, and writes tables, Pareto fronts and plots (see
// usageText() and docs/sweep.md). The work is accuracy::runSweep; this file is the command line,
// the result directory and the report.

#include "sweep_options.h"

#include "accuracy/scene_sweep.h"
#include "accuracy/sweep_files.h"

#include "simcore/io/mesh_import.h"
#include "simcore/io/scene_io.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

namespace {

namespace fs = std::filesystem;
using namespace sweep;

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int) {
    interrupted.store(true);
    std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the program at once
}

// The scene with its mesh files read through assimp (mesh_file.h).
simcore::SceneLoadResult loadScene(const fs::path& path) {
    simcore::SceneReadOptions reading;
    reading.loadMeshFile = simcore::importMeshFile;
    return simcore::loadSceneFile(path, reading);
}

int complain(const std::string& message, int code) {
    std::cerr << "interplay-sweep: " << message << '\n';
    return code;
}

std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string exactNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);  // the job reads back the same double
    return buffer;
}

// The command that runs one grid point and writes DIR/points/<id>.json: this program, the scene and
// every option that decides the result, so the line needs nothing else.
std::string jobCommand(const accuracy::SweepPlan& plan, const fs::path& dir, const accuracy::GridPoint& point) {
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) self = "interplay-sweep";
    std::string command = quoted(self.string()) + " " + quoted(plan.scenePath) + " --seconds " + exactNumber(plan.spec.seconds) +
                          " --sample-rate " + exactNumber(plan.spec.sampleRate);
    for (const std::string& r : plan.spec.reference) command += " --reference " + quoted(r);
    command += " --out " + quoted(dir.string());
    for (const std::string& a : point.assignments) command += " --point " + quoted(a);
    return command;
}

// The plan in DIR: one of another sweep is refused (its results would mix); written unless this
// is one job of an emitted sweep, whose plan is the emitter's.
std::optional<std::string> preparePlan(const fs::path& dir, const accuracy::SweepPlan& plan, bool write) {
    std::error_code ec;
    fs::create_directories(dir / "points", ec);
    if (ec) return "--out " + dir.string() + ": cannot create it: " + ec.message();
    if (fs::exists(accuracy::planPath(dir))) {
        std::string error;
        const std::optional<accuracy::SweepPlan> old = accuracy::readPlan(accuracy::planPath(dir), error);
        if (old && old->key != plan.key)
            return "--out " + dir.string() + " holds the results of another sweep (another scene, --seconds, --sample-rate or "
                   "--reference): give another --out or delete it";
    }
    if (!write) return std::nullopt;
    return accuracy::writeFileAtomically(accuracy::planPath(dir), accuracy::planJson(plan).dump(2) + "\n");
}

// DIR's reference when it has one of this sweep, else a new one (on `jobs` threads), written there.
std::optional<accuracy::Reference> prepareReference(const simcore::Scene& scene, const accuracy::SweepPlan& plan,
                                                    const fs::path& dir, int jobs, int& code) {
    std::string error;
    if (fs::exists(accuracy::referencePath(dir))) {
        if (auto known = accuracy::readReference(accuracy::referencePath(dir), plan.key, error)) return known;
        std::cerr << "interplay-sweep: " << error << "; running the reference again\n";
    }
    std::cerr << "reference run (" << accuracy::referenceAssignments(scene, plan.spec).size() << " settings changed) and its "
              << "convergence check ..." << std::flush;
    std::optional<accuracy::Reference> reference = accuracy::runReference(scene, plan.spec, error, &interrupted, jobs);
    std::cerr << '\n';
    if (!reference) {
        code = interrupted ? kInterrupted : kReferenceFailed;
        std::cerr << "interplay-sweep: "
                  << (interrupted ? "interrupted during the reference run; nothing is kept yet" : error) << '\n';
        return std::nullopt;
    }
    if (auto writeError = accuracy::writeFileAtomically(accuracy::referencePath(dir),
                                                        accuracy::referenceJson(*reference, plan.key).dump() + "\n")) {
        code = kBadArguments;
        std::cerr << "interplay-sweep: " << *writeError << '\n';
        return std::nullopt;
    }
    return reference;
}

std::string measureSummary(const accuracy::Measures& m) {
    std::ostringstream text;
    text.precision(3);
    for (std::size_t i = 0; i < accuracy::kMeasureCount; ++i)
        text << (i ? ", " : "") << accuracy::measureKey(static_cast<accuracy::Measure>(i)) << " " << m[i];
    return text.str();
}

// How the points were timed: their common note, or all the notes when they differ (a resumed sweep).
std::string timingNote(const std::vector<accuracy::PointResult>& points) {
    std::vector<std::string> notes;
    for (const accuracy::PointResult& p : points)
        if (std::find(notes.begin(), notes.end(), p.timing) == notes.end()) notes.push_back(p.timing);
    std::string text;
    for (const std::string& note : notes) text += (text.empty() ? "" : "; some ") + note;
    return text;
}

int finishReport(const Options& options, const simcore::Scene& scene, const accuracy::SweepPlan& plan,
                 const accuracy::Reference& reference, std::vector<accuracy::PointResult> points, const fs::path& dir) {
    accuracy::SweepReport report;
    report.plan = &plan;
    report.reference = &reference;
    report.points = std::move(points);
    report.labels = accuracy::pointLabels(scene, report.points);
    report.fronts = accuracy::fronts(report.points);
    report.timingNote = timingNote(report.points);
    const std::string advice = accuracy::recommendation(report, options.target, options.targetLimit);
    if (auto error = accuracy::writeReport(dir, report, advice)) return complain(*error, kBadArguments);
    std::cerr << "reference " << reference.msPerStep << " ms/step; its distance from a run with half its time step: "
              << measureSummary(reference.convergence) << "\n"
              << "timings: " << report.timingNote << "\n"
              << "wrote " << (dir / "sweep.csv").string() << ", sweep.json, sweep.md and " << accuracy::kMeasureCount
              << " plots\n";
    std::cout << advice << '\n';
    return kSuccess;
}

int merge(const Options& options) {
    const fs::path dir = options.mergeDir;
    std::string error;
    const std::optional<accuracy::SweepPlan> plan = accuracy::readPlan(accuracy::planPath(dir), error);
    if (!plan) return complain(error, kCorruptResult);
    simcore::SceneLoadResult loaded = loadScene(plan->scenePath);
    for (const simcore::Diagnostic& d : loaded.diagnostics) std::cerr << d.toString() << '\n';
    if (!loaded.ok()) return kUnreadableScene;
    const std::optional<accuracy::Reference> reference = accuracy::readReference(accuracy::referencePath(dir), plan->key, error);
    if (!reference) return complain(error, kCorruptResult);
    std::vector<accuracy::PointResult> points;
    std::vector<std::string> missing;
    for (const accuracy::GridPoint& point : plan->grid) {
        const fs::path file = accuracy::pointPath(dir, point);
        if (!fs::exists(file)) {
            missing.push_back(point.id);
            continue;
        }
        std::optional<accuracy::PointResult> result = accuracy::readPoint(file, plan->key, error);
        if (!result) return complain(error, kCorruptResult);
        points.push_back(std::move(*result));
    }
    if (!missing.empty())
        return complain(std::to_string(missing.size()) + " of " + std::to_string(plan->grid.size()) +
                            " points have no result in " + (dir / "points").string() + " yet (the first: " + missing.front() +
                            "): run their jobs, then merge again",
                        kIncomplete);
    return finishReport(options, *loaded.scene, *plan, *reference, std::move(points), dir);
}

int run(Options options) {
    simcore::SceneLoadResult loaded = loadScene(options.scenePath);
    for (const simcore::Diagnostic& d : loaded.diagnostics) std::cerr << d.toString() << '\n';
    if (!loaded.ok()) return kUnreadableScene;
    const simcore::Scene& scene = *loaded.scene;

    accuracy::SweepPlan plan;
    plan.scenePath = options.scenePath;
    plan.spec.knobs = options.knobsGiven ? options.knobs : accuracy::defaultKnobs();
    if (!options.point.empty()) {
        // One point of the grid: the knobs are its assignments, one value each.
        plan.spec.knobs.clear();
        for (const std::string& a : options.point) plan.spec.knobs.push_back({a.substr(0, a.find('=')), {a.substr(a.find('=') + 1)}});
    }
    plan.spec.seconds = options.seconds.value_or(plan.spec.seconds);
    plan.spec.sampleRate = options.sampleRate.value_or(plan.spec.sampleRate);
    plan.spec.reference = options.reference;
    if (auto error = accuracy::checkSpec(scene, plan.spec)) return complain(*error, kBadArguments);
    if (!options.knobsGiven && options.point.empty()) plan.spec.extraPoints = accuracy::effectToggles(scene, plan.spec);
    plan.grid = accuracy::gridPoints(plan.spec);
    plan.key = accuracy::sweepKey(scene, plan.spec);

    const fs::path dir = !options.outDir.empty() ? fs::path(options.outDir)
                                                 : fs::path("sweep-" + fs::path(options.scenePath).stem().string());
    std::signal(SIGINT, onInterrupt);
    if (auto error = preparePlan(dir, plan, options.point.empty())) return complain(*error, kBadArguments);
    const int jobs = options.jobs == 0 ? static_cast<int>(std::max(1u, std::thread::hardware_concurrency())) : options.jobs;
    int code = kSuccess;
    const std::optional<accuracy::Reference> reference = prepareReference(scene, plan, dir, jobs, code);
    if (!reference) return code;

    if (!options.emitJobsPath.empty()) {
        std::string commands;
        for (const accuracy::GridPoint& point : plan.grid) commands += jobCommand(plan, dir, point) + "\n";
        if (auto error = accuracy::writeFileAtomically(options.emitJobsPath, commands)) return complain(*error, kBadArguments);
        std::cerr << "wrote " << plan.grid.size() << " commands to " << options.emitJobsPath
                  << "; run them (docs/sweep.md), then: interplay-sweep --merge " << dir.string() << '\n';
        return kSuccess;
    }

    // Results already in DIR are kept (resuming); each new one is written as soon as it is done.
    std::string writeError;
    accuracy::SweepRunOptions runOptions;
    runOptions.jobs = jobs;
    runOptions.cancel = &interrupted;
    runOptions.lookup = [&](const accuracy::GridPoint& point) -> std::optional<accuracy::PointResult> {
        const fs::path file = accuracy::pointPath(dir, point);
        if (!fs::exists(file)) return std::nullopt;
        std::string error;
        std::optional<accuracy::PointResult> known = accuracy::readPoint(file, plan.key, error);
        if (!known) std::cerr << "\ninterplay-sweep: " << error << "; running the point again\n";
        return known;
    };
    runOptions.timing =
        !options.point.empty() ? "each point timed by its own job (how many ran at once was the job runner's choice)"
        : runOptions.jobs == 1 ? "one point at a time"
                               : std::to_string(runOptions.jobs) + " points at a time on " +
                                     std::to_string(std::thread::hardware_concurrency()) +
                                     " hardware threads: noisier than --jobs 1";
    runOptions.finished = [&](const accuracy::PointResult& result) {
        if (auto error = accuracy::writeFileAtomically(accuracy::pointPath(dir, result.point),
                                                       accuracy::pointJson(result, plan.key).dump(2) + "\n"))
            writeError = *error;
    };
    const bool terminal = ::isatty(STDERR_FILENO) != 0;
    runOptions.progress = [&](const accuracy::SweepProgress& p) {
        if (!options.point.empty()) return;
        const double left = p.elapsedSeconds / static_cast<double>(p.done) * static_cast<double>(p.total - p.done);
        if (terminal || p.done == p.total || p.done % std::max<std::size_t>(1, p.total / 10) == 0)
            std::fprintf(stderr, "%s[%zu/%zu points] %.1f s, about %.0f s left%s", terminal ? "\r" : "", p.done, p.total,
                         p.elapsedSeconds, left, terminal && p.done < p.total ? "" : "\n");
    };
    std::vector<accuracy::PointResult> points = accuracy::runSweep(scene, plan.spec, plan.grid, *reference, runOptions);
    if (!writeError.empty()) return complain(writeError, kBadArguments);
    if (interrupted)
        return complain("interrupted: " + std::to_string(points.size()) + " of " + std::to_string(plan.grid.size()) +
                            " points are in " + (dir / "points").string() + "; run the same command again to resume",
                        kInterrupted);
    if (!options.point.empty()) return kSuccess;
    return finishReport(options, scene, plan, *reference, std::move(points), dir);
}

}  // namespace

int main(int argc, char** argv) {
    const ParseResult parsed = parseArguments({argv + 1, argv + argc});
    if (parsed.options.help) {
        std::cout << usageText();
        return kSuccess;
    }
    if (!parsed.error.empty()) {
        std::cerr << "interplay-sweep: " << parsed.error << "\n\n" << usageText();
        return kBadArguments;
    }
    try {
        return parsed.options.mergeDir.empty() ? run(parsed.options) : merge(parsed.options);
    } catch (const std::exception& e) {
        // The loader and checkSpec validate what the world checks, so this would be a gap in them.
        return complain(std::string("error: ") + e.what(), kUnreadableScene);
    }
}
