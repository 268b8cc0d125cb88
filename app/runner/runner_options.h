#pragma once
// Command line of interplay-run (the interface is fixed by the product brief).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace runner {

// --force NAME=[fx,fy,fz]: a constant force (N) on every body called NAME, at its centre of mass,
// in every step. Only finiteness is checked: the scene's limits are the loader's business, and a
// force too large for float arithmetic ends the run with exit 4 (the documented way to test it).
struct ForceOption {
    std::string body;
    std::array<float, 3> force{};
};

struct RunnerOptions {
    std::string scenePath;
    std::optional<std::uint64_t> steps;
    std::optional<double> seconds;
    std::optional<float> timeStep;           // --dt
    std::optional<int> substeps;             // --substeps
    std::optional<int> velocityIterations;   // --iterations
    // --set key.path=value, in order. --preset NAME comes first as preset=NAME, followed by --dt,
    // --substeps and --iterations as overrides (their fields above are then unset), so that every
    // explicit option overrides the preset. --threads N travels as threads=N, in its place among them.
    std::vector<std::string> settingOverrides;
    std::vector<ForceOption> forces;            // --force NAME=[fx,fy,fz], in order
    std::string tracePath;                   // --trace FILE.csv
    std::string outPath;                     // --out FILE.json
    std::string savePath;                    // --save FILE.json
    bool help = false;
    bool listStages = false;  // --list-stages: print the stage table and exit
};

struct ParseResult {
    RunnerOptions options;
    std::string error;  // empty on success
};

ParseResult parseArguments(const std::vector<std::string>& arguments);  // without argv[0]

// The --help text, with every setting --set takes (from the settings schema): key, range, doc.
std::string usageText();

}  // namespace runner
