#include "simcore/world/profiler.h"

namespace simcore {

std::string_view stageName(Stage stage) {
    switch (stage) {
        case Stage::IntegrateVelocities: return "integrateVelocities";
        case Stage::BroadPhase: return "broadPhase";
        case Stage::NarrowPhase: return "narrowPhase";
        case Stage::SolveConstraints: return "solveConstraints";
        case Stage::IntegratePositions: return "integratePositions";
        case Stage::ContinuousCollision: return "continuousCollision";
        case Stage::Sleep: return "sleep";
        case Stage::Count: break;
    }
    return "unknown";
}

}  // namespace simcore
