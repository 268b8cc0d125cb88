#include "runner_options.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace runner {

namespace {

template <typename T>
std::optional<T> parseNumber(const std::string& text) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

}  // namespace

const char* usageText() {
    return "usage: interplay-run SCENE.json [--steps N | --seconds T] [--dt S] [--substeps K]\n"
           "                    [--iterations V] [--set key.path=value]... [--trace FILE.csv]\n"
           "                    [--out FILE.json] [--save FILE.json]\n"
           "Runs a scene without a window and prints a JSON report on stdout.\n"
           "  --steps N         number of steps (default: 1 second of simulated time)\n"
           "  --seconds T       simulated time; steps = ceil(T / dt)\n"
           "  --dt S            time step in seconds (settings.timeStep)\n"
           "  --substeps K      substeps per step (settings.substeps)\n"
           "  --iterations V    velocity iterations (settings.solver.velocityIterations)\n"
           "  --set key=value   any scene setting, e.g. --set effects.friction=false\n"
           "  --trace FILE.csv  per-step state of every body\n"
           "  --out FILE.json   also write the report to FILE.json\n"
           "  --save FILE.json  write the scene as run (v1) before stepping; --steps 0 converts\n"
           "Exit codes: 0 success, 2 bad arguments, 3 unreadable scene, 4 non-finite state.\n";
}

ParseResult parseArguments(const std::vector<std::string>& arguments) {
    ParseResult result;
    RunnerOptions& options = result.options;
    auto fail = [&result](std::string message) {
        result.error = std::move(message);
        return result;
    };

    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& arg = arguments[i];
        if (arg == "--help" || arg == "-h") {
            options.help = true;
            return result;
        }
        if (arg.rfind("--", 0) != 0) {
            if (!options.scenePath.empty()) return fail("more than one scene given: '" + arg + "'");
            options.scenePath = arg;
            continue;
        }
        if (i + 1 >= arguments.size()) return fail("option " + arg + " needs a value");
        const std::string& value = arguments[++i];

        if (arg == "--steps") {
            const auto steps = parseNumber<std::uint64_t>(value);
            if (!steps) return fail("--steps expects a non-negative integer, got '" + value + "'");
            options.steps = steps;
        } else if (arg == "--seconds") {
            const auto seconds = parseNumber<double>(value);
            if (!seconds || !std::isfinite(*seconds) || *seconds < 0.0)
                return fail("--seconds expects a non-negative number, got '" + value + "'");
            options.seconds = seconds;
        } else if (arg == "--dt") {
            const auto dt = parseNumber<float>(value);
            if (!dt || !std::isfinite(*dt) || *dt <= 0.0f)
                return fail("--dt expects a positive number of seconds, got '" + value + "'");
            options.timeStep = dt;
        } else if (arg == "--substeps") {
            const auto substeps = parseNumber<int>(value);
            if (!substeps || *substeps < 1) return fail("--substeps expects an integer >= 1, got '" + value + "'");
            options.substeps = substeps;
        } else if (arg == "--iterations") {
            const auto iterations = parseNumber<int>(value);
            if (!iterations || *iterations < 1)
                return fail("--iterations expects an integer >= 1, got '" + value + "'");
            options.velocityIterations = iterations;
        } else if (arg == "--set") {
            if (value.find('=') == std::string::npos)
                return fail("--set expects key.path=value, got '" + value + "'");
            options.settingOverrides.push_back(value);
        } else if (arg == "--trace") {
            options.tracePath = value;
        } else if (arg == "--out") {
            options.outPath = value;
        } else if (arg == "--save") {
            options.savePath = value;
        } else {
            return fail("unknown option " + arg);
        }
    }
    if (options.scenePath.empty()) return fail("no scene file given");
    if (options.steps && options.seconds) return fail("--steps and --seconds exclude each other");
    return result;
}

}  // namespace runner
