#pragma once
// Command line of interplay-run (the interface is fixed by the product brief).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace runner {

struct RunnerOptions {
    std::string scenePath;
    std::optional<std::uint64_t> steps;
    std::optional<double> seconds;
    std::optional<float> timeStep;           // --dt
    std::optional<int> substeps;             // --substeps
    std::optional<int> velocityIterations;   // --iterations
    std::vector<std::string> settingOverrides;  // --set key.path=value, in order
    std::string tracePath;                   // --trace FILE.csv
    std::string outPath;                     // --out FILE.json
    std::string savePath;                    // --save FILE.json
    bool help = false;
};

struct ParseResult {
    RunnerOptions options;
    std::string error;  // empty on success
};

ParseResult parseArguments(const std::vector<std::string>& arguments);  // without argv[0]

const char* usageText();

}  // namespace runner
