#pragma once
// Named trade-offs between accuracy and time per step. A preset sets only the accuracy knobs
// (substeps and solver iterations); everything else in the settings is left as the scene has it.
// The profiler shows what each one costs as you switch.

#include "simcore/world/world_settings.h"

#include <QString>
#include <QStringList>

#include <array>

namespace interplay {

struct QualityPreset {
    const char* name;
    int substeps;
    int velocityIterations;
    int positionIterations;
};

// Draft: cheapest, for big piles; Default: the engine's defaults; Precise: tall stacks, high mass
// ratios; about 4x Default's cost.
inline constexpr std::array<QualityPreset, 3> kQualityPresets{{
    {"Draft", 1, 4, 1},
    {"Default", 4, 2, 1},
    {"Precise", 8, 4, 2},
}};

inline simcore::WorldSettings withPreset(simcore::WorldSettings settings, const QualityPreset& preset) {
    settings.substeps = preset.substeps;
    settings.solver.velocityIterations = preset.velocityIterations;
    settings.solver.positionIterations = preset.positionIterations;
    return settings;
}

// Index into kQualityPresets of the preset the settings match, or -1 (custom).
inline int matchingPreset(const simcore::WorldSettings& settings) {
    for (std::size_t i = 0; i < kQualityPresets.size(); ++i) {
        if (withPreset(settings, kQualityPresets[i]) == settings) return static_cast<int>(i);
    }
    return -1;
}

}  // namespace interplay
