#pragma once
// Sequential impulses on contact manifolds: accumulated impulses with clamping, warm starting,
// Coulomb friction on two tangents bounded by the normal impulse, restitution above a velocity
// threshold, speculative contacts, and soft-step or Baumgarte position correction.
//
// Within one World::step the solver is used as:
//   prepare (once) -> for each substep { warmStart, solve(useBias=true) x N, [positions move],
//   relax = solve(useBias=false) x M } -> applyRestitution -> storeImpulses.

#include "simcore/collision/contact_manager.h"
#include "simcore/dynamics/body_storage.h"
#include "simcore/world/world_settings.h"

#include <vector>

namespace simcore {

class ContactSolver {
public:
    struct Params {
        float substepDt = 1.0f / 240.0f;
        bool friction = true;
        bool restitution = true;
        SolverSettings solver;
        ContactSettings contact;
    };

    // Builds constraints for touching contacts with an awake dynamic body. Sleeping and static
    // bodies take part with infinite mass.
    void prepare(const std::vector<Contact>& contacts, const BodyStorage& bodies, const Params& params);
    void warmStart(BodyStorage& bodies) const;
    void solve(BodyStorage& bodies, bool useBias);
    void applyRestitution(BodyStorage& bodies);
    void storeImpulses(std::vector<Contact>& contacts) const;

    std::size_t constraintCount() const { return constraints_.size(); }
    // Whether any prepared constraint has friction rows / can bounce (effects that ran).
    bool usesFriction() const { return usesFriction_; }
    bool usesRestitution() const { return usesRestitution_; }
    float maxPenetration() const { return maxPenetration_; }  // at prepare time (m)

private:
    // Rows of a point: the normal, then the two friction tangents.
    static constexpr int kNormal = 0, kTangent1 = 1, kTangent2 = 2, kRowCount = 3;

    struct Point {
        Vec3 localAnchorA, localAnchorB;  // contact point relative to each centre of mass, body axes
        float baseSeparation = 0.0f;      // separation at prepare (m)
        // Per row: the angular Jacobians r x axis and their inertia-weighted forms I^-1 (r x axis),
        // computed once per step so each iteration is dot products and multiply-adds.
        Vec3 angularA[kRowCount], angularB[kRowCount];
        Vec3 weightedA[kRowCount], weightedB[kRowCount];
        float mass[kRowCount] = {};       // effective mass of each row (kg)
        float impulse[kRowCount] = {};    // accumulated (N s)
        float maxNormalImpulse = 0.0f;    // largest normal impulse this step: did the point push?
        float approachVelocity = 0.0f;    // normal relative velocity at prepare (m/s), for restitution
    };
    struct Constraint {
        std::uint32_t contactIndex = 0;
        std::uint32_t bodyA = 0, bodyB = 0;  // dense indices
        float inverseMassA = 0.0f, inverseMassB = 0.0f;
        Vec3 axes[kRowCount];  // normal (from A to B), tangent1, tangent2
        float friction = 0.0f, restitution = 0.0f;
        int pointCount = 0;
        Point points[kMaxManifoldPoints];
    };

    std::vector<Constraint> constraints_;
    Params params_;
    float biasRate_ = 0.0f, massScale_ = 1.0f, impulseScale_ = 0.0f;  // soft-contact coefficients
    float maxPenetration_ = 0.0f;
    bool usesFriction_ = false;
    bool usesRestitution_ = false;
};

}  // namespace simcore
