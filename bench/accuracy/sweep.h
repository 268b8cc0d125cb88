#pragma once
// The grid of accuracy knobs, one measured point per setting, and the Pareto front of error
// against cost.

#include "reference_scenes.h"

#include "simcore/world/quality_preset.h"

#include <optional>
#include <string>
#include <vector>

namespace accuracy {

// One setting of the knobs the sweep turns; everything else stays as the scene's base settings.
struct Knobs {
    float timeStep = 1.0f / 60.0f;
    int substeps = 4;
    int velocityIterations = 2;
    int positionIterations = 1;
    simcore::PositionCorrection positionCorrection = simcore::PositionCorrection::SoftStep;
    simcore::Integrator integrator = simcore::Integrator::SymplecticEuler;
    // Contact and joint stiffness at their cap, a quarter of the substep rate, instead of the
    // default 60 Hz (only differs where the substep rate exceeds 240 Hz).
    bool stiff = false;
    std::optional<simcore::Effect> switchedOff;
    std::optional<simcore::QualityPreset> preset;  // set: the preset's knobs replace the ones above

    simcore::WorldSettings applyTo(simcore::WorldSettings settings) const;
    std::string label() const;  // "1/60 s ×4, v2 p1 soft", "1/60 s ×4, v2 p1 soft, verlet", "preset fast", ...
};

// The grid: `quick` is the small CI smoke grid. Relevant effect toggles come from the scene.
std::vector<Knobs> sweepGrid(const ReferenceScene& scene, bool quick);

// The converged run's knobs (dt/8 of 1/60 s, 16 substeps, 8 + 2 iterations, stiffness at its cap)
// and a coarser run (dt/4, 8 substeps) whose distance from it shows how converged the reference is.
// --quick uses the coarser pair dt/4, 8 substeps / dt/2, 4 substeps.
Knobs convergedKnobs(bool quick);
Knobs convergenceCheckKnobs(bool quick);

struct Point {
    Knobs knobs;
    std::string label;
    std::vector<std::string> presets;  // preset names whose settings equal this point's
    double error = 0.0;                // +infinity when the run failed (non-finite state)
    double msPerSimulatedSecond = 0.0;
    double msPerStep = 0.0;
    int steps = 0;
    int repeats = 0;
    bool onFront = false;
};

struct Measurement {
    Observation observation;
    double bestMs = 0.0;  // best stepping-loop wall time over the repeats
    int steps = 0;
    int repeats = 0;
    bool deterministic = true;  // every repeat observed the same numbers
};

// Runs the scene at `settings` once, then again while the total stays under `repeatBudgetMs`, at
// most `maxRepeats` times, keeping the fastest stepping loop.
Measurement measure(const ReferenceScene& scene, const simcore::WorldSettings& settings, double seconds,
                    int maxRepeats, double repeatBudgetMs);

// Marks the points no other point beats on both error and cost (failed runs are never on it).
// Returns their indices, cheapest first.
std::vector<std::size_t> markParetoFront(std::vector<Point>& points);

}  // namespace accuracy
