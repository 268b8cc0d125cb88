#pragma once
// Persistent contacts: one per pair of bodies whose fat bounds overlap. Created from the broad
// phase's new pairs, refreshed by the narrow phase every step while either body is awake, and
// destroyed when the fat bounds separate. Each manifold point keeps its accumulated impulses
// across steps, matched by feature id, so the solver starts from last step's answer.

#include "simcore/collision/broad_phase.h"
#include "simcore/collision/contact_manifold.h"
#include "simcore/collision/pair_table.h"
#include "simcore/dynamics/body_storage.h"
#include "simcore/parallel/task_pool.h"

#include <array>
#include <cstdint>
#include <vector>

namespace simcore {

struct ContactImpulse {
    float normal = 0.0f;  // N s, >= 0
};

// Friction acts on a manifold as a whole, at its friction centre (see ContactSolver), so its
// impulses belong to the contact rather than to a point.
struct FrictionImpulse {
    Vec3 linear{0.0f};   // N s, world frame, in the contact plane (the solver's tangents change)
    float twist = 0.0f;  // N m s, about the normal
    Vec3 rolling{0.0f};  // N m s, world frame: the angular impulse of rolling resistance (on B; -rolling on A)
};

struct Contact {
    std::uint32_t slotA = 0, slotB = 0;  // body slots (BodyId::index): stable across removals
    float friction = 0.0f;               // combined: sqrt(frictionA * frictionB)
    float restitution = 0.0f;            // combined: max(restitutionA, restitutionB)
    float rollingLever = 0.0f;           // m, combined: max(CA, CB) max(rA, rB)
    bool dynamicPair = false;            // both bodies dynamic at creation: counts toward their contact cap
    ContactManifold manifold;
    std::array<ContactImpulse, kMaxManifoldPoints> impulses{};
    FrictionImpulse frictionImpulse;
};

// Friction combines by geometric mean (a frictionless surface makes any pair frictionless) and
// restitution by maximum (a bouncy ball bounces on any floor), as in Box2D and Jolt.
float combineFriction(float a, float b);
float combineRestitution(float a, float b);
// Rolling resistance combines into a lever length (m), the larger coefficient times the larger
// rolling radius (shape.h), as in Box2D v3: the contact's rolling torque is bounded by the lever
// times the normal force. A soft ball brakes on any floor and a carpet brakes any ball (the
// carpet is flat, but the ball's radius counts); two flat bodies get 0.
float combineRollingResistance(float coefficientA, float radiusA, float coefficientB, float radiusB);

class ContactManager {
public:
    // Creates contacts for new broad-phase pairs (userData = body slot) that involve a dynamic body,
    // except a pair of dynamic bodies where one already has maxContactsPerBody contacts with other
    // dynamic bodies (contacts with static and kinematic bodies are always made, so a crowd never
    // falls through its floor). Returns how many pairs were refused; the broad phase offers them
    // again when a body's fat box moves.
    std::size_t addPairs(const std::vector<BodyPair>& pairs, const BodyStorage& bodies, int maxContactsPerBody);

    // Narrow phase: refreshes the manifold of every contact with an awake dynamic body, and
    // destroys contacts whose bodies' fat bounds no longer overlap. Points are kept while their
    // separation is within speculativeDistance plus how far the bodies can approach in timeStep.
    // Contacts are refreshed on the pool's threads; the result does not depend on their number.
    void updateManifolds(const BodyStorage& bodies, const BroadPhase& broadPhase, float speculativeDistance,
                         float timeStep, TaskPool& pool);

    void removeContactsOf(std::uint32_t slot);
    // Recombines friction, restitution and rolling resistance of the contacts of one body slot after
    // the body's material changed; manifolds and accumulated impulses stay (warm starts intact).
    void refreshMaterials(std::uint32_t slot, const BodyStorage& bodies);
    // Drops the contact of one pair of body slots, if there is one (a joint between them that
    // turns their collision off).
    void removePair(std::uint32_t slotA, std::uint32_t slotB);
    void clear();

    std::vector<Contact>& contacts() { return contacts_; }
    const std::vector<Contact>& contacts() const { return contacts_; }

private:
    void removeAt(std::size_t index);

    std::vector<Contact> contacts_;
    PairTable pairToContact_;
    std::vector<std::uint32_t> contactsOfSlot_;  // by body slot: contacts with other dynamic bodies
    std::vector<std::uint8_t> separated_;        // scratch, by contact: to remove after the narrow phase
};

}  // namespace simcore
