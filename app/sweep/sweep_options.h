#pragma once
// Command line of interplay-sweep (see usageText()).

#include "accuracy/scene_sweep.h"

#include <optional>
#include <string>
#include <vector>

namespace sweep {

// Exit codes, as --help and docs/sweep.md list them.
enum ExitCode {
    kSuccess = 0,
    kBadArguments = 2,     // unknown knob, empty grid, bad value, unwritable --out, ...
    kUnreadableScene = 3,  // the loader refused the scene
    kReferenceFailed = 4,  // the reference run (or its check) went non-finite
    kCorruptResult = 5,    // --merge: a plan, reference or point file that is corrupt or of another sweep
    kIncomplete = 6,       // --merge: points of the plan have no result yet
    kInterrupted = 130,    // Ctrl-C: the points done are kept, a rerun resumes
};

struct Options {
    std::string scenePath;
    std::vector<accuracy::Knob> knobs;        // --knob, in order (after the --grid file's)
    bool knobsGiven = false;                  // by --knob or the file's "knobs" (else the default grid)
    std::string gridPath;                     // --grid
    std::optional<double> seconds;            // --seconds
    std::optional<double> sampleRate;         // --sample-rate
    std::vector<std::string> reference;       // --reference, in order
    int jobs = 1;                             // --jobs; 0 means one per hardware thread
    std::string outDir;                       // --out; empty: sweep-<scene name>
    std::string emitJobsPath;                 // --emit-jobs
    std::string mergeDir;                     // --merge
    std::vector<std::string> point;           // --point: run only this grid point (what emitted jobs do)
    accuracy::Measure target = accuracy::Measure::Penetration;  // --target MEASURE=LIMIT
    double targetLimit = 0.001;
    bool help = false;
};

struct ParseResult {
    Options options;
    std::string error;  // empty on success
};

ParseResult parseArguments(const std::vector<std::string>& arguments);  // without argv[0]

// "gravity=[0,-1,0],[0,-2,0]" -> key "gravity", values "[0,-1,0]" and "[0,-2,0]": commas inside
// brackets, braces or quotes do not split. Nothing when there is no key.
std::optional<accuracy::Knob> parseKnob(const std::string& text);

// Reads a sweep file: {"knobs": {"substeps": [1, 2, 4], ...}, "seconds": 2, "sampleRate": 60,
// "reference": {"timeStep": 0.001}}; every member optional. Adds to `options` what the command
// line did not already give. Returns an error naming the file and the problem.
std::optional<std::string> readGridFile(const std::string& path, Options& options);

std::string usageText();

}  // namespace sweep
