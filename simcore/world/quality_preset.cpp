#include "simcore/world/quality_preset.h"

namespace simcore {

namespace {

struct PresetKnobs {
    float timeStep;
    int substeps;
    int velocityIterations;
    int positionIterations;
    PositionCorrection positionCorrection;
    float contactHertz;
    float jointHertz;
};

// Points of the front measured over all reference scenes (bench/results/accuracy.md, "Across all
// scenes"); Balanced is WorldSettings' defaults.
//  - Fast: half the substeps and a second relax pass: 0.75-0.8x Balanced's cost for about 2.4x its
//    error (at most 4x on any scene). With one relax pass a 16-cube tower drifts 3x as far (and,
//    not coming to rest, costs more). Contacts and joints get the engine's cap at this substep
//    rate, 30 Hz. (A 1/30 s step in 4 substeps measured about the same for a little less, but
//    halves the step rate the editor shows.)
//  - Accurate: twice the substeps and twice the contact and joint stiffness (the cap at 480 Hz):
//    about 1.7x the cost for 0.36x the error, no scene worse; beyond it more iterations or Baumgarte
//    buy less per millisecond.
PresetKnobs knobs(QualityPreset preset) {
    const WorldSettings defaults;
    const PresetKnobs balanced{defaults.timeStep,
                               defaults.substeps,
                               defaults.solver.velocityIterations,
                               defaults.solver.positionIterations,
                               defaults.solver.positionCorrection,
                               defaults.solver.contactHertz,
                               defaults.joint.hertz};
    switch (preset) {
        case QualityPreset::Fast:
            return {defaults.timeStep, 2, 2, 2, PositionCorrection::SoftStep, defaults.solver.contactHertz,
                    defaults.joint.hertz};
        case QualityPreset::Balanced:
            return balanced;
        case QualityPreset::Accurate:
            return {defaults.timeStep, 8, 2, 1, PositionCorrection::SoftStep, 120.0f, 120.0f};
    }
    return balanced;
}

}  // namespace

std::string_view qualityPresetName(QualityPreset preset) {
    switch (preset) {
        case QualityPreset::Fast: return "fast";
        case QualityPreset::Balanced: return "balanced";
        case QualityPreset::Accurate: return "accurate";
    }
    return "unknown";
}

std::optional<QualityPreset> parseQualityPreset(std::string_view name) {
    for (QualityPreset preset : kQualityPresets)
        if (qualityPresetName(preset) == name) return preset;
    return std::nullopt;
}

void applyQualityPreset(WorldSettings& settings, QualityPreset preset) {
    const PresetKnobs k = knobs(preset);
    settings.timeStep = k.timeStep;
    settings.substeps = k.substeps;
    settings.solver.velocityIterations = k.velocityIterations;
    settings.solver.positionIterations = k.positionIterations;
    settings.solver.positionCorrection = k.positionCorrection;
    settings.solver.contactHertz = k.contactHertz;
    settings.joint.hertz = k.jointHertz;
}

std::optional<QualityPreset> matchingQualityPreset(const WorldSettings& settings) {
    for (QualityPreset preset : kQualityPresets) {
        WorldSettings withPreset = settings;
        applyQualityPreset(withPreset, preset);
        if (withPreset == settings) return preset;
    }
    return std::nullopt;
}

}  // namespace simcore
