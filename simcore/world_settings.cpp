#include "simcore/world_settings.h"

namespace simcore {

std::string_view effectName(Effect effect) {
    switch (effect) {
        case Effect::Gravity: return "gravity";
        case Effect::Damping: return "damping";
        case Effect::Gyroscopic: return "gyroscopic";
        case Effect::Contacts: return "contacts";
        case Effect::Friction: return "friction";
        case Effect::Restitution: return "restitution";
        case Effect::Joints: return "joints";
        case Effect::Ccd: return "ccd";
        case Effect::Sleeping: return "sleeping";
        case Effect::Count: break;
    }
    return "unknown";
}

std::string_view positionCorrectionName(PositionCorrection method) {
    switch (method) {
        case PositionCorrection::SoftStep: return "softStep";
        case PositionCorrection::Baumgarte: return "baumgarte";
    }
    return "unknown";
}

std::string_view integratorName(Integrator integrator) {
    switch (integrator) {
        case Integrator::SymplecticEuler: return "symplecticEuler";
        case Integrator::ExplicitEuler: return "explicitEuler";
        case Integrator::VelocityVerlet: return "velocityVerlet";
    }
    return "unknown";
}

}  // namespace simcore
