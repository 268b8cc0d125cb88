// interplay-bench-accuracy: what accuracy costs in time. For each reference scene (a closed-form
// answer, or a converged run to compare with) it sweeps a grid of the accuracy knobs, measures the
// error and the wall time of the stepping loop, finds the Pareto front (least error for the cost),
// and writes a Markdown report, a CSV of every point and one SVG plot per scene. See usageText().
//
// Cost is wall milliseconds per simulated second (the time step varies across the grid, so a
// smaller step costs more steps for the same simulated time); ms per step is reported beside it.
// Only World::step calls are timed; each point is the best of a few runs (fewer when a run is
// long), single-threaded, on whatever else the machine is doing: the report records the load.

#include "reference_scenes.h"
#include "accuracy/svg_plot.h"
#include "sweep.h"

#include "simcore/io/scene_io.h"
#include "simcore/world/quality_preset.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#ifndef INTERPLAY_SOURCE_DIR
#define INTERPLAY_SOURCE_DIR "."
#endif
#ifndef INTERPLAY_BUILD_TYPE
#define INTERPLAY_BUILD_TYPE "unknown"
#endif

namespace {

namespace fs = std::filesystem;
using accuracy::Knobs;
using accuracy::Point;
using accuracy::ReferenceKind;
using accuracy::ReferenceScene;
using Clock = std::chrono::steady_clock;

const char* usageText() {
    return "usage: interplay-bench-accuracy [--quick] [--out DIR] [--scene NAME]...\n"
           "       interplay-bench-accuracy --save-scenes DIR [--scene NAME]...\n"
           "\n"
           "Sweeps the accuracy knobs (time step, substeps, velocity and position iterations, position\n"
           "correction, integrator, contact/joint stiffness, the scene's relevant effects) over reference\n"
           "scenes with\n"
           "known answers and writes error against wall ms per simulated second, with the Pareto front:\n"
           "DIR/accuracy.md, DIR/accuracy.csv and DIR/accuracy-<scene>.svg.\n"
           "\n"
           "  --quick       a small grid and shorter runs, a smoke test (under 20 s); default DIR is\n"
           "                ./accuracy-quick so the published results are not overwritten\n"
           "  --out DIR     where to write (default: bench/results in the source tree)\n"
           "  --scene NAME  run only this scene; repeatable. Names: incline-slide, rolling-sphere,\n"
           "                pendulum, elastic-collision, tumbling, tower-drift, pyramid-drift,\n"
           "                mass-ratio-sink, chain-joint-error, pile-penetration\n"
           "  --save-scenes DIR  writes each scene as built, before its first step, to DIR/NAME.json (a\n"
           "                scene file, for interplay-sweep) and prints 'NAME.json SECONDS' per scene (the\n"
           "                simulated time the full sweep runs it for), then exits\n";
}

struct Options {
    bool quick = false;
    fs::path out;
    fs::path saveScenes;  // --save-scenes DIR
    std::vector<std::string> scenes;
};

std::string fmt(const char* format, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

std::string errorText(double error) {
    if (!std::isfinite(error)) return "failed";
    if (error == 0.0) return "0";
    return fmt("%.3g", error);
}

std::string costText(double ms) { return fmt(ms < 1.0 ? "%.4f" : ms < 100.0 ? "%.3f" : "%.1f", ms); }

std::string firstLineOf(const fs::path& path, const std::string& prefix) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(prefix, 0) == 0) return line.substr(line.find_first_not_of(" \t", line.find(':') + 1));
    return "";
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    double one = 0.0, five = 0.0, fifteen = 0.0;
    if (!(in >> one >> five >> fifteen)) return "unknown";
    return fmt("%.2f", one) + " / " + fmt("%.2f", five) + " / " + fmt("%.2f", fifteen);
}

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    return buffer;
}

std::string knobsText(const Knobs& k) {
    const simcore::WorldSettings s = k.applyTo(simcore::WorldSettings{});
    std::string text = "dt 1/" + std::to_string(std::lround(1.0 / static_cast<double>(s.timeStep))) + " s, " +
                       std::to_string(s.substeps) + " substeps, " + std::to_string(s.solver.velocityIterations) +
                       " velocity + " + std::to_string(s.solver.positionIterations) + " relax iterations, " +
                       std::string(simcore::positionCorrectionName(s.solver.positionCorrection)) + ", " +
                       std::string(simcore::integratorName(s.integrator));
    const float cap = static_cast<float>(s.substeps) / s.timeStep / 4.0f;
    text += ", contacts " + fmt("%.0f", static_cast<double>(std::min(s.solver.contactHertz, cap))) + " Hz, joints " +
            fmt("%.0f", static_cast<double>(std::min(s.joint.hertz, cap))) + " Hz";
    return text;
}

// Errors below this are float rounding at the scenes' scale (positions of metres, relative errors).
constexpr double kFloatResolution = 1e-6;

// Timing: the best of up to kMaxRepeats runs, another only while the runs so far took less than
// kRepeatBudgetMs in all (long runs are less disturbed by other work, and are what costs time).
constexpr int kMaxRepeats = 5;
constexpr double kRepeatBudgetMs = 300.0;

// One scene's sweep and what the report needs from it.
struct SceneResult {
    const ReferenceScene* scene = nullptr;
    std::vector<Point> points;
    std::vector<std::size_t> front;
    double convergedError = 0.0;        // ClosedForm: the converged run's own error
    double convergenceCheck = 0.0;      // ConvergedRun: the coarser run's distance from the reference
    double convergedMsPerSecond = 0.0;  // cost of the converged run
    double errorFloor = 0.0;            // errors below this are not resolved (see aggregate())
    bool referenceFailed = false;       // the converged run went non-finite: no error can be measured
    bool allDeterministic = true;
    double wallSeconds = 0.0;
};

SceneResult sweepScene(const ReferenceScene& scene, bool quick) {
    const auto start = Clock::now();
    SceneResult result;
    result.scene = &scene;
    const double seconds = quick ? scene.quickSeconds : scene.seconds;
    const int maxRepeats = quick ? 1 : kMaxRepeats;

    const accuracy::Measurement converged =
        accuracy::measure(scene, accuracy::convergedKnobs(quick).applyTo(scene.base), seconds, 1, 0.0);
    const accuracy::Observation* reference =
        scene.reference == ReferenceKind::ConvergedRun ? &converged.observation : nullptr;
    result.convergedMsPerSecond = converged.bestMs / seconds;
    if (scene.reference == ReferenceKind::ConvergedRun) {
        result.referenceFailed = !converged.observation.finite;
        const accuracy::Measurement check =
            accuracy::measure(scene, accuracy::convergenceCheckKnobs(quick).applyTo(scene.base), seconds, 1, 0.0);
        result.convergenceCheck = check.observation.finite && !result.referenceFailed
                                      ? scene.error(check.observation, reference)
                                      : std::numeric_limits<double>::infinity();
    } else {
        result.convergedError = converged.observation.finite ? scene.error(converged.observation, nullptr)
                                                             : std::numeric_limits<double>::infinity();
    }

    std::vector<Knobs> knobs = accuracy::sweepGrid(scene, quick);
    std::vector<simcore::WorldSettings> settings;
    for (const Knobs& k : knobs) settings.push_back(k.applyTo(scene.base));
    std::vector<std::vector<std::string>> presetNames(knobs.size());
    for (simcore::QualityPreset preset : simcore::kQualityPresets) {
        Knobs k;
        k.preset = preset;
        const simcore::WorldSettings s = k.applyTo(scene.base);
        const auto same = std::find(settings.begin(), settings.end(), s);
        const std::size_t index = static_cast<std::size_t>(same - settings.begin());
        if (same == settings.end()) {
            knobs.push_back(k);
            settings.push_back(s);
            presetNames.emplace_back();
        }
        presetNames[index].emplace_back(simcore::qualityPresetName(preset));
    }

    for (std::size_t i = 0; i < knobs.size(); ++i) {
        const accuracy::Measurement m = accuracy::measure(scene, settings[i], seconds, maxRepeats, kRepeatBudgetMs);
        Point p;
        p.knobs = knobs[i];
        p.label = knobs[i].label();
        p.presets = presetNames[i];
        p.error = m.observation.finite && !result.referenceFailed ? scene.error(m.observation, reference)
                                                                   : std::numeric_limits<double>::infinity();
        if (std::isnan(p.error)) p.error = std::numeric_limits<double>::infinity();
        const double simulated = m.steps * static_cast<double>(settings[i].timeStep);
        p.msPerSimulatedSecond = m.bestMs / simulated;
        p.msPerStep = m.bestMs / m.steps;
        p.steps = m.steps;
        p.repeats = m.repeats;
        result.allDeterministic = result.allDeterministic && m.deterministic;
        result.points.push_back(std::move(p));
    }
    result.front = accuracy::markParetoFront(result.points);
    result.errorFloor = std::max(kFloatResolution, result.convergenceCheck);
    result.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
}

const Point* presetPoint(const SceneResult& r, simcore::QualityPreset preset) {
    const std::string name(simcore::qualityPresetName(preset));
    for (const Point& p : r.points)
        if (std::find(p.presets.begin(), p.presets.end(), name) != p.presets.end()) return &p;
    return nullptr;
}

std::string pointRow(const Point& p) {
    std::string presets;
    for (const std::string& name : p.presets) presets += (presets.empty() ? "" : ", ") + ("**" + name + "**");
    return "| " + std::string(p.onFront ? "★ " : "") + p.label + " | " + costText(p.msPerStep) + " | " +
           costText(p.msPerSimulatedSecond) + " | " + errorText(p.error) + " | " + presets + " |\n";
}

// Across scenes: for every knob setting all scenes ran (effects as the scene has them), the
// geometric means over scenes of cost and error relative to the defaults, and the worst error ratio.
// Errors are raised to the scene's floor first, so that a change below what can be resolved (float
// rounding, or the converged run's own uncertainty) does not count as a large ratio.
struct Aggregate {
    std::string label;
    double costRatio = 1.0;
    double errorRatio = 1.0;
    double worstErrorRatio = 1.0;
    std::vector<std::string> presets;
    bool onFront = false;
};

std::vector<Aggregate> aggregate(const std::vector<SceneResult>& results) {
    std::map<std::string, std::vector<const Point*>> byLabel;  // points in the order of `results`
    std::vector<const Point*> defaults;
    const std::string defaultLabel = Knobs{}.label();
    for (const SceneResult& r : results) {
        for (const Point& p : r.points) {
            if (p.knobs.switchedOff) continue;
            byLabel[p.label].push_back(&p);
            if (p.label == defaultLabel) defaults.push_back(&p);
        }
    }
    std::vector<Aggregate> out;
    if (defaults.size() != results.size()) return out;
    for (const auto& [label, points] : byLabel) {
        if (points.size() != results.size()) continue;
        Aggregate a;
        a.label = label;
        a.presets = points.front()->presets;
        double logCost = 0.0, logError = 0.0, worst = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double floor = results[i].errorFloor;
            const double ratio = std::max(points[i]->error, floor) / std::max(defaults[i]->error, floor);
            logCost += std::log(points[i]->msPerSimulatedSecond / defaults[i]->msPerSimulatedSecond);
            logError += std::log(ratio);
            worst = std::max(worst, ratio);
        }
        const double n = static_cast<double>(points.size());
        a.costRatio = std::exp(logCost / n);
        a.errorRatio = std::exp(logError / n);
        a.worstErrorRatio = worst;
        out.push_back(std::move(a));
    }
    std::sort(out.begin(), out.end(), [](const Aggregate& a, const Aggregate& b) { return a.costRatio < b.costRatio; });
    double best = std::numeric_limits<double>::infinity();
    for (Aggregate& a : out) {
        if (std::isfinite(a.errorRatio) && a.errorRatio < best) {
            best = a.errorRatio;
            a.onFront = true;
        }
    }
    return out;
}

std::string sceneSection(const SceneResult& r, bool quick) {
    const ReferenceScene& s = *r.scene;
    std::ostringstream md;
    md << "## " << s.title << " (`" << s.name << "`)\n\n";
    md << s.setup << " " << fmt("%.1f", quick ? s.quickSeconds : s.seconds) << " s simulated per run.\n\n";
    md << "- **Error:** " << s.metric << ".\n";
    if (r.referenceFailed) md << "- **The converged run failed (non-finite state): no error could be measured.**\n";
    if (s.reference == ReferenceKind::ClosedForm) {
        md << "- **Exact answer:** " << s.answer << ". The converged run (" << knobsText(accuracy::convergedKnobs(quick))
           << ", " << costText(r.convergedMsPerSecond) << " ms per simulated s) has error " << errorText(r.convergedError)
           << ": the method's floor.\n";
    } else {
        md << "- **Reference:** a converged run (" << knobsText(accuracy::convergedKnobs(quick)) << ", "
           << costText(r.convergedMsPerSecond) << " ms per simulated s), compared on " << s.answer
           << ". A coarser run (" << knobsText(accuracy::convergenceCheckKnobs(quick)) << ") is "
           << errorText(r.convergenceCheck) << " from it: errors near that are not resolved.\n";
    }
    if (!s.toggles.empty()) {
        md << "- **Effects switched off in the sweep:** ";
        for (std::size_t i = 0; i < s.toggles.size(); ++i) md << (i ? ", " : "") << simcore::effectName(s.toggles[i]);
        md << ".\n";
    }
    std::size_t failed = 0;
    for (const Point& p : r.points) failed += std::isfinite(p.error) ? 0 : 1;
    md << "- " << r.points.size() << " points, " << r.front.size() << " on the front, " << failed
       << " failed (non-finite state, or no period to measure)"
       << (r.allDeterministic ? "" : "; **some repeats observed different numbers**") << "; sweep took "
       << fmt("%.1f", r.wallSeconds) << " s.\n\n";
    md << "![" << s.title << ": error against cost](accuracy-" << s.name << ".svg)\n\n";
    md << "The front (cheapest first) and the presets:\n\n";
    md << "| knobs | ms/step | ms per simulated s | error | preset |\n|---|--:|--:|--:|---|\n";
    for (const Point& p : r.points)
        if (!p.onFront && !p.presets.empty()) md << pointRow(p);
    for (std::size_t i : r.front) md << pointRow(r.points[i]);
    std::vector<const Point*> byCost;
    for (const Point& p : r.points) byCost.push_back(&p);
    std::sort(byCost.begin(), byCost.end(),
              [](const Point* a, const Point* b) { return a->msPerSimulatedSecond < b->msPerSimulatedSecond; });
    md << "\n<details><summary>All " << r.points.size() << " points, cheapest first (★ on the front)</summary>\n\n";
    md << "| knobs | ms/step | ms per simulated s | error | preset |\n|---|--:|--:|--:|---|\n";
    for (const Point* p : byCost) md << pointRow(*p);
    md << "\n</details>\n\n";
    return md.str();
}

int run(const Options& options) {
    std::vector<ReferenceScene> all = accuracy::referenceScenes();
    std::vector<const ReferenceScene*> chosen;
    for (const ReferenceScene& s : all)
        if (options.scenes.empty() || std::find(options.scenes.begin(), options.scenes.end(), s.name) != options.scenes.end())
            chosen.push_back(&s);
    for (const std::string& name : options.scenes) {
        if (std::none_of(all.begin(), all.end(), [&](const ReferenceScene& s) { return s.name == name; })) {
            std::cerr << "interplay-bench-accuracy: unknown scene '" << name << "'\n" << usageText();
            return 2;
        }
    }
    const fs::path& dir = options.saveScenes.empty() ? options.out : options.saveScenes;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        std::cerr << "interplay-bench-accuracy: cannot create " << dir << ": " << ec.message() << '\n';
        return 2;
    }
    if (!options.saveScenes.empty()) {
        for (const ReferenceScene* s : chosen) {
            const std::string file = s->name + ".json";
            if (auto error = simcore::saveSceneFile(accuracy::sceneFile(*s), dir / file)) {
                std::cerr << "interplay-bench-accuracy: " << *error << '\n';
                return 2;
            }
            std::cout << file << ' ' << s->seconds << '\n';
        }
        return 0;
    }

    const auto start = Clock::now();
    const std::string loadBefore = loadAverage();
    std::vector<SceneResult> results;
    for (const ReferenceScene* s : chosen) {
        std::cerr << "sweeping " << s->name << " ..." << std::flush;
        results.push_back(sweepScene(*s, options.quick));
        std::cerr << " " << results.back().points.size() << " points, " << fmt("%.1f", results.back().wallSeconds) << " s\n";
    }
    const double totalSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    const std::string loadAfter = loadAverage();

    std::ostringstream md;
    md << "# Accuracy against time" << (options.quick ? " (quick grid)" : "") << "\n\n";
    md << "Written by `interplay-bench-accuracy" << (options.quick ? " --quick" : "") << "` on " << utcNow() << ": "
       << firstLineOf("/proc/cpuinfo", "model name") << ", " << std::thread::hardware_concurrency()
       << " hardware threads, build type " << INTERPLAY_BUILD_TYPE << ", single-threaded. Whole run "
       << fmt("%.1f", totalSeconds) << " s. Load average (1/5/15 min) " << loadBefore << " before, " << loadAfter
       << " after: other work on the machine slows some points, which best-of-N timing only partly hides.\n\n";
    md << "**Cost** is wall milliseconds of the `World::step` calls per simulated second (the time step varies across the "
          "grid, so per step alone would flatter small steps); ms per step is given too. Each point is the best of up to "
       << (options.quick ? 1 : kMaxRepeats) << " runs (another only while the runs so far took under "
       << fmt("%.0f", kRepeatBudgetMs) << " ms in all). **Error** is per scene, against a closed form "
          "or a converged run, as each section says. The **Pareto front** (★, blue line) holds the points no other point "
          "beats on both error and cost; failed runs are never on it.\n\n";
    md << "**Grid** (per scene): time step 1/30, 1/60, 1/120, 1/240 s × 1, 2, 4, 8 substeps × {velocity iterations 1, 2, "
          "4, 8 with 1 relax pass; 2 iterations with 0 or 2 relax passes; Baumgarte at 2 and 8 iterations}; contacts and "
          "joints at the stiffness cap (a quarter of the substep rate instead of 60 Hz) at 2 and 4 iterations where the "
          "cap is above 60 Hz; the explicit Euler and velocity Verlet integrators (instead of semi-implicit Euler) at the default solver "
          "settings; each of the scene's relevant effects switched off at the default solver settings. GJK/EPA "
          "tolerances are not swept.";
    if (options.quick) md << " **This is the quick grid**: fewer points and shorter runs, for a smoke test.";
    md << "\n\n";

    // Presets.
    md << "## Quality presets\n\n";
    md << "Named points of the front (`simcore/world/quality_preset.h`): a scene selects one with `\"preset\"` in its "
          "settings (applied first; the scene's explicit keys override it), the runner with `--preset NAME`. Balanced "
          "is the engine's defaults.\n\n";
    md << "| preset | knobs |\n|---|---|\n";
    for (simcore::QualityPreset preset : simcore::kQualityPresets) {
        Knobs k;
        k.preset = preset;
        md << "| **" << simcore::qualityPresetName(preset) << "** | " << knobsText(k) << " |\n";
    }
    md << "\nMeasured per scene: ms per step, ms per simulated second (the fair comparison when the presets' "
          "time steps differ), and the error in the scene's unit (★ = on that scene's front):\n\n";
    md << "| scene |";
    for (simcore::QualityPreset preset : simcore::kQualityPresets) {
        const std::string_view name = simcore::qualityPresetName(preset);
        md << " " << name << " ms/step | " << name << " ms/sim s | " << name << " error |";
    }
    md << "\n|---|";
    for (std::size_t i = 0; i < simcore::kQualityPresets.size(); ++i) md << "--:|--:|--:|";
    md << "\n";
    for (const SceneResult& r : results) {
        md << "| " << r.scene->name << " |";
        for (simcore::QualityPreset preset : simcore::kQualityPresets) {
            const Point* p = presetPoint(r, preset);
            md << " " << costText(p->msPerStep) << " | " << costText(p->msPerSimulatedSecond) << " | "
               << (p->onFront ? "★ " : "") << errorText(p->error) << " |";
        }
        md << "\n";
    }
    md << "\n";

    const std::vector<Aggregate> aggregates = aggregate(results);
    if (!aggregates.empty()) {
        md << "## Across all scenes\n\n";
        md << "For each knob setting every scene ran (effects as the scene has them): the geometric mean over the "
           << results.size() << " scenes of cost and of error relative to the defaults (balanced), and the worst "
              "scene's error ratio. Errors below a scene's resolution count as that resolution: "
           << fmt("%.0e", kFloatResolution)
           << " (float rounding), or for scenes against a converged run the coarser run's distance from it. The "
              "presets are picked from this front. Front and presets, cheapest first:\n\n";
        md << "| knobs | cost / default | error / default (geometric mean) | worst scene's error / default | preset |\n"
              "|---|--:|--:|--:|---|\n";
        for (const Aggregate& a : aggregates) {
            if (!a.onFront && a.presets.empty()) continue;
            std::string presets;
            for (const std::string& name : a.presets) presets += (presets.empty() ? "" : ", ") + ("**" + name + "**");
            md << "| " << (a.onFront ? "★ " : "") << a.label << " | " << fmt("%.2f", a.costRatio) << " | "
               << fmt("%.3g", a.errorRatio) << " | " << fmt("%.3g", a.worstErrorRatio) << " | " << presets << " |\n";
        }
        md << "\n";
    }

    for (const SceneResult& r : results) md << sceneSection(r, options.quick);

    // Files: the report, every point as CSV, one plot per scene.
    std::ostringstream csv;
    csv << "scene,knobs,timeStep,substeps,velocityIterations,positionIterations,positionCorrection,integrator,stiff,"
           "switchedOff,"
           "presets,error,msPerSimulatedSecond,msPerStep,steps,repeats,onFront\n";
    for (const SceneResult& r : results) {
        for (const Point& p : r.points) {
            const simcore::WorldSettings s = p.knobs.applyTo(r.scene->base);
            std::string presets;
            for (const std::string& name : p.presets) presets += (presets.empty() ? "" : " ") + name;
            csv << r.scene->name << ",\"" << p.label << "\"," << fmt("%.9g", static_cast<double>(s.timeStep)) << ','
                << s.substeps << ',' << s.solver.velocityIterations << ',' << s.solver.positionIterations << ','
                << simcore::positionCorrectionName(s.solver.positionCorrection) << ','
                << simcore::integratorName(s.integrator) << ',' << (p.knobs.stiff ? 1 : 0) << ','
                << (p.knobs.switchedOff ? simcore::effectName(*p.knobs.switchedOff) : "") << ',' << presets << ','
                << fmt("%.6g", p.error) << ',' << fmt("%.6g", p.msPerSimulatedSecond) << ',' << fmt("%.6g", p.msPerStep)
                << ',' << p.steps << ',' << p.repeats << ',' << (p.onFront ? 1 : 0) << '\n';
        }
        accuracy::Plot plot;
        plot.title = r.scene->title;
        plot.subtitle = r.scene->metric;
        plot.xLabel = "cost: wall ms of World::step per simulated second (log scale)";
        plot.yLabel = r.scene->errorAxis + " (log scale)";
        for (const Point& p : r.points) plot.points.push_back({p.msPerSimulatedSecond, p.error, p.onFront, p.presets});
        std::ofstream(options.out / ("accuracy-" + r.scene->name + ".svg")) << accuracy::renderSvg(plot);
    }
    std::ofstream(options.out / "accuracy.csv") << csv.str();
    std::ofstream report(options.out / "accuracy.md");
    report << md.str();
    if (!report) {
        std::cerr << "interplay-bench-accuracy: cannot write " << (options.out / "accuracy.md") << '\n';
        return 2;
    }
    std::cout << md.str();
    std::cerr << "wrote " << (options.out / "accuracy.md") << ", accuracy.csv and " << results.size() << " plots in "
              << fmt("%.1f", totalSeconds) << " s\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    bool outGiven = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            std::cout << usageText();
            return 0;
        }
        if (arg == "--quick") {
            options.quick = true;
        } else if ((arg == "--out" || arg == "--scene" || arg == "--save-scenes") && i + 1 < argc) {
            if (arg == "--out") {
                options.out = argv[++i];
                outGiven = true;
            } else if (arg == "--save-scenes") {
                options.saveScenes = argv[++i];
            } else {
                options.scenes.push_back(argv[++i]);
            }
        } else {
            std::cerr << "interplay-bench-accuracy: bad argument '" << arg << "'\n" << usageText();
            return 2;
        }
    }
    if (!outGiven) options.out = options.quick ? fs::path("accuracy-quick") : fs::path(INTERPLAY_SOURCE_DIR) / "bench" / "results";
    return run(options);
}
