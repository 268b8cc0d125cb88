#include "runner_options.h"

#include "command_line.h"

#include "simcore/settings_schema.h"
#include "simcore/world/quality_preset.h"

#include <charconv>
#include <cmath>

namespace runner {

namespace {

using command_line::parseNumber;

// "[1, -2.5, 3e3]" (spaces allowed) -> three finite floats.
std::optional<std::array<float, 3>> parseVector(const std::string& text) {
    std::string t;
    for (char c : text)
        if (c != ' ') t += c;
    if (t.size() < 2 || t.front() != '[' || t.back() != ']') return std::nullopt;
    std::array<float, 3> v{};
    std::size_t start = 1;
    for (int i = 0; i < 3; ++i) {
        const std::size_t end = t.find(i < 2 ? ',' : ']', start);
        if (end == std::string::npos) return std::nullopt;
        const auto c = parseNumber<float>(t.substr(start, end - start));
        if (!c || !std::isfinite(*c)) return std::nullopt;
        v[static_cast<std::size_t>(i)] = *c;
        start = end + 1;
    }
    if (start != t.size()) return std::nullopt;
    return v;
}

}  // namespace

std::string usageText() {
    std::string text = "usage: interplay-run SCENE.json [--steps N | --seconds T] [--dt S] [--substeps K]\n"
           "                    [--iterations V] [--threads N] [--preset NAME] [--set key.path=value]...\n"
           "                    [--force NAME=[fx,fy,fz]]...\n"
           "                    [--trace FILE.csv] [--out FILE.json] [--save FILE.json]\n"
           "       interplay-run --list-stages\n"
           "Runs a scene without a window and prints a JSON report on stdout.\n"
           "  --steps N         number of steps (default: 1 second of simulated time)\n"
           "  --seconds T       simulated time; steps = ceil(T / dt)\n"
           "  --dt S            time step in seconds (settings.timeStep)\n"
           "  --substeps K      substeps per step (settings.substeps)\n"
           "  --iterations V    velocity iterations (settings.solver.velocityIterations)\n"
           "  --threads N       threads the step runs on, 0: one per core (settings.threads); the\n"
           "                    results are the same for any N\n"
           "  --preset NAME     quality preset fast, balanced or accurate (settings.preset), applied\n"
           "                    before the scene's other settings options, which override it\n"
           "  --set key=value   any scene setting, e.g. --set effects.friction=false\n"
           "  --force NAME=[fx,fy,fz]  constant force (N) on body NAME in every step\n"
           "  --trace FILE.csv  per-step state of every body\n"
           "  --out FILE.json   also write the report to FILE.json\n"
           "  --save FILE.json  write the scene as run (v1) before stepping; --steps 0 converts\n"
           "  --list-stages     print the step's stages in order of execution (a Markdown table) and exit\n"
           "Exit codes: 0 success, 2 bad arguments, 3 unreadable scene, 4 non-finite state.\n"
           "Settings (--set key=value; a vector as [x,y,z] or key.0=x, a section as a JSON object):\n"
           "  preset  fast, balanced or accurate\n";
    for (const simcore::SettingInfo& info : simcore::settingsSchema()) {
        std::string accepted;
        switch (info.type) {
            case simcore::SettingType::Bool: accepted = "true or false"; break;
            case simcore::SettingType::Choice: accepted = info.choiceList(); break;
            case simcore::SettingType::Vec3: accepted = "[x, y, z], each in " + info.range.describe(); break;
            case simcore::SettingType::Int: accepted = "integer in " + info.range.describe(); break;
            case simcore::SettingType::Float: accepted = info.range.describe(); break;
        }
        text += "  " + std::string(info.key) + "  " + accepted + ": " + std::string(info.doc) + "\n";
    }
    return text;
}

ParseResult parseArguments(const std::vector<std::string>& arguments) {
    ParseResult result;
    RunnerOptions& options = result.options;
    std::optional<std::string> preset;  // --preset NAME, validated
    auto fail = [&result](std::string message) {
        result.error = std::move(message);
        return result;
    };

    const command_line::Walk walk = command_line::walkArguments(
        arguments, {"--list-stages"}, [&](const std::string& arg, const std::string& value) -> std::optional<std::string> {
            if (arg == "--steps") {
                const auto steps = parseNumber<std::uint64_t>(value);
                if (!steps) return "--steps expects a non-negative integer, got '" + value + "'";
                options.steps = steps;
            } else if (arg == "--seconds") {
                const auto seconds = parseNumber<double>(value);
                if (!seconds || !std::isfinite(*seconds) || *seconds < 0.0)
                    return "--seconds expects a non-negative number, got '" + value + "'";
                options.seconds = seconds;
            } else if (arg == "--dt") {
                const auto dt = parseNumber<float>(value);
                if (!dt || !std::isfinite(*dt) || *dt <= 0.0f)
                    return "--dt expects a positive number of seconds, got '" + value + "'";
                options.timeStep = dt;
            } else if (arg == "--substeps") {
                const auto substeps = parseNumber<int>(value);
                if (!substeps || *substeps < 1) return "--substeps expects an integer >= 1, got '" + value + "'";
                options.substeps = substeps;
            } else if (arg == "--iterations") {
                const auto iterations = parseNumber<int>(value);
                if (!iterations || *iterations < 1) return "--iterations expects an integer >= 1, got '" + value + "'";
                options.velocityIterations = iterations;
            } else if (arg == "--threads") {
                // The schema's range, so the option and the setting accept the same counts.
                const simcore::NumberRange& range = simcore::findSetting("threads")->range;
                const auto threads = parseNumber<int>(value);
                if (!threads || !range.contains(*threads))
                    return "--threads expects an integer in " + range.describe() + " (0: one per core), got '" + value + "'";
                options.settingOverrides.push_back("threads=" + std::to_string(*threads));
            } else if (arg == "--preset") {
                if (!simcore::parseQualityPreset(value)) return "--preset expects fast, balanced or accurate, got '" + value + "'";
                preset = value;
            } else if (arg == "--set") {
                if (value.find('=') == std::string::npos) return "--set expects key.path=value, got '" + value + "'";
                options.settingOverrides.push_back(value);
            } else if (arg == "--force") {
                const std::size_t eq = value.rfind('=');
                const auto force = eq == std::string::npos ? std::nullopt : parseVector(value.substr(eq + 1));
                if (eq == 0 || !force) return "--force expects NAME=[fx,fy,fz] with finite numbers, got '" + value + "'";
                options.forces.push_back({value.substr(0, eq), *force});
            } else if (arg == "--trace") {
                options.tracePath = value;
            } else if (arg == "--out") {
                options.outPath = value;
            } else if (arg == "--save") {
                options.savePath = value;
            } else {
                return "unknown option " + arg;
            }
            return std::nullopt;
        });
    options.scenePath = walk.scenePath;
    options.listStages = walk.stoppedAt == "--list-stages";
    options.help = !walk.stoppedAt.empty() && !options.listStages;
    if (!walk.stoppedAt.empty()) return result;
    if (!walk.error.empty()) return fail(walk.error);
    if (options.scenePath.empty()) return fail("no scene file given");
    if (options.steps && options.seconds) return fail("--steps and --seconds exclude each other");
    if (preset) {
        // The preset goes first and every explicit setting option overrides it. The typed options
        // are applied before the overrides, so with a preset they travel as overrides after it.
        std::vector<std::string> ordered{"preset=" + *preset};
        if (options.timeStep) {
            char text[32];
            const auto written = std::to_chars(text, text + sizeof text, *options.timeStep);  // shortest: same float back
            ordered.push_back("timeStep=" + std::string(text, written.ptr));
        }
        if (options.substeps) ordered.push_back("substeps=" + std::to_string(*options.substeps));
        if (options.velocityIterations)
            ordered.push_back("solver.velocityIterations=" + std::to_string(*options.velocityIterations));
        options.timeStep.reset();
        options.substeps.reset();
        options.velocityIterations.reset();
        ordered.insert(ordered.end(), options.settingOverrides.begin(), options.settingOverrides.end());
        options.settingOverrides = std::move(ordered);
    }
    return result;
}

}  // namespace runner
