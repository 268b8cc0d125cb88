#include "simcore/world_settings.h"

namespace simcore {

namespace {
template <typename Enum, std::size_t N>
std::string_view nameOf(Enum value, const std::array<std::string_view, N>& names) {
    const auto index = static_cast<std::size_t>(value);
    return index < N ? names[index] : "unknown";
}
}  // namespace

std::string_view effectName(Effect effect) { return nameOf(effect, kEffectNames); }
std::string_view positionCorrectionName(PositionCorrection method) { return nameOf(method, kPositionCorrectionNames); }
std::string_view integratorName(Integrator integrator) { return nameOf(integrator, kIntegratorNames); }

}  // namespace simcore
