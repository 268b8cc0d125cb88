#pragma once
// A sweep of one scene file over a grid of settings, measured against a converged reference run:
// the engine under interplay-sweep, Qt-free so that an editor panel can run it in the background
// (progress callback, cancellation flag). Knobs are settings key paths with values as
// `interplay-run --set` takes them; every value goes through simcore::applySettingOverride.

#include "simcore/io/scene.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace accuracy {

// One knob: a settings key and the values the grid gives it ("substeps" -> "1", "2", "4").
struct Knob {
    std::string key;
    std::vector<std::string> values;
};

struct SweepSpec {
    std::vector<Knob> knobs;               // the grid is their Cartesian product, the first knob slowest
    double seconds = 2.0;                  // simulated per run
    double sampleRate = 60.0;              // Hz: trajectories are compared at these instants
    std::vector<std::string> reference;    // "key=value" applied after defaultReference(): what the user changed
    // Points beyond the Cartesian product, each its own assignments over the scene's settings
    // (effectToggles() gives the default grid's).
    std::vector<std::vector<std::string>> extraPoints;
};

// The grid when none is given: time step 1/30, 1/60, 1/120 s x 1, 2, 4, 8 substeps x 1, 2, 4
// velocity iterations x 0, 1 relax passes (72 points).
std::vector<Knob> defaultKnobs();
// The converged run when none is given: 1/480 s (or the scene's step / 8 if smaller), 16 substeps,
// 8 velocity iterations, 2 relax passes; contact and joint stiffness stay the scene's, so the
// reference converges to the same soft-constraint model the grid runs.
std::vector<std::string> defaultReference(const simcore::WorldSettings& scene);
// The reference run's assignments: defaultReference() followed by the spec's own (later ones win).
std::vector<std::string> referenceAssignments(const simcore::Scene& scene, const SweepSpec& spec);

// A grid point: its assignments in knob order, and a stable id from them (16 hex digits, a hash),
// which names its result file.
struct GridPoint {
    std::vector<std::string> assignments;
    std::string id;
};
std::string pointId(const std::vector<std::string>& assignments);
std::vector<GridPoint> expandGrid(const std::vector<Knob>& knobs);
// The Cartesian product of the knobs, then the extra points not already in it.
std::vector<GridPoint> gridPoints(const SweepSpec& spec);

// Checks the spec against the scene: every knob a known setting with at least one value, each
// value accepted, no knob twice, a positive duration and sample rate, a valid reference. Returns
// the first problem as a sentence naming it ("--knob substeps: invalid value '0': ...").
std::optional<std::string> checkSpec(const simcore::Scene& scene, const SweepSpec& spec);

// The error measures of a run against the reference. Trajectory measures compare the dynamic
// bodies at the sample instants (linear interpolation between steps; orientation by normalised
// lerp): positions (m) and orientations (rad, the angle of the relative rotation), largest and RMS
// over bodies and instants; total energy (J) and linear momentum (N s) likewise, largest
// difference. Penetration and joint error are the run's own worst values.
enum class Measure {
    PositionMax,
    PositionRms,
    OrientationMax,
    OrientationRms,
    Penetration,
    EnergyDrift,
    MomentumDrift,
    JointError,
};
inline constexpr std::size_t kMeasureCount = 8;
std::string_view measureKey(Measure m);    // "positionMax", as in sweep.json and sweep.csv
std::string_view measureTitle(Measure m);  // "largest position error", for plots and messages
std::string_view measureUnit(Measure m);   // "m", "rad", "J", "N s"
std::optional<Measure> parseMeasure(std::string_view key);
using Measures = std::array<double, kMeasureCount>;  // indexed by Measure; +inf: the run failed

// What one run recorded: its state at each sample instant (dynamic bodies in scene order), worst
// values seen in any step, and the wall time of the World::step calls alone.
struct RunRecord {
    std::vector<std::vector<double>> positions;     // [sample][3 * body]
    std::vector<std::vector<double>> orientations;  // [sample][4 * body], w x y z
    std::vector<double> energy;                     // [sample] kinetic + potential (J)
    std::vector<std::array<double, 3>> momentum;    // [sample] linear (N s)
    double penetration = 0.0;                       // deepest contact overlap (m)
    double jointError = 0.0;                        // worst joint position error (m)
    double wallMs = 0.0;
    std::uint64_t steps = 0;
    double timeStep = 0.0;
    std::array<bool, simcore::kEffectCount> effectsRan{};  // which effects ran in any step
    bool finite = true;     // false: a body's state went non-finite; the run stopped there
    bool cancelled = false;
};

// Runs the scene with `assignments` applied (they must have passed checkSpec) for `spec.seconds`.
// `cancel`, when set, is polled every step.
RunRecord recordRun(const simcore::Scene& scene, const std::vector<std::string>& assignments, const SweepSpec& spec,
                    const std::atomic<bool>* cancel = nullptr);

// One extra point per effect the scene uses that trades accuracy or cost rather than defining the
// scene (damping, gyroscopic, friction, restitution, ccd, sleeping): "effects.NAME=false" at the
// scene's own settings. Found by running the scene at its settings for `spec.seconds`.
std::vector<std::vector<std::string>> effectToggles(const simcore::Scene& scene, const SweepSpec& spec);

// `run` against `reference`; a failed run has every measure +inf.
Measures compare(const RunRecord& run, const RunRecord& reference);

// The reference run, and how converged it is: the same measures between it and a run with half its
// time step. For the trajectory measures that distance bounds (triangle inequality) how much any
// point's error would change were the finer run the reference.
struct Reference {
    std::vector<std::string> assignments;
    RunRecord run;
    Measures convergence{};
    double msPerStep = 0.0;
};
// Fails (nothing, with `error` set) when the reference or its check goes non-finite, or cancelled.
// With `jobs` above 1 the two runs go side by side on two threads (the same numbers; the check,
// at half the step, costs twice the reference, so this saves up to a third of the time).
std::optional<Reference> runReference(const simcore::Scene& scene, const SweepSpec& spec, std::string& error,
                                      const std::atomic<bool>* cancel = nullptr, int jobs = 1);
// The assignments of the run twice as fine as the reference (its time step halved).
std::vector<std::string> finerAssignments(const simcore::Scene& scene, const std::vector<std::string>& reference);

struct PointResult {
    GridPoint point;
    Measures measures{};
    bool failed = false;
    std::uint64_t steps = 0;
    double msPerStep = 0.0;
    double msPerSimulatedSecond = 0.0;
    std::string timing;  // how it was timed ("one point at a time", ...): the caller's note, kept with it
};
// Nothing when cancelled.
std::optional<PointResult> runPoint(const simcore::Scene& scene, const SweepSpec& spec, const GridPoint& point,
                                    const Reference& reference, const std::atomic<bool>* cancel = nullptr);

struct SweepProgress {
    std::size_t done = 0;     // points finished, including those found already done
    std::size_t total = 0;
    double elapsedSeconds = 0.0;
};

struct SweepRunOptions {
    int jobs = 1;                                          // points run at once, on threads
    const std::atomic<bool>* cancel = nullptr;             // set: no new point starts, running ones stop
    std::function<void(const SweepProgress&)> progress;    // after each point, from the worker's thread
    // Looks up a point already done (resuming), or nothing to run it.
    std::function<std::optional<PointResult>(const GridPoint&)> lookup;
    std::string timing;  // stamped on each point run (PointResult::timing)
    // Receives each point as it finishes (the tool writes its result file), under a lock.
    std::function<void(const PointResult&)> finished;
};

// Runs every point not already done. Returns them in grid order; when cancelled, only those done.
std::vector<PointResult> runSweep(const simcore::Scene& scene, const SweepSpec& spec, const std::vector<GridPoint>& grid,
                                  const Reference& reference, const SweepRunOptions& options);

// Per measure, the indices of the points on its front of the measure against ms per simulated
// second, cheapest first.
std::array<std::vector<std::size_t>, kMeasureCount> fronts(const std::vector<PointResult>& points);

// The cheapest point (ms per simulated second) whose `measure` is at most `limit`, or nothing.
std::optional<std::size_t> cheapestWithin(const std::vector<PointResult>& points, Measure measure, double limit);

}  // namespace accuracy
