#include "sweep_options.h"

#include "runner/command_line.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace sweep {

namespace {

std::optional<double> parseDouble(const std::string& text) {
    const std::optional<double> value = command_line::parseNumber<double>(text);
    if (!value || !std::isfinite(*value)) return std::nullopt;
    return value;
}

// A JSON value as --set takes it: a string's own text, anything else as JSON.
std::string valueText(const nlohmann::json& value) { return value.is_string() ? value.get<std::string>() : value.dump(); }

}  // namespace

std::string usageText() {
    return "usage: interplay-sweep SCENE.json [--knob KEY=V1,V2,...]... [--grid SWEEP.json] [--seconds T]\n"
           "                      [--reference KEY=VALUE]... [--jobs N] [--out DIR] [--emit-jobs FILE]\n"
           "                      [--target MEASURE=LIMIT] [--sample-rate HZ]\n"
           "       interplay-sweep --merge DIR [--target MEASURE=LIMIT]\n"
           "Runs SCENE at every point of a grid of settings, measures each run's error against a converged\n"
           "reference run and its cost, and writes into DIR: sweep.csv, sweep.json (every point: knobs,\n"
           "ms/step, each measure, whether it is on that measure's Pareto front) and sweep-MEASURE.svg, then\n"
           "prints a one-line recommendation. See docs/sweep.md.\n"
           "  --knob KEY=V1,V2  a settings key as interplay-run --set takes it (timeStep, substeps,\n"
           "                    solver.velocityIterations, effects.friction, ...) and its values; repeatable,\n"
           "                    the grid is every combination. Default: timeStep=1/30,1/60,1/120 s,\n"
           "                    substeps=1,2,4,8, solver.velocityIterations=1,2,4, solver.positionIterations=0,1,\n"
           "                    and each effect the scene uses of damping, gyroscopic, friction, restitution,\n"
           "                    ccd and sleeping switched off at the scene's own settings\n"
           "  --grid FILE       knobs (and seconds, sampleRate, reference) from a JSON file:\n"
           "                    {\"knobs\": {\"substeps\": [1, 2, 4]}, \"seconds\": 2, \"reference\": {\"substeps\": 32}}\n"
           "  --seconds T       simulated seconds per run (default 2)\n"
           "  --reference K=V   changes the reference run (default: timeStep 1/480 s or the scene's / 8,\n"
           "                    16 substeps, 8 velocity iterations, 2 relax passes); repeatable. Its own\n"
           "                    error is checked against a run with half its time step and reported\n"
           "  --jobs N          points run at once on threads (default 1; 0: one per core); above 1 the\n"
           "                    reference and its check also run side by side. Timings are noisier\n"
           "                    above 1, and the output says so\n"
           "  --out DIR         where results go (default ./sweep-SCENENAME). A point whose result file is\n"
           "                    already in DIR/points is not run again: an interrupted sweep resumes\n"
           "  --emit-jobs FILE  runs the reference, then writes one shell command per grid point to FILE\n"
           "                    instead of running them (for GNU parallel, xargs -P, a Slurm array)\n"
           "  --merge DIR       gathers the results the jobs wrote into DIR's tables and plots\n"
           "  --target M=LIMIT  what the recommendation aims at (default penetration=0.001, in metres).\n"
           "                    Measures: positionMax, positionRms, orientationMax, orientationRms,\n"
           "                    penetration, energyDrift, momentumDrift, jointError\n"
           "  --sample-rate HZ  instants per second at which trajectories are compared (default 60)\n"
           "  --point KEY=V     (repeatable) runs only this grid point and writes its result file: what\n"
           "                    the emitted commands do\n"
           "Exit codes: 0 success, 2 bad arguments (unknown knob, empty grid, bad value), 3 a scene that\n"
           "cannot be read, 4 the reference run went non-finite, 5 --merge found a corrupt result file (or\n"
           "one of another sweep), 6 --merge found points without a result, 130 interrupted (rerun to resume).\n";
}

std::optional<accuracy::Knob> parseKnob(const std::string& text) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) return std::nullopt;
    accuracy::Knob knob;
    knob.key = text.substr(0, eq);
    std::string current;
    int depth = 0;
    bool quoted = false;
    for (std::size_t i = eq + 1; i <= text.size(); ++i) {
        const char c = i < text.size() ? text[i] : ',';
        if (c == '"') quoted = !quoted;
        if (!quoted && (c == '[' || c == '{')) ++depth;
        if (!quoted && (c == ']' || c == '}')) --depth;
        if (c == ',' && depth == 0 && !quoted) {
            if (!current.empty()) knob.values.push_back(current);
            current.clear();
        } else {
            current += c;
        }
    }
    return knob;
}

std::optional<std::string> readGridFile(const std::string& path, Options& options) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "--grid " + path + ": cannot be opened";
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::ordered_json j;
    try {
        j = nlohmann::ordered_json::parse(text.str());
    } catch (const nlohmann::json::parse_error& e) {
        return "--grid " + path + ": not JSON: " + e.what();
    }
    if (!j.is_object()) return "--grid " + path + ": expected a JSON object";
    for (const auto& [key, value] : j.items()) {
        if (key == "knobs") {
            if (!value.is_object()) return "--grid " + path + ": \"knobs\" must be an object of key: [values]";
            std::vector<accuracy::Knob> fromFile;
            for (const auto& [knobKey, values] : value.items()) {
                if (!values.is_array()) return "--grid " + path + ": knob '" + knobKey + "' must be an array of values";
                accuracy::Knob knob{knobKey, {}};
                for (const auto& v : values) knob.values.push_back(valueText(v));
                fromFile.push_back(std::move(knob));
            }
            options.knobs.insert(options.knobs.begin(), fromFile.begin(), fromFile.end());
            options.knobsGiven = true;
        } else if (key == "seconds" || key == "sampleRate") {
            if (!value.is_number()) return "--grid " + path + ": \"" + key + "\" must be a number";
            std::optional<double>& field = key == "seconds" ? options.seconds : options.sampleRate;
            if (!field) field = value.get<double>();
        } else if (key == "reference") {
            if (!value.is_object()) return "--grid " + path + ": \"reference\" must be an object of key: value";
            std::vector<std::string> fromFile;
            for (const auto& [refKey, v] : value.items()) fromFile.push_back(refKey + "=" + valueText(v));
            options.reference.insert(options.reference.begin(), fromFile.begin(), fromFile.end());
        } else {
            return "--grid " + path + ": unknown member \"" + key + "\" (expected knobs, seconds, sampleRate, reference)";
        }
    }
    return std::nullopt;
}

ParseResult parseArguments(const std::vector<std::string>& arguments) {
    ParseResult result;
    Options& options = result.options;
    auto fail = [&result](std::string message) {
        result.error = std::move(message);
        return result;
    };
    const command_line::Walk walk = command_line::walkArguments(
        arguments, {}, [&](const std::string& arg, const std::string& value) -> std::optional<std::string> {
            if (arg == "--knob") {
                const std::optional<accuracy::Knob> knob = parseKnob(value);
                if (!knob) return "--knob expects KEY=V1,V2,..., got '" + value + "'";
                if (knob->values.empty()) return "the grid is empty: --knob " + knob->key + " has no values";
                options.knobs.push_back(*knob);
                options.knobsGiven = true;
            } else if (arg == "--grid") {
                options.gridPath = value;
            } else if (arg == "--seconds" || arg == "--sample-rate") {
                const std::optional<double> number = parseDouble(value);
                if (!number || *number <= 0.0) return arg + " expects a positive number, got '" + value + "'";
                (arg == "--seconds" ? options.seconds : options.sampleRate) = number;
            } else if (arg == "--reference" || arg == "--point") {
                if (value.find('=') == std::string::npos || value.front() == '=')
                    return arg + " expects KEY=VALUE, got '" + value + "'";
                (arg == "--reference" ? options.reference : options.point).push_back(value);
            } else if (arg == "--jobs") {
                const std::optional<double> jobs = parseDouble(value);
                if (!jobs || *jobs < 0.0 || *jobs > 1024.0 || *jobs != std::floor(*jobs))
                    return "--jobs expects an integer from 0 (one per core) to 1024, got '" + value + "'";
                options.jobs = static_cast<int>(*jobs);
            } else if (arg == "--out") {
                options.outDir = value;
            } else if (arg == "--emit-jobs") {
                options.emitJobsPath = value;
            } else if (arg == "--merge") {
                options.mergeDir = value;
            } else if (arg == "--target") {
                const std::size_t eq = value.find('=');
                const std::optional<accuracy::Measure> measure =
                    eq == std::string::npos ? std::nullopt : accuracy::parseMeasure(value.substr(0, eq));
                const std::optional<double> limit = measure ? parseDouble(value.substr(eq + 1)) : std::nullopt;
                if (!measure || !limit || *limit < 0.0)
                    return "--target expects MEASURE=LIMIT with a measure of --help and a limit >= 0, got '" + value + "'";
                options.target = *measure;
                options.targetLimit = *limit;
            } else {
                return "unknown option '" + arg + "'";
            }
            return std::nullopt;
        });
    options.scenePath = walk.scenePath;
    if (!walk.stoppedAt.empty()) {
        options.help = true;
        return result;
    }
    if (!walk.error.empty()) return fail(walk.error);
    if (options.mergeDir.empty() && options.scenePath.empty()) return fail("no scene given");
    if (!options.mergeDir.empty() && (!options.scenePath.empty() || !options.emitJobsPath.empty() || !options.point.empty()))
        return fail("--merge DIR takes no scene, --emit-jobs or --point: the plan in DIR names them");
    if (!options.emitJobsPath.empty() && !options.point.empty()) return fail("--emit-jobs and --point exclude each other");
    if (!options.gridPath.empty()) {
        if (auto error = readGridFile(options.gridPath, options)) return fail(*error);
    }
    return result;
}

}  // namespace sweep
