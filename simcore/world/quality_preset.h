#pragma once
// Named trade-offs between accuracy and time, picked from the Pareto front that
// interplay-bench-accuracy measures (bench/results/accuracy.md). A preset sets only the
// accuracy knobs listed in applyQualityPreset; gravity, materials, damping, sleep and effects stay
// as the scene has them. Balanced is the engine's defaults.

#include "simcore/world_settings.h"

#include <array>
#include <optional>
#include <string_view>

namespace simcore {

enum class QualityPreset : std::uint8_t { Fast, Balanced, Accurate };

inline constexpr std::array<QualityPreset, 3> kQualityPresets{QualityPreset::Fast, QualityPreset::Balanced,
                                                              QualityPreset::Accurate};

std::string_view qualityPresetName(QualityPreset preset);  // "fast", "balanced", "accurate"
std::optional<QualityPreset> parseQualityPreset(std::string_view name);  // exact, lower case

// Sets timeStep, substeps, solver iterations and position correction, and the soft-contact and
// joint stiffness, to the preset's values.
void applyQualityPreset(WorldSettings& settings, QualityPreset preset);

// The preset whose knobs the settings have exactly (every other field may be anything), if any.
std::optional<QualityPreset> matchingQualityPreset(const WorldSettings& settings);

}  // namespace simcore
