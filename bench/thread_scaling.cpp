// interplay-bench-threads: ms per step of every benchmark scene at 1, 2 and all cores
// (settings.threads), medians of several runs, as a Markdown table (bench/results/threads.md), with
// the peak resident memory of a process that has stepped pile1k. Each run's final state is hashed
// bit for bit: the table says whether every thread count ended in the same bits, as it must.
//
// Runs of one scene alternate between thread counts (1, 2, N, then 2, N, 1, ...), so a burst of
// load on a shared machine spreads over all of them; the report records the load average. A scene
// whose runs are short runs more of them (--min-time), so that one preempted step does not decide
// its median: a tower of 40's 600 steps take 3.3 ms, and one preemption 40-80 us.

#include "support/state_hash.h"

#include "simcore/io/scene_io.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
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
using Clock = std::chrono::steady_clock;

// Steps per run: a few seconds of simulated time where a step is cheap, fewer where it is not.
struct SceneSteps {
    const char* name;
    int steps;
};
constexpr SceneSteps kDefaultSteps[] = {
    {"pile1k", 600}, {"mixed1k", 600}, {"pyramid10", 600}, {"pyramid20", 120}, {"tower20", 3600},
};
constexpr int kOtherSceneSteps = 600;
constexpr const char* kRssScene = "pile1k";

const char* usageText() {
    return "usage: interplay-bench-threads [--scene NAME]... [--steps N] [--repeat R] [--min-time S]\n"
           "                               [--threads T]... [--out FILE] [--scenes-dir DIR]\n"
           "       interplay-bench-threads --round-trip\n"
           "\n"
           "Steps each benchmark scene at several thread counts (settings.threads) and writes a Markdown\n"
           "table of ms per step (medians of R or more runs, with their range), the speedup over 1 thread,\n"
           "whether every thread count ended in the same bits, and the peak resident memory after pile1k.\n"
           "\n"
           "  --scene NAME      DIR/NAME.json; repeatable (default: every .json in DIR)\n"
           "  --steps N         steps per run (default: pile1k, mixed1k, pyramid10 600, pyramid20 120,\n"
           "                    tower20 3600, others 600)\n"
           "  --repeat R        runs per scene and thread count, at least (default 3)\n"
           "  --min-time S      and more until each thread count has stepped the scene for S seconds\n"
           "                    in all (default 0.5)\n"
           "  --threads T       a thread count to run, 0 meaning all cores; repeatable (default 1, 2, 0)\n"
           "  --out FILE        where to write the table (default: " INTERPLAY_SOURCE_DIR
           "/bench/results/threads.md;\n"
           "                    '-' prints it only)\n"
           "  --scenes-dir DIR  where scenes are looked up (default: " INTERPLAY_SOURCE_DIR
           "/scenes/bench)\n"
           "  --round-trip      print only the core-to-core round trip now, in ns (for other harnesses)\n"
           "\n"
           "Exit status: 0 done; 2 bad arguments or an unwritable FILE; 3 a scene that cannot be read;\n"
           "4 the thread counts ended in different states (the table is written first).\n";
}

struct Options {
    std::vector<std::string> scenes;
    std::optional<int> steps;
    int repeat = 3;
    double minSeconds = 0.5;
    std::vector<int> threads;
    std::string out = INTERPLAY_SOURCE_DIR "/bench/results/threads.md";
    fs::path scenesDir = fs::path(INTERPLAY_SOURCE_DIR) / "scenes" / "bench";
    bool roundTripOnly = false;
};

bool parseInt(const std::string& text, int& out, int minimum) {
    try {
        std::size_t used = 0;
        const int v = std::stoi(text, &used);
        if (used != text.size() || v < minimum) return false;
        out = v;
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

bool parseSeconds(const std::string& text, double& out) {
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size() || !(v >= 0.0) || v > 3600.0) return false;
        out = v;
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

int resolvedThreads(int threads) {
    return threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::optional<std::string> parseArguments(int argc, char** argv, Options& options, bool& help) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        std::string v;
        auto value = [&]() {
            if (i + 1 >= argc) return false;
            v = argv[++i];
            return true;
        };
        int n = 0;
        if (arg == "--help" || arg == "-h") {
            help = true;
        } else if (arg == "--round-trip") {
            options.roundTripOnly = true;
        } else if (arg == "--scene") {
            if (!value() || v.empty()) return "--scene needs a scene name";
            options.scenes.push_back(v);
        } else if (arg == "--steps") {
            if (!value() || !parseInt(v, n, 1)) return "--steps needs a whole number >= 1";
            options.steps = n;
        } else if (arg == "--repeat") {
            if (!value() || !parseInt(v, n, 1)) return "--repeat needs a whole number >= 1";
            options.repeat = n;
        } else if (arg == "--min-time") {
            if (!value() || !parseSeconds(v, options.minSeconds)) return "--min-time needs a number of seconds >= 0";
        } else if (arg == "--threads") {
            if (!value() || !parseInt(v, n, 0)) return "--threads needs a whole number >= 0 (0: all cores)";
            options.threads.push_back(n);
        } else if (arg == "--out") {
            if (!value() || v.empty()) return "--out needs a file name (or '-')";
            options.out = v;
        } else if (arg == "--scenes-dir") {
            if (!value() || v.empty()) return "--scenes-dir needs a directory";
            options.scenesDir = v;
        } else {
            return "unknown argument '" + arg + "'";
        }
    }
    if (options.scenes.empty()) {
        std::error_code error;
        for (const fs::directory_entry& entry : fs::directory_iterator(options.scenesDir, error))
            if (entry.path().extension() == ".json") options.scenes.push_back(entry.path().stem().string());
        if (error) return "cannot list " + options.scenesDir.string() + ": " + error.message();
        std::sort(options.scenes.begin(), options.scenes.end());
        if (options.scenes.empty()) return "no .json scene in " + options.scenesDir.string();
    }
    if (options.threads.empty()) options.threads = {1, 2, 0};
    // As resolved counts, each once (on a 2-core machine "all cores" is 2).
    for (int& threads : options.threads) threads = resolvedThreads(threads);
    std::vector<int> distinct;
    for (int threads : options.threads)
        if (std::find(distinct.begin(), distinct.end(), threads) == distinct.end()) distinct.push_back(threads);
    options.threads = distinct;
    return std::nullopt;
}

int defaultSteps(const std::string& scene) {
    for (const SceneSteps& s : kDefaultSteps)
        if (scene == s.name) return s.steps;
    return kOtherSceneSteps;
}

struct Run {
    double msPerStep = 0.0;
    std::uint64_t finalState = 0;  // test_support::stateHash
};

Run runScene(simcore::Scene scene, int threads, int steps) {
    scene.settings.threads = threads;
    simcore::BuiltWorld built = simcore::buildWorld(scene);
    const auto start = Clock::now();
    for (int s = 0; s < steps; ++s) built.world.step();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return {ms / steps, test_support::stateHash(built.world)};
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// ns for a cache line to go from one thread to another and back: two threads pass a counter back
// and forth, the median of several batches of round trips. On the project's 2-core VM the host
// mostly runs the two virtual CPUs on cores that share no cache (2026-12-06: round trips 400-480 ns,
// a line written on one core read on the other in 110-150 ns against 5-19 ns on its own), and
// then every body and manifold one stage's worker hands to another's costs that: pyramid20 ran
// 1.1-1.2x faster at 2 threads than at 1, each stage taking 40-75% more CPU time in all. Once, a
// line crossed in 22 ns, and pyramid20 ran 1.7x faster (a build timing each stage) with no more
// CPU time than at 1 thread. So each multi-threaded run records it.
double roundTripNs() {
    constexpr int kBatches = 9, kTripsPerBatch = 2000;
    alignas(64) std::atomic<int> counter{0};
    std::thread partner([&] {
        for (int n = 1; n < 2 * kBatches * kTripsPerBatch; n += 2) {
            while (counter.load(std::memory_order_acquire) != n) {}
            counter.store(n + 1, std::memory_order_release);
        }
    });
    std::vector<double> batches;
    int n = 0;
    for (int b = 0; b < kBatches; ++b) {
        const auto start = Clock::now();
        for (int t = 0; t < kTripsPerBatch; ++t, n += 2) {
            counter.store(n + 1, std::memory_order_release);
            while (counter.load(std::memory_order_acquire) != n + 2) {}
        }
        batches.push_back(std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kTripsPerBatch);
    }
    partner.join();
    return median(batches);
}

// A field of /proc/self/status in kB (VmHWM: peak resident set), or -1 where there is none.
long statusKb(const char* field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    const std::string prefix = std::string(field) + ":";
    while (std::getline(status, line)) {
        if (line.rfind(prefix, 0) == 0) return std::stol(line.substr(prefix.size()));
    }
    return -1;
}

std::string firstLineOf(const char* path, const char* key) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) == 0) {
            const std::size_t colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(line.find_first_not_of(" \t", colon + 1));
        }
    }
    return "unknown";
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
}

std::string fixed(double v, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    return buffer;
}

std::string msText(double ms) { return fixed(ms, ms < 0.1 ? 4 : ms < 10.0 ? 3 : 2); }

struct Cell {
    std::vector<double> ms;
    std::vector<double> roundTripNs;  // measured before each run (multi-threaded runs only)
    double seconds = 0.0;             // stepping, over all runs
    std::uint64_t state = 0;
};

struct SceneRow {
    std::string name;
    std::size_t bodies = 0;
    int steps = 0;
    std::vector<Cell> cells;  // by options.threads
    bool identical = true;
};

}  // namespace

int main(int argc, char** argv) {
    Options options;
    bool help = false;
    if (auto error = parseArguments(argc, argv, options, help)) {
        std::cerr << "interplay-bench-threads: " << *error << "\n\n" << usageText();
        return 2;
    }
    if (help) {
        std::cout << usageText();
        return 0;
    }
    if (options.roundTripOnly) {
        std::cout << std::lround(roundTripNs()) << '\n';
        return 0;
    }

    // Peak memory first, in a process that has loaded and stepped nothing else: pile1k, 1 thread.
    long rssBeforeKb = -1, rssPeakKb = -1;
    if (std::find(options.scenes.begin(), options.scenes.end(), kRssScene) != options.scenes.end()) {
        simcore::SceneLoadResult loaded = simcore::loadSceneFile(options.scenesDir / (std::string(kRssScene) + ".json"));
        if (loaded.ok()) {
            rssBeforeKb = statusKb("VmHWM");
            runScene(*loaded.scene, 1, options.steps.value_or(defaultSteps(kRssScene)));
            rssPeakKb = statusKb("VmHWM");
        }
    }

    std::vector<simcore::Scene> scenes;
    for (const std::string& name : options.scenes) {
        const fs::path path = options.scenesDir / (name + ".json");
        simcore::SceneLoadResult loaded = simcore::loadSceneFile(path);
        for (const simcore::Diagnostic& d : loaded.diagnostics) std::cerr << d.toString() << '\n';
        if (!loaded.ok()) {
            std::cerr << "interplay-bench-threads: cannot read scene '" << name << "' (" << path.string() << ")\n";
            return 3;
        }
        scenes.push_back(*loaded.scene);
    }

    const std::string loadBefore = loadAverage();
    char started[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(started, sizeof started, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));

    std::vector<SceneRow> rows;
    bool allIdentical = true;
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        SceneRow row;
        row.name = options.scenes[s];
        row.steps = options.steps.value_or(defaultSteps(row.name));
        for (const simcore::SceneBody& b : scenes[s].bodies)
            if (b.body.motion == simcore::MotionType::Dynamic) ++row.bodies;
        row.cells.resize(options.threads.size());
        std::cerr << "interplay-bench-threads: " << row.name << ", " << row.steps << " steps" << std::flush;
        const std::size_t counts = options.threads.size();
        const auto enoughRuns = [&](int runs) {
            if (runs < options.repeat) return false;
            for (const Cell& cell : row.cells)
                if (cell.seconds < options.minSeconds) return false;
            return true;
        };
        for (int r = 0; !enoughRuns(r); ++r) {
            for (std::size_t k = 0; k < counts; ++k) {
                const std::size_t t = (k + static_cast<std::size_t>(r)) % counts;  // rotate who goes first
                Cell& cell = row.cells[t];
                if (options.threads[t] > 1) cell.roundTripNs.push_back(roundTripNs());
                const Run run = runScene(scenes[s], options.threads[t], row.steps);
                cell.ms.push_back(run.msPerStep);
                cell.seconds += 1e-3 * run.msPerStep * row.steps;
                cell.state = run.finalState;
                std::cerr << '.' << std::flush;
            }
        }
        std::cerr << '\n';
        for (const Cell& cell : row.cells) row.identical = row.identical && cell.state == row.cells.front().state;
        allIdentical = allIdentical && row.identical;
        rows.push_back(std::move(row));
    }

    std::ostringstream md;
    md << "# Thread scaling\n\n"
       << "`interplay-bench-threads` (bench/thread_scaling.cpp), " << started << ", " << INTERPLAY_BUILD_TYPE
       << " build, " << firstLineOf("/proc/cpuinfo", "model name") << ", " << std::thread::hardware_concurrency()
       << " hardware threads; load average (1, 5, 15 min) " << loadBefore << " before, " << loadAverage()
       << " after. ms per step of the stepping loop (wall time), the median of a scene's runs (at least "
       << options.repeat << ", and more until each thread count has stepped it for " << fixed(options.minSeconds, 1)
       << " s), the range of the runs in brackets; the runs of a scene alternate between thread counts. "
       << "\"same bits\": every thread count ended in the same state, bit for bit. After the range of a "
       << "multi-threaded cell, the range of the core-to-core round trip measured before each of its runs "
       << "(two threads passing a counter): where the host runs the threads on cores that share a cache it "
       << "is several times shorter, and the workers' hand-overs of bodies and manifolds cost that much less.\n\n";
    md << "| scene | bodies | steps | runs |";
    const int cores = resolvedThreads(0);
    for (int threads : options.threads)
        md << ' ' << threads << (threads == 1 ? " thread" : " threads") << (threads == cores ? " (all cores)" : "") << " |";
    for (std::size_t t = 1; t < options.threads.size(); ++t)
        md << " speedup " << options.threads[t] << " / " << options.threads[0] << " |";
    md << " same bits |\n|---|--:|--:|--:|";
    for (std::size_t t = 0; t < 2 * options.threads.size() - 1; ++t) md << "--:|";
    md << "---|\n";
    for (const SceneRow& row : rows) {
        md << "| " << row.name << " | " << row.bodies << " | " << row.steps << " | " << row.cells.front().ms.size() << " |";
        for (const Cell& cell : row.cells) {
            const auto [low, high] = std::minmax_element(cell.ms.begin(), cell.ms.end());
            md << ' ' << msText(median(cell.ms)) << " (" << msText(*low) << "–" << msText(*high) << ")";
            if (!cell.roundTripNs.empty()) {
                const auto [fastest, slowest] = std::minmax_element(cell.roundTripNs.begin(), cell.roundTripNs.end());
                md << "; " << fixed(*fastest, 0) << "–" << fixed(*slowest, 0) << " ns";
            }
            md << " |";
        }
        const double base = median(row.cells.front().ms);
        for (std::size_t t = 1; t < row.cells.size(); ++t) md << ' ' << fixed(base / median(row.cells[t].ms), 2) << "× |";
        md << ' ' << (row.identical ? "yes" : "**no**") << " |\n";
    }
    if (rssPeakKb >= 0) {
        md << "\nPeak resident memory (VmHWM) of this process after loading and stepping " << kRssScene
           << " at 1 thread, before any other scene: " << fixed(rssPeakKb / 1024.0, 1) << " MiB ("
           << fixed(rssBeforeKb / 1024.0, 1) << " MiB with it loaded, before the first step).\n";
    }

    std::cout << md.str();
    if (options.out != "-") {
        std::ofstream file(options.out);
        if (!(file << md.str())) {
            std::cerr << "interplay-bench-threads: cannot write " << options.out << '\n';
            return 2;
        }
        std::cerr << "interplay-bench-threads: wrote " << options.out << '\n';
    }
    return allIdentical ? 0 : 4;
}
