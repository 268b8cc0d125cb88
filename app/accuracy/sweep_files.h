#pragma once
// What a scene sweep keeps on disk and what it reports: the plan (scene, spec, grid), the
// reference, one result file per point (so a sweep can resume, or run as separate jobs and be
// merged), and the tables and plots made from them. Every file is written atomically.

#include "accuracy/scene_sweep.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace accuracy {

// Writes to a temporary file beside `path`, then renames it over `path`: a reader (or an
// interrupted sweep) sees the old file or the new one, never half of one. Returns an error message.
std::optional<std::string> writeFileAtomically(const std::filesystem::path& path, const std::string& text);

// What identifies a sweep's results: the scene as loaded, the duration, sample rate and reference.
// Results in a directory with another key belong to another sweep.
std::string sweepKey(const simcore::Scene& scene, const SweepSpec& spec);

struct SweepPlan {
    std::string scenePath;  // as given on the command line
    std::string key;
    SweepSpec spec;
    std::vector<GridPoint> grid;
};

// DIR/sweep-plan.json, DIR/reference.json, DIR/points/<id>.json.
std::filesystem::path planPath(const std::filesystem::path& dir);
std::filesystem::path referencePath(const std::filesystem::path& dir);
std::filesystem::path pointPath(const std::filesystem::path& dir, const GridPoint& point);

nlohmann::ordered_json planJson(const SweepPlan& plan);
nlohmann::ordered_json referenceJson(const Reference& reference, const std::string& key);
nlohmann::ordered_json pointJson(const PointResult& result, const std::string& key);

// Reading them back: nothing, with `error` saying what is wrong, when the file is missing, not
// JSON, not of its kind, of another sweep (`key` differs) or malformed.
std::optional<SweepPlan> readPlan(const std::filesystem::path& file, std::string& error);
std::optional<Reference> readReference(const std::filesystem::path& file, const std::string& key, std::string& error);
std::optional<PointResult> readPoint(const std::filesystem::path& file, const std::string& key, std::string& error);

// The report, from the points in grid order. `labels[i]` names presets or the scene's own settings
// at point i (may be empty); `timingNote` says how the timings were taken.
struct SweepReport {
    const SweepPlan* plan = nullptr;
    const Reference* reference = nullptr;
    std::vector<PointResult> points;
    std::vector<std::vector<std::string>> labels;
    std::array<std::vector<std::size_t>, kMeasureCount> fronts;
    std::string timingNote;
};
// For each point: "scene" when its settings are the scene's, and the quality presets they equal.
std::vector<std::vector<std::string>> pointLabels(const simcore::Scene& scene, const std::vector<PointResult>& points);

std::string sweepCsv(const SweepReport& report);
nlohmann::ordered_json sweepJson(const SweepReport& report);
std::string measureSvg(const SweepReport& report, Measure measure);
// A Markdown summary: the grid, the reference and its convergence, the recommendation, and per
// measure its front (with the scene's own settings and the presets) beside its plot.
std::string sweepMarkdown(const SweepReport& report, const std::string& recommendationLine);

// "for <= 0.001 m deepest penetration: substeps=4, ... — 0.8 ms/step (48 ms per simulated s)", or
// what comes closest when no point is within the limit.
std::string recommendation(const SweepReport& report, Measure measure, double limit);

// Writes sweep.csv, sweep.json, sweep.md and sweep-<measure>.svg into `dir`. Returns an error message.
std::optional<std::string> writeReport(const std::filesystem::path& dir, const SweepReport& report,
                                       const std::string& recommendationLine);

}  // namespace accuracy
