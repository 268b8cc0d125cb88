#pragma once
// The reference scenes of the accuracy benchmark. Each builds its world in code with the public
// World API, steps it, and turns what it observed into one error number against a known answer:
// a closed form where physics gives one, otherwise a converged run of the same scene.

#include "simcore/io/scene.h"
#include "simcore/world/world.h"
#include "simcore/world_settings.h"

#include <functional>
#include <string>
#include <vector>

namespace accuracy {

// Adds up the wall time of World::step calls only, so the scene's own measuring between steps
// (zero crossings, joint errors, penetration) is not charged to the engine.
class SteppingTimer {
public:
    // `beforeFirstStep`, when given, sees the world as the scene built it, just before its first step.
    explicit SteppingTimer(std::function<void(const simcore::World&)> beforeFirstStep = {})
        : beforeFirstStep_(std::move(beforeFirstStep)) {}
    void step(simcore::World& world);
    double milliseconds() const { return milliseconds_; }

private:
    std::function<void(const simcore::World&)> beforeFirstStep_;
    double milliseconds_ = 0.0;
};

// What one run observed: the numbers its scene computes the error from, in the scene's own layout.
struct Observation {
    std::vector<double> values;
    bool finite = true;  // false once any body's state became non-finite
};

enum class ReferenceKind {
    ClosedForm,    // the error compares the observation with an exact answer
    ConvergedRun,  // the error compares it with the observation of a converged run
};

struct ReferenceScene {
    std::string name;         // for --scene and file names: "incline-slide"
    std::string title;        // "Box sliding down a 30° incline"
    std::string setup;        // the scene, in one Markdown paragraph
    std::string metric;       // what the error is and its unit
    std::string errorAxis;    // plot axis label, with the unit
    std::string answer;       // the closed form, or what the converged run is compared on
    ReferenceKind reference = ReferenceKind::ClosedForm;
    double seconds = 1.0;       // simulated per run, full sweep
    double quickSeconds = 1.0;  // simulated per run, --quick
    simcore::WorldSettings base;  // the scene's settings before the sweep sets its knobs
    std::vector<simcore::Effect> toggles;  // effects the sweep also switches off, one at a time

    // Builds the world with `settings`, runs `seconds` of simulated time through `timer`.
    std::function<Observation(const simcore::WorldSettings& settings, double seconds, SteppingTimer& timer)> run;
    // The error of an observation; `converged` is the converged run's (ConvergedRun scenes only).
    std::function<double(const Observation& observed, const Observation* converged)> error;
};

std::vector<ReferenceScene> referenceScenes();

// The scene as its `run` builds it at its base settings, before the first step, as a scene file
// holds it: what interplay-sweep is given to sweep the same scene. Bodies come from the world's
// getters, joints' frames from World::draw (their anchors and axes as creation reads them).
simcore::Scene sceneFile(const ReferenceScene& scene);

}  // namespace accuracy
