#include "sweep.h"

#include "accuracy/pareto.h"

#include <algorithm>
#include <cmath>

namespace accuracy {

using simcore::PositionCorrection;
using simcore::WorldSettings;

WorldSettings Knobs::applyTo(WorldSettings settings) const {
    if (preset) {
        simcore::applyQualityPreset(settings, *preset);
        return settings;
    }
    settings.timeStep = timeStep;
    settings.substeps = substeps;
    settings.solver.velocityIterations = velocityIterations;
    settings.solver.positionIterations = positionIterations;
    settings.solver.positionCorrection = positionCorrection;
    settings.integrator = integrator;
    if (stiff) {
        // Whole hertz, so that a preset stating the same stiffness gives identical settings.
        const float quarterSubstepRate =
            static_cast<float>(std::round(substeps / (4.0 * static_cast<double>(timeStep))));
        settings.solver.contactHertz = quarterSubstepRate;
        settings.joint.hertz = quarterSubstepRate;
    }
    if (switchedOff) settings.effects[*switchedOff] = false;
    return settings;
}

std::string Knobs::label() const {
    if (preset) return "preset " + std::string(simcore::qualityPresetName(*preset));
    std::string text = "1/" + std::to_string(std::lround(1.0 / static_cast<double>(timeStep))) + " s ×" +
                       std::to_string(substeps) + ", v" + std::to_string(velocityIterations);
    if (positionCorrection == PositionCorrection::SoftStep)
        text += " p" + std::to_string(positionIterations) + " soft";
    else
        text += " baumgarte";
    if (integrator == simcore::Integrator::ExplicitEuler) text += ", explicit Euler";
    if (integrator == simcore::Integrator::VelocityVerlet) text += ", Verlet";
    if (stiff) text += ", stiff";
    if (switchedOff) text += ", " + std::string(simcore::effectName(*switchedOff)) + " off";
    return text;
}

namespace {

Knobs knobs(float timeStep, int substeps, int velocityIterations, int positionIterations,
            PositionCorrection correction = PositionCorrection::SoftStep) {
    Knobs k;
    k.timeStep = timeStep;
    k.substeps = substeps;
    k.velocityIterations = velocityIterations;
    k.positionIterations = positionIterations;
    k.positionCorrection = correction;
    return k;
}

bool stiffnessDiffers(const Knobs& k) {
    const WorldSettings defaults;
    return static_cast<float>(k.substeps) / k.timeStep / 4.0f > defaults.solver.contactHertz * 1.001f;
}

}  // namespace

std::vector<Knobs> sweepGrid(const ReferenceScene& scene, bool quick) {
    std::vector<Knobs> grid;
    const WorldSettings defaults;
    const int defaultVelocity = defaults.solver.velocityIterations;
    const int defaultPosition = defaults.solver.positionIterations;
    auto addToggles = [&](const Knobs& at) {
        for (simcore::Effect effect : scene.toggles) {
            Knobs k = at;
            k.switchedOff = effect;
            grid.push_back(k);
        }
    };
    auto addIntegrators = [&](Knobs k) {
        for (simcore::Integrator method : {simcore::Integrator::ExplicitEuler, simcore::Integrator::VelocityVerlet}) {
            k.integrator = method;
            grid.push_back(k);
        }
    };
    auto addStiff = [&](Knobs k) {
        if (!stiffnessDiffers(k)) return;
        k.stiff = true;
        grid.push_back(k);
    };

    if (quick) {
        for (float dt : {1.0f / 30.0f, 1.0f / 60.0f, 1.0f / 120.0f})
            for (int substeps : {1, 4}) grid.push_back(knobs(dt, substeps, defaultVelocity, defaultPosition));
        grid.push_back(knobs(1.0f / 60.0f, 4, 8, defaultPosition));
        grid.push_back(knobs(1.0f / 60.0f, 4, defaultVelocity, 0, PositionCorrection::Baumgarte));
        addStiff(knobs(1.0f / 120.0f, 4, defaultVelocity, defaultPosition));
        addIntegrators(knobs(1.0f / 60.0f, 4, defaultVelocity, defaultPosition));
        addToggles(knobs(1.0f / 60.0f, 4, defaultVelocity, defaultPosition));
        return grid;
    }

    for (float dt : {1.0f / 30.0f, 1.0f / 60.0f, 1.0f / 120.0f, 1.0f / 240.0f}) {
        for (int substeps : {1, 2, 4, 8}) {
            // Velocity iterations with the default position correction.
            for (int velocity : {1, 2, 4, 8}) grid.push_back(knobs(dt, substeps, velocity, defaultPosition));
            // Position correction: relax passes 0 and 2, and Baumgarte (which has none) at 2 and 8 iterations.
            grid.push_back(knobs(dt, substeps, defaultVelocity, 0));
            grid.push_back(knobs(dt, substeps, defaultVelocity, 2));
            grid.push_back(knobs(dt, substeps, defaultVelocity, 0, PositionCorrection::Baumgarte));
            grid.push_back(knobs(dt, substeps, 8, 0, PositionCorrection::Baumgarte));
            // Stiffer contacts and joints where the substep rate allows them.
            for (int velocity : {defaultVelocity, 4}) addStiff(knobs(dt, substeps, velocity, defaultPosition));
            addIntegrators(knobs(dt, substeps, defaultVelocity, defaultPosition));
            addToggles(knobs(dt, substeps, defaultVelocity, defaultPosition));
        }
    }
    return grid;
}

Knobs convergedKnobs(bool quick) {
    Knobs k = quick ? knobs(1.0f / 240.0f, 8, 8, 2) : knobs(1.0f / 480.0f, 16, 8, 2);
    k.stiff = true;
    return k;
}

Knobs convergenceCheckKnobs(bool quick) {
    Knobs k = quick ? knobs(1.0f / 120.0f, 4, 8, 2) : knobs(1.0f / 240.0f, 8, 8, 2);
    k.stiff = true;
    return k;
}

Measurement measure(const ReferenceScene& scene, const WorldSettings& settings, double seconds, int maxRepeats,
                    double repeatBudgetMs) {
    Measurement m;
    m.steps = static_cast<int>(std::lround(seconds / static_cast<double>(settings.timeStep)));
    double totalMs = 0.0;
    for (int r = 0; r < maxRepeats && (r == 0 || totalMs < repeatBudgetMs); ++r) {
        SteppingTimer timer;
        Observation o = scene.run(settings, seconds, timer);
        if (r == 0) {
            m.observation = std::move(o);
            m.bestMs = timer.milliseconds();
        } else {
            if (m.observation.finite && o.values != m.observation.values) m.deterministic = false;
            m.bestMs = std::min(m.bestMs, timer.milliseconds());
        }
        totalMs += timer.milliseconds();
        ++m.repeats;
    }
    return m;
}

std::vector<std::size_t> markParetoFront(std::vector<Point>& points) {
    std::vector<double> cost, error;
    for (Point& p : points) {
        p.onFront = false;
        cost.push_back(p.msPerSimulatedSecond);
        error.push_back(p.error);
    }
    const std::vector<std::size_t> front = paretoFront(cost, error);
    for (std::size_t i : front) points[i].onFront = true;
    return front;
}

}  // namespace accuracy
