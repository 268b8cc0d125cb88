#include "accuracy/scene_sweep.h"

#include "accuracy/pareto.h"

#include "simcore/io/scene_io.h"
#include "simcore/settings_schema.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace accuracy {

namespace {

constexpr std::array<std::string_view, kMeasureCount> kMeasureKeys = {
    "positionMax", "positionRms", "orientationMax", "orientationRms",
    "penetration", "energyDrift", "momentumDrift", "jointError"};
constexpr std::array<std::string_view, kMeasureCount> kMeasureTitles = {
    "largest position error", "RMS position error", "largest orientation error", "RMS orientation error",
    "deepest penetration",    "largest energy difference from the reference",
    "largest momentum difference from the reference", "worst joint position error"};
constexpr std::array<std::string_view, kMeasureCount> kMeasureUnits = {"m", "m", "rad", "rad", "m", "J", "N s", "m"};

// A grid larger than this is a typo, not a sweep (it would run for days).
constexpr std::size_t kMaxGridPoints = 100000;
// Runs longer than this many steps are refused (hours of stepping for one point).
constexpr double kMaxStepsPerRun = 1e8;

std::string shortest(float value) {
    char text[32];
    const auto written = std::to_chars(text, text + sizeof text, value);  // reads back as the same float
    return std::string(text, written.ptr);
}

simcore::Scene withAssignments(const simcore::Scene& scene, const std::vector<std::string>& assignments) {
    simcore::Scene copy = scene;
    for (const std::string& assignment : assignments)
        if (auto error = simcore::applySettingOverride(copy, assignment))
            throw std::invalid_argument(assignment + ": " + *error);
    return copy;
}

// State of the dynamic bodies after a step, what the samples interpolate between.
struct StepState {
    std::vector<double> positions, orientations;
    double energy = 0.0;
    std::array<double, 3> momentum{};
};

StepState capture(const simcore::World& world, const std::vector<simcore::BodyId>& bodies) {
    StepState s;
    s.positions.reserve(3 * bodies.size());
    s.orientations.reserve(4 * bodies.size());
    for (simcore::BodyId id : bodies) {
        const simcore::Vec3 p = world.position(id);
        const simcore::Quat q = world.orientation(id);
        s.positions.insert(s.positions.end(), {p.x, p.y, p.z});
        s.orientations.insert(s.orientations.end(), {q.w, q.x, q.y, q.z});
    }
    s.energy = world.kineticEnergy() + world.potentialEnergy();
    const simcore::Vec3 m = world.linearMomentum();
    s.momentum = {m.x, m.y, m.z};
    return s;
}

std::vector<double> lerp(const std::vector<double>& a, const std::vector<double>& b, double w) {
    std::vector<double> out(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] + w * (b[i] - a[i]);
    return out;
}

// Linear in time between two steps; quaternions are then renormalised (and taken on the same
// hemisphere as the earlier one, so the blend does not pass through the long way round).
void addSample(RunRecord& record, const StepState& before, const StepState& after, double w) {
    record.positions.push_back(lerp(before.positions, after.positions, w));
    std::vector<double> q(before.orientations.size());
    for (std::size_t b = 0; b + 3 < q.size(); b += 4) {
        double dot = 0.0;
        for (int k = 0; k < 4; ++k) dot += before.orientations[b + k] * after.orientations[b + k];
        const double sign = dot < 0.0 ? -1.0 : 1.0;
        double norm = 0.0;
        for (int k = 0; k < 4; ++k) {
            q[b + k] = before.orientations[b + k] + w * (sign * after.orientations[b + k] - before.orientations[b + k]);
            norm += q[b + k] * q[b + k];
        }
        norm = std::sqrt(norm);
        for (int k = 0; k < 4; ++k) q[b + k] /= norm;
    }
    record.orientations.push_back(std::move(q));
    record.energy.push_back(before.energy + w * (after.energy - before.energy));
    std::array<double, 3> m{};
    for (int k = 0; k < 3; ++k) m[k] = before.momentum[k] + w * (after.momentum[k] - before.momentum[k]);
    record.momentum.push_back(m);
}

// The angle (rad) of the rotation from orientation a to b: 2 atan2(|vector part|, |scalar part|) of
// conj(a) b, which stays accurate for small angles where acos would not.
double rotationAngle(const double* a, const double* b) {
    const double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const double x = a[0] * b[1] - a[1] * b[0] - a[2] * b[3] + a[3] * b[2];
    const double y = a[0] * b[2] + a[1] * b[3] - a[2] * b[0] - a[3] * b[1];
    const double z = a[0] * b[3] - a[1] * b[2] + a[2] * b[1] - a[3] * b[0];
    return 2.0 * std::atan2(std::sqrt(x * x + y * y + z * z), std::abs(w));
}

}  // namespace

std::string_view measureKey(Measure m) { return kMeasureKeys[static_cast<std::size_t>(m)]; }
std::string_view measureTitle(Measure m) { return kMeasureTitles[static_cast<std::size_t>(m)]; }
std::string_view measureUnit(Measure m) { return kMeasureUnits[static_cast<std::size_t>(m)]; }
std::optional<Measure> parseMeasure(std::string_view key) {
    for (std::size_t i = 0; i < kMeasureCount; ++i)
        if (kMeasureKeys[i] == key) return static_cast<Measure>(i);
    return std::nullopt;
}

std::vector<Knob> defaultKnobs() {
    return {{"timeStep", {shortest(1.0f / 30.0f), shortest(1.0f / 60.0f), shortest(1.0f / 120.0f)}},
            {"substeps", {"1", "2", "4", "8"}},
            {"solver.velocityIterations", {"1", "2", "4"}},
            {"solver.positionIterations", {"0", "1"}}};
}

std::vector<std::string> defaultReference(const simcore::WorldSettings& scene) {
    const float timeStep = std::min(1.0f / 480.0f, scene.timeStep / 8.0f);
    return {"timeStep=" + shortest(timeStep), "substeps=16", "solver.velocityIterations=8",
            "solver.positionIterations=2"};
}

std::vector<std::string> referenceAssignments(const simcore::Scene& scene, const SweepSpec& spec) {
    std::vector<std::string> all = defaultReference(scene.settings);
    all.insert(all.end(), spec.reference.begin(), spec.reference.end());
    return all;
}

std::vector<std::string> finerAssignments(const simcore::Scene& scene, const std::vector<std::string>& reference) {
    const simcore::Scene applied = withAssignments(scene, reference);
    std::vector<std::string> finer = reference;
    finer.push_back("timeStep=" + shortest(applied.settings.timeStep * 0.5f));
    return finer;
}

std::string pointId(const std::vector<std::string>& assignments) {
    // FNV-1a, 64 bits, over the assignments separated by a byte no assignment holds.
    std::uint64_t hash = 14695981039346656037ull;
    for (const std::string& a : assignments) {
        for (unsigned char c : a + '\n') {
            hash ^= c;
            hash *= 1099511628211ull;
        }
    }
    char text[17];
    for (int i = 15; i >= 0; --i, hash >>= 4) text[i] = "0123456789abcdef"[hash & 0xf];
    text[16] = '\0';
    return text;
}

std::vector<GridPoint> expandGrid(const std::vector<Knob>& knobs) {
    std::vector<GridPoint> grid;
    if (knobs.empty()) return grid;
    for (const Knob& k : knobs)
        if (k.values.empty()) return grid;
    std::vector<std::size_t> index(knobs.size(), 0);
    for (;;) {
        GridPoint p;
        for (std::size_t k = 0; k < knobs.size(); ++k) p.assignments.push_back(knobs[k].key + "=" + knobs[k].values[index[k]]);
        p.id = pointId(p.assignments);
        grid.push_back(std::move(p));
        // Odometer order: the last knob turns fastest.
        std::size_t k = knobs.size();
        while (k > 0 && ++index[k - 1] == knobs[k - 1].values.size()) index[--k] = 0;
        if (k == 0) return grid;
    }
}

std::vector<GridPoint> gridPoints(const SweepSpec& spec) {
    std::vector<GridPoint> grid = expandGrid(spec.knobs);
    for (const std::vector<std::string>& assignments : spec.extraPoints) {
        GridPoint p{assignments, pointId(assignments)};
        if (std::none_of(grid.begin(), grid.end(), [&](const GridPoint& q) { return q.id == p.id; }))
            grid.push_back(std::move(p));
    }
    return grid;
}

std::vector<std::vector<std::string>> effectToggles(const simcore::Scene& scene, const SweepSpec& spec) {
    const RunRecord run = recordRun(scene, {}, spec);
    std::vector<std::vector<std::string>> toggles;
    for (simcore::Effect effect : {simcore::Effect::Damping, simcore::Effect::Gyroscopic, simcore::Effect::Friction,
                                   simcore::Effect::Restitution, simcore::Effect::Ccd, simcore::Effect::Sleeping})
        if (run.effectsRan[static_cast<std::size_t>(effect)])
            toggles.push_back({"effects." + std::string(simcore::effectName(effect)) + "=false"});
    return toggles;
}

std::optional<std::string> checkSpec(const simcore::Scene& scene, const SweepSpec& spec) {
    if (!(spec.seconds > 0.0) || !(spec.seconds <= 1e5))
        return "--seconds must be a number of seconds in (0, 100000], got " + simcore::formatNumber(spec.seconds);
    if (!(spec.sampleRate > 0.0) || !(spec.sampleRate <= 1e4))
        return "the sample rate must be in (0, 10000] Hz, got " + simcore::formatNumber(spec.sampleRate);
    if (spec.knobs.empty()) return "the grid is empty: no knob is given";
    double points = 1.0;
    for (std::size_t i = 0; i < spec.knobs.size(); ++i) {
        const Knob& knob = spec.knobs[i];
        if (knob.values.empty()) return "the grid is empty: knob '" + knob.key + "' has no values";
        for (std::size_t j = 0; j < i; ++j)
            if (spec.knobs[j].key == knob.key) return "knob '" + knob.key + "' is given twice";
        for (const std::string& value : knob.values) {
            simcore::Scene copy = scene;
            if (auto error = simcore::applySettingOverride(copy, knob.key + "=" + value))
                return "knob '" + knob.key + "=" + value + "': " + *error;
            if (spec.seconds / static_cast<double>(copy.settings.timeStep) > kMaxStepsPerRun)
                return "knob '" + knob.key + "=" + value + "': " + simcore::formatNumber(spec.seconds) +
                       " s would take more than 1e8 steps";
        }
        points *= static_cast<double>(knob.values.size());
    }
    for (const std::vector<std::string>& extra : spec.extraPoints) {
        simcore::Scene copy = scene;
        for (const std::string& assignment : extra)
            if (auto error = simcore::applySettingOverride(copy, assignment)) return "point '" + assignment + "': " + *error;
    }
    if (points > static_cast<double>(kMaxGridPoints))
        return "the grid has " + simcore::formatNumber(points) + " points, more than " + std::to_string(kMaxGridPoints);
    simcore::Scene reference = scene;
    for (const std::string& assignment : referenceAssignments(scene, spec))
        if (auto error = simcore::applySettingOverride(reference, assignment))
            return "--reference " + assignment + ": " + *error;
    if (spec.seconds / (0.5 * static_cast<double>(reference.settings.timeStep)) > kMaxStepsPerRun)
        return "the reference's convergence check would take more than 1e8 steps: give --reference timeStep=... larger";
    if (reference.settings.timeStep * 0.5f < 1e-6f)
        return "the reference's time step is too small to halve for its convergence check (the least is 2e-06 s)";
    return std::nullopt;
}

RunRecord recordRun(const simcore::Scene& scene, const std::vector<std::string>& assignments, const SweepSpec& spec,
                    const std::atomic<bool>* cancel) {
    const simcore::Scene applied = withAssignments(scene, assignments);
    simcore::BuiltWorld built = simcore::buildWorld(applied);
    simcore::World& world = built.world;
    std::vector<simcore::BodyId> dynamicBodies;
    for (simcore::BodyId id : built.bodyIds)
        if (world.motionType(id) == simcore::MotionType::Dynamic) dynamicBodies.push_back(id);

    RunRecord record;
    record.timeStep = world.settings().timeStep;
    const auto samples = static_cast<std::size_t>(std::floor(spec.seconds * spec.sampleRate + 1e-9));
    const double lastSample = static_cast<double>(samples) / spec.sampleRate;
    // Enough steps to reach the last sample; the slack keeps 2 s of 1/60 s steps at 120, not 121.
    record.steps = static_cast<std::uint64_t>(std::max(1.0, std::ceil(lastSample / record.timeStep * (1.0 - 1e-9))));

    StepState before = capture(world, dynamicBodies);
    std::size_t nextSample = 1;  // instant 0 is the initial state, where every run agrees
    for (std::uint64_t s = 0; s < record.steps; ++s) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            record.cancelled = true;
            return record;
        }
        const auto start = std::chrono::steady_clock::now();
        world.step();
        record.wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (world.findNonFiniteBody()) {
            record.finite = false;
            return record;
        }
        record.penetration = std::max(record.penetration, static_cast<double>(world.lastStepProfile().maxPenetration));
        if (world.jointCount() > 0)
            record.jointError = std::max(record.jointError, static_cast<double>(world.worstJointError().position));
        const StepState after = capture(world, dynamicBodies);
        const double t0 = static_cast<double>(s) * record.timeStep;
        const double t1 = static_cast<double>(s + 1) * record.timeStep;
        for (; nextSample <= samples && static_cast<double>(nextSample) / spec.sampleRate <= t1; ++nextSample)
            addSample(record, before, after, (static_cast<double>(nextSample) / spec.sampleRate - t0) / (t1 - t0));
        before = after;
    }
    for (std::size_t e = 0; e < record.effectsRan.size(); ++e)
        record.effectsRan[e] = world.effectUsage().ran(static_cast<simcore::Effect>(e));
    // A last instant the steps fell short of by rounding (under 1e-9 of the run) takes the final state.
    for (; nextSample <= samples; ++nextSample) addSample(record, before, before, 0.0);
    return record;
}

Measures compare(const RunRecord& run, const RunRecord& reference) {
    Measures m{};
    if (!run.finite || !reference.finite) {
        m.fill(std::numeric_limits<double>::infinity());
        return m;
    }
    if (run.positions.size() != reference.positions.size())
        throw std::invalid_argument("the run and the reference have different sample counts");
    double positionMax = 0.0, positionSquares = 0.0, angleMax = 0.0, angleSquares = 0.0;
    double energyMax = 0.0, momentumMax = 0.0;
    std::size_t terms = 0;
    for (std::size_t s = 0; s < run.positions.size(); ++s) {
        const std::vector<double>& p = run.positions[s];
        const std::vector<double>& pr = reference.positions[s];
        if (p.size() != pr.size()) throw std::invalid_argument("the run and the reference have different body counts");
        for (std::size_t b = 0; b * 3 < p.size(); ++b) {
            const double dx = p[3 * b] - pr[3 * b], dy = p[3 * b + 1] - pr[3 * b + 1], dz = p[3 * b + 2] - pr[3 * b + 2];
            const double d2 = dx * dx + dy * dy + dz * dz;
            positionMax = std::max(positionMax, std::sqrt(d2));
            positionSquares += d2;
            const double angle = rotationAngle(&reference.orientations[s][4 * b], &run.orientations[s][4 * b]);
            angleMax = std::max(angleMax, angle);
            angleSquares += angle * angle;
            ++terms;
        }
        energyMax = std::max(energyMax, std::abs(run.energy[s] - reference.energy[s]));
        double m2 = 0.0;
        for (int k = 0; k < 3; ++k) m2 += (run.momentum[s][k] - reference.momentum[s][k]) * (run.momentum[s][k] - reference.momentum[s][k]);
        momentumMax = std::max(momentumMax, std::sqrt(m2));
    }
    const double n = terms > 0 ? static_cast<double>(terms) : 1.0;
    m[static_cast<std::size_t>(Measure::PositionMax)] = positionMax;
    m[static_cast<std::size_t>(Measure::PositionRms)] = std::sqrt(positionSquares / n);
    m[static_cast<std::size_t>(Measure::OrientationMax)] = angleMax;
    m[static_cast<std::size_t>(Measure::OrientationRms)] = std::sqrt(angleSquares / n);
    m[static_cast<std::size_t>(Measure::Penetration)] = run.penetration;
    m[static_cast<std::size_t>(Measure::EnergyDrift)] = energyMax;
    m[static_cast<std::size_t>(Measure::MomentumDrift)] = momentumMax;
    m[static_cast<std::size_t>(Measure::JointError)] = run.jointError;
    return m;
}

std::optional<Reference> runReference(const simcore::Scene& scene, const SweepSpec& spec, std::string& error,
                                      const std::atomic<bool>* cancel, int jobs) {
    Reference reference;
    reference.assignments = referenceAssignments(scene, spec);
    const std::vector<std::string> finerSettings = finerAssignments(scene, reference.assignments);
    RunRecord finer;
    if (jobs > 1) {
        // std::async: the check's exception reaches the caller, and an exception here waits for it.
        std::future<RunRecord> check =
            std::async(std::launch::async, [&] { return recordRun(scene, finerSettings, spec, cancel); });
        reference.run = recordRun(scene, reference.assignments, spec, cancel);
        finer = check.get();
    } else {
        reference.run = recordRun(scene, reference.assignments, spec, cancel);
        // A reference that failed needs no check.
        if (reference.run.finite && !reference.run.cancelled) finer = recordRun(scene, finerSettings, spec, cancel);
    }
    if (reference.run.cancelled || finer.cancelled) {
        error = "cancelled";
        return std::nullopt;
    }
    if (!reference.run.finite || !finer.finite) {
        error = std::string(!reference.run.finite ? "the reference run" : "the reference's convergence check (time step halved)") +
                " went non-finite: give a finer or stiffer --reference";
        return std::nullopt;
    }
    reference.convergence = compare(finer, reference.run);
    // The run's own worst values: how much they move when the step is halved.
    reference.convergence[static_cast<std::size_t>(Measure::Penetration)] = std::abs(finer.penetration - reference.run.penetration);
    reference.convergence[static_cast<std::size_t>(Measure::JointError)] = std::abs(finer.jointError - reference.run.jointError);
    reference.msPerStep = reference.run.wallMs / static_cast<double>(reference.run.steps);
    return reference;
}

std::optional<PointResult> runPoint(const simcore::Scene& scene, const SweepSpec& spec, const GridPoint& point,
                                    const Reference& reference, const std::atomic<bool>* cancel) {
    const RunRecord run = recordRun(scene, point.assignments, spec, cancel);
    if (run.cancelled) return std::nullopt;
    PointResult result;
    result.point = point;
    result.measures = compare(run, reference.run);
    result.failed = !run.finite;
    result.steps = run.steps;
    result.msPerStep = run.wallMs / static_cast<double>(run.steps);
    result.msPerSimulatedSecond = run.wallMs / (static_cast<double>(run.steps) * run.timeStep);
    return result;
}

std::vector<PointResult> runSweep(const simcore::Scene& scene, const SweepSpec& spec, const std::vector<GridPoint>& grid,
                                  const Reference& reference, const SweepRunOptions& options) {
    std::vector<std::optional<PointResult>> slots(grid.size());
    std::atomic<std::size_t> next{0};
    std::mutex mutex;  // guards `done` and the callbacks
    std::size_t done = 0;
    const auto start = std::chrono::steady_clock::now();
    auto report = [&](std::optional<PointResult> result, std::size_t index, bool fresh) {
        std::lock_guard lock(mutex);
        if (fresh && options.finished) options.finished(*result);
        slots[index] = std::move(result);
        ++done;
        if (options.progress)
            options.progress({done, grid.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    };
    auto worker = [&] {
        for (;;) {
            if (options.cancel && options.cancel->load()) return;
            const std::size_t i = next.fetch_add(1);
            if (i >= grid.size()) return;
            if (options.lookup) {
                if (std::optional<PointResult> known = options.lookup(grid[i])) {
                    report(std::move(known), i, false);
                    continue;
                }
            }
            std::optional<PointResult> result = runPoint(scene, spec, grid[i], reference, options.cancel);
            if (!result) return;
            result->timing = options.timing;
            report(std::move(result), i, true);
        }
    };
    const int jobs = std::clamp(options.jobs, 1, static_cast<int>(std::max<std::size_t>(grid.size(), 1)));
    std::vector<std::thread> threads;
    for (int t = 1; t < jobs; ++t) threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();

    std::vector<PointResult> results;
    for (std::optional<PointResult>& slot : slots)
        if (slot) results.push_back(std::move(*slot));
    return results;
}

std::array<std::vector<std::size_t>, kMeasureCount> fronts(const std::vector<PointResult>& points) {
    std::array<std::vector<std::size_t>, kMeasureCount> all;
    std::vector<double> cost;
    for (const PointResult& p : points) cost.push_back(p.msPerSimulatedSecond);
    for (std::size_t m = 0; m < kMeasureCount; ++m) {
        std::vector<double> error;
        for (const PointResult& p : points) error.push_back(p.measures[m]);
        all[m] = paretoFront(cost, error);
    }
    return all;
}

std::optional<std::size_t> cheapestWithin(const std::vector<PointResult>& points, Measure measure, double limit) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const PointResult& p = points[i];
        if (p.failed || !(p.measures[static_cast<std::size_t>(measure)] <= limit)) continue;
        if (!best || p.msPerSimulatedSecond < points[*best].msPerSimulatedSecond) best = i;
    }
    return best;
}

}  // namespace accuracy
