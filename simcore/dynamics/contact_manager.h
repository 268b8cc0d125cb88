#pragma once
// Persistent contacts: one per pair of sub-shapes (shape.h) of two bodies whose fat bounds overlap.
// Each manifold point keeps its accumulated impulses across steps, matched by feature id within
// its sub-shape pair, so the solver starts from last step's answer.
// A contact is only the pair; its manifold and impulses (a ManifoldRecord) exist while it has
// points, in a pool of records reused through a free list, since most pairs never touch.
//
// Two bodies with one sub-shape each (every convex shape) have one contact, created from the
// broad phase's new pair and destroyed when their fat bounds separate. A body pair where either
// side has several sub-shapes (a compound) gets a SubShapeBodyPair instead, and each step, while
// either body is awake, a mid-phase finds its sub-shape pairs whose tight bounds, grown by the
// speculative margin, overlap: each gets a contact, dropped again once its bounds part. See
// docs/architecture.md ("Contacts per pair of sub-shapes") for how a triangle mesh plugs in.

#include "simcore/collision/broad_phase.h"
#include "simcore/collision/contact_manifold.h"
#include "simcore/collision/pair_table.h"
#include "simcore/dynamics/body_storage.h"
#include "simcore/parallel/large_array_allocator.h"
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

// A manifold as the narrow phase last made it, kept while the pair's relative pose stays within a
// small tolerance of the pose it was made at (see ContactManager::updateManifolds). Kept, it is
// what the solver's substeps make of a manifold within a step (Box3D's contact recycling): the
// normal stays fixed in the world and each point stays at a fixed offset, in world axes, from its
// own body's origin, moving with the body but not turning with it; only the separations are
// measured again, from the offsets turned with their bodies. Points that turned with their bodies
// carried a stacked cube's support round with its tilt, and an awake tower of 28 unit cubes or more
// buckled (docs/testing.md); kept fixed, 40 and 60 stand.
struct KeptManifold {
    Quat rotationA{1.0f, 0.0f, 0.0f, 0.0f}, rotationB{1.0f, 0.0f, 0.0f, 0.0f};  // the bodies' when made
    Vec3 positionBInA{0.0f};                                    // B's origin in A's frame when made
    std::array<Vec3, kMaxManifoldPoints> offsetA{}, offsetB{};  // each point from its body's origin, world axes
    float reachB = 0.0f;  // the farthest point from B's origin (m): how far a turn of B moves them
};

// What a contact carries only while it has points: its manifold, what keeping it needs, and the
// impulses accumulated on it. Most pairs the broad phase finds never touch (in a
// resting pile of cubes, three in four), so these live in a pool of their own, taken when a
// contact gains points and given back when it loses them, and a pair without points costs only
// its Contact.
struct ManifoldRecord {
    // The solver's part first: prepare and storeImpulses read or write only these, fetched ahead.
    ContactManifold manifold;             // world frame, as the narrow phase made or moved it this step
    std::array<ContactImpulse, kMaxManifoldPoints> impulses{};
    FrictionImpulse frictionImpulse;
    // m: how much deeper than its points the manifold's soft spring acts, so that it holds its
    // load nearly touching (ContactSolver::kGiveOffsetRate).
    float giveOffset = 0.0f;
    KeptManifold kept;
};

struct Contact {
    static constexpr std::uint32_t kNoManifold = ~std::uint32_t{0};

    std::uint32_t slotA = 0, slotB = 0;  // body slots (BodyId::index): stable across removals
    std::uint32_t subShapeA = 0, subShapeB = 0;  // sub-shape of each body (0 for a convex shape)
    float friction = 0.0f;               // combined: sqrt(frictionA * frictionB)
    float restitution = 0.0f;            // combined: max(restitutionA, restitutionB)
    float rollingLever = 0.0f;           // m, combined: max(CA, CB) max(rA, rB)
    // Its ManifoldRecord (ContactManager::manifoldOf) while it has points, else kNoManifold.
    std::uint32_t manifoldIndex = kNoManifold;
    // N s: the points' summed normal impulse in the last substep solved (ContactSolver::
    // storeImpulses), the load that stiffens the contact's spring. Kept here as well as in the
    // manifold's record so that colouring the manifolds reads no record.
    float normalImpulse = 0.0f;
    bool ofSubShapeBodyPair = false;     // made by the mid-phase for a body pair with several sub-shapes
    bool dynamicPair = false;            // both bodies dynamic at creation: counts toward their contact cap
                                         // (false in a SubShapeBodyPair, which counts once for all)

    bool hasPoints() const { return manifoldIndex != kNoManifold; }
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
    // Creates contacts (or a SubShapeBodyPair) for new broad-phase pairs (userData = body slot) that involve a dynamic body,
    // except a pair of dynamic bodies where one already has maxContactsPerBody contacts with other
    // dynamic bodies (contacts with static and kinematic bodies are always made, so a crowd never
    // falls through its floor). Returns how many pairs were refused; the broad phase offers them
    // again when a body's fat box moves.
    std::size_t addPairs(const std::vector<BodyPair>& pairs, const BodyStorage& bodies, int maxContactsPerBody);

    // Mid-phase, then narrow phase: makes the contacts of the sub-shape pairs that came near (in a
    // fixed order, on one thread), refreshes the manifold of every contact with an awake dynamic
    // body, and destroys contacts whose bodies' fat bounds (or, with several sub-shapes, whose
    // sub-shapes' grown bounds) no longer overlap. Points are kept while their
    // separation is within speculativeDistance plus how far the bodies can approach in timeStep.
    // Contacts are refreshed on the pool's threads; the result does not depend on their number.
    //
    // A pair whose relative pose moved by less than `reuseDistance` (m: any point of it, turning
    // included) since its manifold was made keeps that manifold (KeptManifold): its normal and
    // points stay as they were made and only their separations are measured again. A resting
    // pair's pose changes by micrometres a step, and running SAT and clipping on it anew was most
    // of the narrow phase of a resting pyramid.
    void updateManifolds(const BodyStorage& bodies, const BroadPhase& broadPhase, float speculativeDistance,
                         float reuseDistance, float timeStep, TaskPool& pool);

    void removeContactsOf(std::uint32_t slot);
    // Recombines friction, restitution and rolling resistance of the contacts of one body slot after
    // the body's material changed; manifolds and accumulated impulses stay (warm starts intact).
    void refreshMaterials(std::uint32_t slot, const BodyStorage& bodies);
    // Drops the contacts of one pair of body slots, if there are any (a joint between them that
    // turns their collision off).
    void removePair(std::uint32_t slotA, std::uint32_t slotB);
    void clear();

    const std::vector<Contact>& contacts() const { return contacts_; }
    std::vector<Contact>& contacts() { return contacts_; }
    // The manifold and impulses of a contact that has points (contact.hasPoints()).
    const ManifoldRecord& manifoldOf(const Contact& contact) const { return manifolds_[contact.manifoldIndex]; }
    ManifoldRecord& manifoldOf(const Contact& contact) { return manifolds_[contact.manifoldIndex]; }

    std::size_t subShapeBodyPairCount() const { return subShapeBodyPairs_.size(); }

    // Changes whenever a contact gains or loses points or leaves the list (which moves another
    // into its place): the solver colours the manifolds again only then (ContactSolver::prepare).
    // A new contact has no points and goes at the end, so it leaves this as it was.
    std::uint64_t manifoldListVersion() const { return manifoldListVersion_; }

private:
    // A pair of bodies at least one of which has several sub-shapes: its contacts are made by the
    // mid-phase, one per sub-shape pair that came near.
    struct SubShapeBodyPair {
        std::uint32_t slotA = 0, slotB = 0;
        bool dynamicPair = false;  // counts once toward both bodies' contact cap
        std::vector<std::uint64_t> subShapePairs;  // sorted (subShapeA << 32 | subShapeB) of its contacts
    };

    // What the narrow phase found for one contact. The parallel pass only notes it; the changes to
    // the contact list and the manifold pool follow on one thread, in contact order, so that they
    // are race-free and the same for any thread count.
    enum class PairChange : std::uint8_t {
        None,         // kept its points (refreshed, moved along or asleep), or still has none
        GainsPoints,  // had none and has some now: collided again, into the record taken for it
        LosesPoints,  // its ManifoldRecord goes back to the pool
        Separates,    // the contact goes
    };
    PairChange refreshManifold(const Contact& contact, const BodyStorage& bodies, const BroadPhase& broadPhase,
                               float speculativeDistance, float reuseDistance, float timeStep);
    void takeManifold(Contact& contact);
    void releaseManifold(Contact& contact);
    void findSubShapePairs(const BodyStorage& bodies, const BroadPhase& broadPhase, float speculativeDistance,
                           float timeStep);
    void removeAt(std::size_t index);
    void removeSubShapeBodyPairAt(std::size_t index);

    std::vector<Contact> contacts_;
    PairTable pairToContact_;  // body pairs with one sub-shape each -> their contact
    std::vector<SubShapeBodyPair> subShapeBodyPairs_;
    PairTable pairToSubShapeBodyPair_;
    std::vector<std::uint32_t> contactsOfSlot_;  // by body slot: contacts with other dynamic bodies
    std::vector<ManifoldRecord, LargeArrayAllocator<ManifoldRecord>> manifolds_;  // the pool: records in use and free ones
    std::vector<std::uint32_t> freeManifolds_;         // indices into manifolds_ not in use, taken last in first out
    std::vector<PairChange> changes_;                  // scratch, by contact: what the narrow phase found
    std::vector<std::uint32_t> gainingPoints_;         // scratch: contacts that gained points this step, in order
    std::uint64_t manifoldListVersion_ = 0;
};

}  // namespace simcore
