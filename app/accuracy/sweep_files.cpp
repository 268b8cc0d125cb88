#include "accuracy/sweep_files.h"

#include "accuracy/svg_plot.h"

#include "simcore/io/scene_io.h"
#include "simcore/world/quality_preset.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

namespace accuracy {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

constexpr int kFileVersion = 1;

Json measuresJson(const Measures& m) {
    Json out = Json::object();
    for (std::size_t i = 0; i < kMeasureCount; ++i)
        out[std::string(measureKey(static_cast<Measure>(i)))] = std::isfinite(m[i]) ? Json(m[i]) : Json(nullptr);
    return out;
}

Measures measuresFrom(const Json& j) {
    Measures m{};
    for (std::size_t i = 0; i < kMeasureCount; ++i) {
        const Json& v = j.at(std::string(measureKey(static_cast<Measure>(i))));
        m[i] = v.is_null() ? std::numeric_limits<double>::infinity() : v.get<double>();
    }
    return m;
}

// Reads a JSON file of the given kind ("format" member) and sweep; nothing with `error` set otherwise.
std::optional<Json> readKind(const fs::path& file, std::string_view format, const std::string* key, std::string& error) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        error = file.string() + ": cannot be opened";
        return std::nullopt;
    }
    std::stringstream text;
    text << in.rdbuf();
    Json j = Json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object()) {
        error = file.string() + ": corrupt: not a JSON object";
        return std::nullopt;
    }
    if (!j.contains("format") || j["format"] != format || !j.contains("version") || j["version"] != kFileVersion) {
        error = file.string() + ": corrupt: not an " + std::string(format) + " file of version " + std::to_string(kFileVersion);
        return std::nullopt;
    }
    if (key && (!j.contains("sweep") || j["sweep"] != *key)) {
        error = file.string() + ": belongs to another sweep (another scene, duration, sample rate or reference)";
        return std::nullopt;
    }
    return j;
}

std::vector<std::vector<double>> rows(const Json& j) { return j.get<std::vector<std::vector<double>>>(); }

std::string csvField(const std::string& text) {
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string number(double v) {
    if (!std::isfinite(v)) return "";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);  // reads back as the same double
    return buffer;
}

std::string shortNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return buffer;
}

// Whether the point is one of the knobs' product (else an extra point over the scene's settings).
bool inProduct(const SweepPlan& plan, const GridPoint& point) {
    return point.assignments.size() == plan.spec.knobs.size() &&
           std::equal(point.assignments.begin(), point.assignments.end(), plan.spec.knobs.begin(),
                      [](const std::string& a, const Knob& k) { return a.compare(0, a.find('='), k.key) == 0; });
}

bool onFront(const SweepReport& report, std::size_t measure, std::size_t point) {
    const std::vector<std::size_t>& f = report.fronts[measure];
    return std::find(f.begin(), f.end(), point) != f.end();
}

// "timeStep=0.0166666675" reads better as "timeStep=1/60 s".
std::string knobText(const std::string& assignment) {
    const std::size_t eq = assignment.find('=');
    if (assignment.compare(0, eq, "timeStep") == 0) {
        const double step = std::strtod(assignment.c_str() + eq + 1, nullptr);
        const double rate = 1.0 / step;
        if (step > 0.0 && std::abs(rate - std::round(rate)) < 1e-4 * rate)
            return "timeStep=1/" + std::to_string(std::lround(rate)) + " s";
    }
    return assignment;
}

}  // namespace

std::optional<std::string> writeFileAtomically(const fs::path& path, const std::string& text) {
    // Beside the target, so the rename stays on one file system; a random name, so concurrent jobs
    // never share a temporary.
    std::random_device random;
    const fs::path temp = path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(random()));
    std::FILE* f = std::fopen(temp.string().c_str(), "wbx");
    if (!f) return "cannot write " + path.string() + ": cannot create " + temp.string();
    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0 && ::fsync(fileno(f)) == 0;
    ok = std::fclose(f) == 0 && ok;
    std::error_code ec;
    if (ok) fs::rename(temp, path, ec);
    if (!ok || ec) {
        fs::remove(temp, ec);
        return "cannot write " + path.string();
    }
    return std::nullopt;
}

std::string sweepKey(const simcore::Scene& scene, const SweepSpec& spec) {
    std::vector<std::string> parts{simcore::serializeScene(scene), number(spec.seconds), number(spec.sampleRate)};
    parts.insert(parts.end(), spec.reference.begin(), spec.reference.end());
    return pointId(parts);
}

fs::path planPath(const fs::path& dir) { return dir / "sweep-plan.json"; }
fs::path referencePath(const fs::path& dir) { return dir / "reference.json"; }
fs::path pointPath(const fs::path& dir, const GridPoint& point) { return dir / "points" / (point.id + ".json"); }

Json planJson(const SweepPlan& plan) {
    Json knobs = Json::array();
    for (const Knob& k : plan.spec.knobs) knobs.push_back({{"key", k.key}, {"values", k.values}});
    Json grid = Json::array();
    for (const GridPoint& p : plan.grid) grid.push_back({{"id", p.id}, {"knobs", p.assignments}});
    return {{"format", "interplay.sweep-plan"}, {"version", kFileVersion},  {"sweep", plan.key},
            {"scene", plan.scenePath},          {"seconds", plan.spec.seconds}, {"sampleRate", plan.spec.sampleRate},
            {"reference", plan.spec.reference}, {"knobs", knobs},           {"points", grid}};
}

Json referenceJson(const Reference& r, const std::string& key) {
    return {{"format", "interplay.sweep-reference"},
            {"version", kFileVersion},
            {"sweep", key},
            {"knobs", r.assignments},
            {"convergence", measuresJson(r.convergence)},
            {"msPerStep", r.msPerStep},
            {"steps", r.run.steps},
            {"timeStep", r.run.timeStep},
            {"penetration", r.run.penetration},
            {"jointError", r.run.jointError},
            {"positions", r.run.positions},
            {"orientations", r.run.orientations},
            {"energy", r.run.energy},
            {"momentum", r.run.momentum}};
}

Json pointJson(const PointResult& p, const std::string& key) {
    return {{"format", "interplay.sweep-point"}, {"version", kFileVersion},
            {"sweep", key},                      {"id", p.point.id},
            {"knobs", p.point.assignments},      {"failed", p.failed},
            {"measures", measuresJson(p.measures)}, {"steps", p.steps},
            {"msPerStep", p.msPerStep},          {"msPerSimulatedSecond", p.msPerSimulatedSecond},
            {"timing", p.timing}};
}

std::optional<SweepPlan> readPlan(const fs::path& file, std::string& error) {
    const std::optional<Json> j = readKind(file, "interplay.sweep-plan", nullptr, error);
    if (!j) return std::nullopt;
    try {
        SweepPlan plan;
        plan.key = j->at("sweep").get<std::string>();
        plan.scenePath = j->at("scene").get<std::string>();
        plan.spec.seconds = j->at("seconds").get<double>();
        plan.spec.sampleRate = j->at("sampleRate").get<double>();
        plan.spec.reference = j->at("reference").get<std::vector<std::string>>();
        for (const Json& k : j->at("knobs"))
            plan.spec.knobs.push_back({k.at("key").get<std::string>(), k.at("values").get<std::vector<std::string>>()});
        for (const Json& p : j->at("points")) {
            GridPoint point{p.at("knobs").get<std::vector<std::string>>(), p.at("id").get<std::string>()};
            if (point.id != pointId(point.assignments)) throw std::runtime_error("point " + point.id + " has another's knobs");
            plan.grid.push_back(std::move(point));
        }
        return plan;
    } catch (const std::exception& e) {
        error = file.string() + ": corrupt: " + e.what();
        return std::nullopt;
    }
}

std::optional<Reference> readReference(const fs::path& file, const std::string& key, std::string& error) {
    const std::optional<Json> j = readKind(file, "interplay.sweep-reference", &key, error);
    if (!j) return std::nullopt;
    try {
        Reference r;
        r.assignments = j->at("knobs").get<std::vector<std::string>>();
        r.convergence = measuresFrom(j->at("convergence"));
        r.msPerStep = j->at("msPerStep").get<double>();
        r.run.steps = j->at("steps").get<std::uint64_t>();
        r.run.timeStep = j->at("timeStep").get<double>();
        r.run.penetration = j->at("penetration").get<double>();
        r.run.jointError = j->at("jointError").get<double>();
        r.run.positions = rows(j->at("positions"));
        r.run.orientations = rows(j->at("orientations"));
        r.run.energy = j->at("energy").get<std::vector<double>>();
        r.run.momentum = j->at("momentum").get<std::vector<std::array<double, 3>>>();
        if (r.run.orientations.size() != r.run.positions.size() || r.run.energy.size() != r.run.positions.size() ||
            r.run.momentum.size() != r.run.positions.size())
            throw std::runtime_error("the sample arrays differ in length");
        return r;
    } catch (const std::exception& e) {
        error = file.string() + ": corrupt: " + e.what();
        return std::nullopt;
    }
}

std::optional<PointResult> readPoint(const fs::path& file, const std::string& key, std::string& error) {
    const std::optional<Json> j = readKind(file, "interplay.sweep-point", &key, error);
    if (!j) return std::nullopt;
    try {
        PointResult p;
        p.point.id = j->at("id").get<std::string>();
        p.point.assignments = j->at("knobs").get<std::vector<std::string>>();
        if (p.point.id != pointId(p.point.assignments) || file.stem() != p.point.id)
            throw std::runtime_error("its id does not match its knobs or its file name");
        p.failed = j->at("failed").get<bool>();
        p.measures = measuresFrom(j->at("measures"));
        p.steps = j->at("steps").get<std::uint64_t>();
        p.msPerStep = j->at("msPerStep").get<double>();
        p.msPerSimulatedSecond = j->at("msPerSimulatedSecond").get<double>();
        p.timing = j->at("timing").get<std::string>();
        return p;
    } catch (const std::exception& e) {
        error = file.string() + ": corrupt: " + e.what();
        return std::nullopt;
    }
}

std::vector<std::vector<std::string>> pointLabels(const simcore::Scene& scene, const std::vector<PointResult>& points) {
    std::vector<std::vector<std::string>> labels(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        simcore::Scene applied = scene;
        for (const std::string& a : points[i].point.assignments) simcore::applySettingOverride(applied, a);
        if (applied.settings == scene.settings) labels[i].push_back("scene");
        for (simcore::QualityPreset preset : simcore::kQualityPresets) {
            simcore::WorldSettings s = scene.settings;
            simcore::applyQualityPreset(s, preset);
            if (applied.settings == s) labels[i].emplace_back(simcore::qualityPresetName(preset));
        }
    }
    return labels;
}

// The keys the points set, the knobs' first: a column each in the CSV.
std::vector<std::string> assignedKeys(const SweepReport& report) {
    std::vector<std::string> keys;
    for (const Knob& k : report.plan->spec.knobs) keys.push_back(k.key);
    for (const PointResult& p : report.points)
        for (const std::string& a : p.point.assignments)
            if (std::find(keys.begin(), keys.end(), a.substr(0, a.find('='))) == keys.end()) keys.push_back(a.substr(0, a.find('=')));
    return keys;
}

std::string sweepCsv(const SweepReport& report) {
    const std::vector<std::string> keys = assignedKeys(report);
    std::ostringstream csv;
    csv << "id";
    for (const std::string& key : keys) csv << ',' << csvField(key);
    csv << ",failed";
    for (std::size_t m = 0; m < kMeasureCount; ++m) csv << ',' << measureKey(static_cast<Measure>(m));
    csv << ",steps,msPerStep,msPerSimulatedSecond";
    for (std::size_t m = 0; m < kMeasureCount; ++m) csv << ",front." << measureKey(static_cast<Measure>(m));
    csv << ",labels\n";
    for (std::size_t i = 0; i < report.points.size(); ++i) {
        const PointResult& p = report.points[i];
        csv << p.point.id;
        for (const std::string& key : keys) {  // empty: the point keeps the scene's value
            std::string value;
            for (const std::string& a : p.point.assignments)
                if (a.compare(0, a.find('='), key) == 0) value = a.substr(a.find('=') + 1);
            csv << ',' << csvField(value);
        }
        csv << ',' << (p.failed ? 1 : 0);
        for (double v : p.measures) csv << ',' << number(v);  // empty: the run failed
        csv << ',' << p.steps << ',' << number(p.msPerStep) << ',' << number(p.msPerSimulatedSecond);
        for (std::size_t m = 0; m < kMeasureCount; ++m) csv << ',' << (onFront(report, m, i) ? 1 : 0);
        std::string labels;
        for (const std::string& l : report.labels[i]) labels += (labels.empty() ? "" : " ") + l;
        csv << ',' << labels << '\n';
    }
    return csv.str();
}

Json sweepJson(const SweepReport& report) {
    Json points = Json::array();
    for (std::size_t i = 0; i < report.points.size(); ++i) {
        const PointResult& p = report.points[i];
        Json front = Json::object();
        for (std::size_t m = 0; m < kMeasureCount; ++m)
            front[std::string(measureKey(static_cast<Measure>(m)))] = onFront(report, m, i);
        points.push_back({{"id", p.point.id},
                          {"knobs", p.point.assignments},
                          {"failed", p.failed},
                          {"measures", measuresJson(p.measures)},
                          {"steps", p.steps},
                          {"msPerStep", p.msPerStep},
                          {"msPerSimulatedSecond", p.msPerSimulatedSecond},
                          {"onFront", front},
                          {"labels", report.labels[i]}});
    }
    const Reference& r = *report.reference;
    return {{"format", "interplay.sweep"},
            {"version", kFileVersion},
            {"scene", report.plan->scenePath},
            {"seconds", report.plan->spec.seconds},
            {"sampleRate", report.plan->spec.sampleRate},
            {"timing", report.timingNote},
            {"reference",
             {{"knobs", r.assignments},
              {"msPerStep", r.msPerStep},
              {"penetration", r.run.penetration},
              {"jointError", r.run.jointError},
              {"convergence", measuresJson(r.convergence)}}},
            {"points", points}};
}

std::string measureSvg(const SweepReport& report, Measure measure) {
    const std::size_t m = static_cast<std::size_t>(measure);
    Plot plot;
    plot.title = fs::path(report.plan->scenePath).filename().string() + ": " + std::string(measureTitle(measure));
    plot.subtitle = "against a reference run (" + std::to_string(report.points.size()) + " points; " + report.timingNote + ")";
    plot.xLabel = "cost: wall ms of World::step per simulated second (log scale)";
    plot.yLabel = std::string(measureTitle(measure)) + " (" + std::string(measureUnit(measure)) + ", log scale)";
    for (std::size_t i = 0; i < report.points.size(); ++i) {
        const PointResult& p = report.points[i];
        plot.points.push_back({p.msPerSimulatedSecond, p.measures[m], onFront(report, m, i), report.labels[i]});
    }
    return renderSvg(plot);
}

std::string recommendation(const SweepReport& report, Measure measure, double limit) {
    const std::size_t m = static_cast<std::size_t>(measure);
    auto knobs = [&](const PointResult& p) {
        std::string text = inProduct(*report.plan, p.point) ? "" : "the scene's settings with ";
        for (std::size_t i = 0; i < p.point.assignments.size(); ++i) text += (i ? ", " : "") + knobText(p.point.assignments[i]);
        return text;
    };
    auto cost = [](const PointResult& p) {
        return shortNumber(p.msPerStep) + " ms/step (" + shortNumber(p.msPerSimulatedSecond) + " ms per simulated s)";
    };
    const std::string goal = std::string(measureTitle(measure)) + " <= " + shortNumber(limit) + " " + std::string(measureUnit(measure));
    if (const std::optional<std::size_t> best = cheapestWithin(report.points, measure, limit))
        return "for " + goal + ": " + knobs(report.points[*best]) + " — " + cost(report.points[*best]);
    const PointResult* closest = nullptr;
    for (const PointResult& p : report.points)
        if (!p.failed && (!closest || p.measures[m] < closest->measures[m])) closest = &p;
    if (!closest) return "no point of the grid ran without failing";
    return "no point reaches " + goal + "; the least is " + shortNumber(closest->measures[m]) + " " +
           std::string(measureUnit(measure)) + " at " + knobs(*closest) +
           " — " + cost(*closest);
}

std::string sweepMarkdown(const SweepReport& report, const std::string& recommendationLine) {
    const SweepPlan& plan = *report.plan;
    const Reference& r = *report.reference;
    auto knobs = [](const std::vector<std::string>& assignments) {
        std::string text;
        for (const std::string& a : assignments) text += (text.empty() ? "" : ", ") + knobText(a);
        return text;
    };
    std::size_t failed = 0;
    for (const PointResult& p : report.points) failed += p.failed ? 1 : 0;
    std::ostringstream md;
    md << "# What accuracy costs: `" << fs::path(plan.scenePath).filename().string() << "`\n\n";
    md << "Written by `interplay-sweep` (docs/sweep.md). " << report.points.size() << " points (" << failed
       << " failed), " << plan.spec.seconds << " s simulated each, trajectories compared at " << plan.spec.sampleRate
       << " instants per second. Cost is wall ms of `World::step` per simulated second; timings: " << report.timingNote
       << ".\n\n";
    md << "**Grid:** ";
    for (std::size_t k = 0; k < plan.spec.knobs.size(); ++k) {
        std::string values;
        const std::string& key = plan.spec.knobs[k].key;
        for (const std::string& v : plan.spec.knobs[k].values)
            values += (values.empty() ? "" : ", ") + knobText(key + "=" + v).substr(key.size() + 1);
        md << (k ? "; " : "") << "`" << plan.spec.knobs[k].key << "` " << values;
    }
    std::string extras;
    for (const PointResult& p : report.points) {
        if (!inProduct(plan, p.point)) extras += (extras.empty() ? "" : ", ") + ("`" + knobs(p.point.assignments) + "`");
    }
    if (!extras.empty()) md << "; and at the scene's own settings: " << extras;
    md << ".\n\n**Reference:** " << knobs(r.assignments) << " (" << shortNumber(r.msPerStep)
       << " ms/step). Its distance from a run with half its time step, below which errors are not resolved:\n\n";
    md << "| measure | reference's distance |\n|---|--:|\n";
    for (std::size_t m = 0; m < kMeasureCount; ++m)
        md << "| " << measureTitle(static_cast<Measure>(m)) << " (" << measureUnit(static_cast<Measure>(m)) << ") | "
           << shortNumber(r.convergence[m]) << " |\n";
    md << "\n**Recommendation:** " << recommendationLine << "\n\n";
    for (std::size_t m = 0; m < kMeasureCount; ++m) {
        const Measure measure = static_cast<Measure>(m);
        md << "## " << measureTitle(measure) << " (" << measureUnit(measure) << ")\n\n";
        md << "![" << measureTitle(measure) << " against cost](sweep-" << measureKey(measure) << ".svg)\n\n";
        md << "The front (★, cheapest first), and the scene's own settings and the presets where the grid holds them:\n\n";
        md << "| knobs | ms/step | ms per simulated s | " << measureTitle(measure) << " | |\n|---|--:|--:|--:|---|\n";
        std::vector<std::size_t> rowsToShow = report.fronts[m];
        for (std::size_t i = 0; i < report.points.size(); ++i)
            if (!report.labels[i].empty() && !onFront(report, m, i)) rowsToShow.push_back(i);
        for (std::size_t i : rowsToShow) {
            const PointResult& p = report.points[i];
            std::string labels;
            for (const std::string& l : report.labels[i]) labels += (labels.empty() ? "" : ", ") + ("**" + l + "**");
            md << "| " << (onFront(report, m, i) ? "★ " : "") << knobs(p.point.assignments) << " | "
               << shortNumber(p.msPerStep) << " | " << shortNumber(p.msPerSimulatedSecond) << " | "
               << (p.failed ? std::string("failed") : shortNumber(p.measures[m])) << " | " << labels << " |\n";
        }
        md << "\n";
    }
    return md.str();
}

std::optional<std::string> writeReport(const fs::path& dir, const SweepReport& report, const std::string& recommendationLine) {
    if (auto error = writeFileAtomically(dir / "sweep.csv", sweepCsv(report))) return error;
    if (auto error = writeFileAtomically(dir / "sweep.md", sweepMarkdown(report, recommendationLine))) return error;
    if (auto error = writeFileAtomically(dir / "sweep.json", sweepJson(report).dump(2) + "\n")) return error;
    for (std::size_t m = 0; m < kMeasureCount; ++m) {
        const Measure measure = static_cast<Measure>(m);
        if (auto error = writeFileAtomically(dir / ("sweep-" + std::string(measureKey(measure)) + ".svg"), measureSvg(report, measure)))
            return error;
    }
    return std::nullopt;
}

}  // namespace accuracy
