#include "simcore/dynamics/contact_manager.h"

#include "simcore/collision/collide_shapes.h"

#include <cmath>

namespace simcore {

namespace {

// Contacts per chunk of the parallel narrow phase: enough shape tests to outweigh handing a chunk out.
constexpr std::size_t kNarrowPhaseGrain = 64;

// Points closer than this to last step's point (m) are taken to be the same contact.
constexpr float kPersistenceDistance = 0.01f;

// Warm start: each new point inherits the impulses of last step's point made by the same pair of
// features or, failing that, of the nearest unclaimed old point within kPersistenceDistance. The
// fallback matters where ids are ambiguous: at the corners of two coincident faces a point is both
// an incident vertex and a clip intersection, and the label flips with the tiniest rotation.
std::array<ContactImpulse, kMaxManifoldPoints> matchImpulses(const ContactManifold& old,
                                                             const std::array<ContactImpulse, kMaxManifoldPoints>& oldImpulses,
                                                             const ContactManifold& fresh) {
    std::array<ContactImpulse, kMaxManifoldPoints> impulses{};
    bool claimed[kMaxManifoldPoints] = {};
    bool matched[kMaxManifoldPoints] = {};
    for (int i = 0; i < fresh.pointCount; ++i) {
        for (int j = 0; j < old.pointCount; ++j) {
            if (!claimed[j] && old.points[j].featureId == fresh.points[i].featureId) {
                impulses[i] = oldImpulses[j];
                claimed[j] = matched[i] = true;
                break;
            }
        }
    }
    for (int i = 0; i < fresh.pointCount; ++i) {
        if (matched[i]) continue;
        int nearest = -1;
        float nearestDistance2 = kPersistenceDistance * kPersistenceDistance;
        for (int j = 0; j < old.pointCount; ++j) {
            const float d2 = lengthSquared(old.points[j].pointA - fresh.points[i].pointA);
            if (!claimed[j] && d2 < nearestDistance2) {
                nearest = j;
                nearestDistance2 = d2;
            }
        }
        if (nearest >= 0) {
            impulses[i] = oldImpulses[nearest];
            claimed[nearest] = true;
        }
    }
    return impulses;
}

// The contact's material from its bodies' (dense indices a and b).
void combineMaterials(Contact& contact, const BodyStorage& bodies, std::size_t a, std::size_t b) {
    contact.friction = combineFriction(bodies.friction[a], bodies.friction[b]);
    contact.restitution = combineRestitution(bodies.restitution[a], bodies.restitution[b]);
    contact.rollingLever = combineRollingResistance(bodies.rollingResistance[a], rollingRadius(bodies.shape[a]),
                                                    bodies.rollingResistance[b], rollingRadius(bodies.shape[b]));
}

// The narrow phase for one contact; false when its bodies' fat boxes no longer overlap and it is to go.
bool refreshManifold(Contact& contact, const BodyStorage& bodies, const BroadPhase& broadPhase, float speculativeDistance,
                     float timeStep) {
    auto isAwakeDynamic = [&bodies](std::size_t i) {
        return bodies.motion[i] == MotionType::Dynamic && bodies.awake[i];
    };
    const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
    const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
    if (!isAwakeDynamic(a) && !isAwakeDynamic(b)) return true;  // a sleeping pair keeps its manifold, ready for when it wakes
    if (!broadPhase.testOverlap(bodies.proxy[a], bodies.proxy[b])) return false;

    // Speculative margin: how far the surfaces can approach within the step (relative linear
    // speed plus each body's spin times its reach), so a fast impact is met at contact rather
    // than discovered a step later deep inside, where pushing out adds energy.
    const float approachSpeed =
        glm::length(bodies.linearVelocity[b] - bodies.linearVelocity[a]) +
        glm::length(bodies.angularVelocity[a]) * glm::length(bodies.bounds[a].halfExtents()) +
        glm::length(bodies.angularVelocity[b]) * glm::length(bodies.bounds[b].halfExtents());
    const float margin = speculativeDistance + timeStep * approachSpeed;

    // Fat boxes overlap long before shapes touch: when even the tight boxes, grown by the
    // margin, are apart, the pair has no points and the shape test is skipped.
    Aabb reach = bodies.bounds[a];
    reach.min -= Vec3(margin);
    reach.max += Vec3(margin);
    if (!reach.overlaps(bodies.bounds[b])) {
        contact.manifold.pointCount = 0;
        contact.impulses = {};
        contact.frictionImpulse = {};
        return true;
    }

    ContactManifold manifold;
    collideShapes(bodies.shape[a], bodies.transform(a), bodies.shape[b], bodies.transform(b), margin, manifold);

    contact.impulses = matchImpulses(contact.manifold, contact.impulses, manifold);
    contact.manifold = manifold;
    return true;
}

}  // namespace

float combineFriction(float a, float b) { return std::sqrt(a * b); }
float combineRestitution(float a, float b) { return std::max(a, b); }
float combineRollingResistance(float coefficientA, float radiusA, float coefficientB, float radiusB) {
    return std::max(coefficientA, coefficientB) * std::max(radiusA, radiusB);
}

std::size_t ContactManager::addPairs(const std::vector<BodyPair>& pairs, const BodyStorage& bodies,
                                     int maxContactsPerBody) {
    std::size_t refused = 0;
    const auto cap = static_cast<std::uint32_t>(maxContactsPerBody);
    for (const BodyPair& pair : pairs) {
        const std::uint64_t key = PairTable::key(pair.a, pair.b);
        if (pairToContact_.find(key) != PairTable::kNotFound) continue;
        const std::size_t a = bodies.denseIndexOfSlot(pair.a);
        const std::size_t b = bodies.denseIndexOfSlot(pair.b);
        const bool dynamicA = bodies.motion[a] == MotionType::Dynamic;
        const bool dynamicB = bodies.motion[b] == MotionType::Dynamic;
        if (!dynamicA && !dynamicB) continue;
        const std::size_t slots = std::max(pair.a, pair.b) + std::size_t{1};
        if (contactsOfSlot_.size() < slots) contactsOfSlot_.resize(slots, 0);  // only when bodies were added
        if (dynamicA && dynamicB && std::max(contactsOfSlot_[pair.a], contactsOfSlot_[pair.b]) >= cap) {
            ++refused;
            continue;
        }

        Contact contact;
        contact.slotA = pair.a;
        contact.slotB = pair.b;
        combineMaterials(contact, bodies, a, b);
        pairToContact_.insert(key, static_cast<std::uint32_t>(contacts_.size()));
        contact.dynamicPair = dynamicA && dynamicB;
        contacts_.push_back(contact);
        if (contact.dynamicPair) {
            ++contactsOfSlot_[pair.a];
            ++contactsOfSlot_[pair.b];
        }
    }
    return refused;
}

void ContactManager::updateManifolds(const BodyStorage& bodies, const BroadPhase& broadPhase,
                                     float speculativeDistance, float timeStep, TaskPool& pool) {
    // Each contact's update reads the bodies and writes only that contact, so the contacts are
    // refreshed in parallel and the separated ones removed after, in the order a single pass
    // would remove them (removal moves the last contact into the gap: the order is part of the
    // state).
    separated_.resize(contacts_.size());
    pool.parallelFor(contacts_.size(), kNarrowPhaseGrain, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t c = begin; c < end; ++c)
            separated_[c] = !refreshManifold(contacts_[c], bodies, broadPhase, speculativeDistance, timeStep);
    });
    for (std::size_t c = 0; c < contacts_.size();) {
        if (!separated_[c]) {
            ++c;
            continue;
        }
        separated_[c] = separated_.back();  // removeAt moves the last contact into slot c: visit it next
        separated_.pop_back();
        removeAt(c);
    }
}

void ContactManager::removeAt(std::size_t index) {
    if (contacts_[index].dynamicPair) {
        --contactsOfSlot_[contacts_[index].slotA];
        --contactsOfSlot_[contacts_[index].slotB];
    }
    pairToContact_.erase(PairTable::key(contacts_[index].slotA, contacts_[index].slotB));
    if (index + 1 != contacts_.size()) {
        contacts_[index] = contacts_.back();
        pairToContact_.assign(PairTable::key(contacts_[index].slotA, contacts_[index].slotB),
                              static_cast<std::uint32_t>(index));
    }
    contacts_.pop_back();
}

void ContactManager::removeContactsOf(std::uint32_t slot) {
    for (std::size_t c = 0; c < contacts_.size();) {
        if (contacts_[c].slotA == slot || contacts_[c].slotB == slot) {
            removeAt(c);
        } else {
            ++c;
        }
    }
}

void ContactManager::refreshMaterials(std::uint32_t slot, const BodyStorage& bodies) {
    for (Contact& contact : contacts_) {
        if (contact.slotA != slot && contact.slotB != slot) continue;
        combineMaterials(contact, bodies, bodies.denseIndexOfSlot(contact.slotA), bodies.denseIndexOfSlot(contact.slotB));
    }
}

void ContactManager::removePair(std::uint32_t slotA, std::uint32_t slotB) {
    const std::uint32_t index = pairToContact_.find(PairTable::key(slotA, slotB));
    if (index != PairTable::kNotFound) removeAt(index);
}

void ContactManager::clear() {
    contacts_.clear();
    pairToContact_.clear();
    contactsOfSlot_.clear();
}

}  // namespace simcore
