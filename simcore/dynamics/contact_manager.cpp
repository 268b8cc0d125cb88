#include "simcore/dynamics/contact_manager.h"

#include "simcore/collision/collide_mesh.h"
#include "simcore/collision/collide_shapes.h"

#include <algorithm>
#include <cmath>
#include <utility>

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

// The contact's material from its bodies' (dense indices a and b); rolling on the sub-shapes that touch.
void combineMaterials(Contact& contact, const BodyStorage& bodies, std::size_t a, std::size_t b) {
    contact.friction = combineFriction(bodies.friction[a], bodies.friction[b]);
    contact.restitution = combineRestitution(bodies.restitution[a], bodies.restitution[b]);
    contact.rollingLever = combineRollingResistance(
        bodies.rollingResistance[a], rollingRadius(subShape(bodies.shape[a], contact.subShapeA)),
        bodies.rollingResistance[b], rollingRadius(subShape(bodies.shape[b], contact.subShapeB)));
}

// Whether a body collides through its sub-shapes one pair at a time (a compound's children, a
// surface's triangles); a convex shape is its own single sub-shape and collides whole.
bool hasSeveralSubShapes(const Shape& shape) { return !isConvex(shape.type); }

// Speculative margin: how far the surfaces can approach within the step (relative linear speed
// plus each body's spin times its reach), so a fast impact is met at contact rather than
// discovered a step later deep inside, where pushing out adds energy.
float speculativeMargin(const BodyStorage& bodies, std::size_t a, std::size_t b, float speculativeDistance,
                        float timeStep) {
    const float approachSpeed =
        glm::length(bodies.linearVelocity[b] - bodies.linearVelocity[a]) +
        glm::length(bodies.angularVelocity[a]) * glm::length(bodies.bounds[a].halfExtents()) +
        glm::length(bodies.angularVelocity[b]) * glm::length(bodies.bounds[b].halfExtents());
    return speculativeDistance + timeStep * approachSpeed;
}

Aabb grown(Aabb box, float margin) {
    box.min -= Vec3(margin);
    box.max += Vec3(margin);
    return box;
}

// Triangle `sub` of surface body i, in the world.
Triangle surfaceTriangle(const BodyStorage& bodies, std::size_t i, std::uint32_t sub) {
    return visitSurface(bodies.shape[i], [&](const auto& surface) { return surface.triangle(sub); })
        .placed(bodies.transform(i));
}

// A sub-shape's tight world bounds; a convex body's are the body's, already current this step.
Aabb subShapeWorldBounds(const BodyStorage& bodies, std::size_t i, std::uint32_t sub) {
    const Shape& shape = bodies.shape[i];
    if (!hasSeveralSubShapes(shape)) return bodies.bounds[i];
    if (isSurface(shape.type)) {
        Aabb bounds;
        for (const Vec3& v : surfaceTriangle(bodies, i, sub).vertices) bounds.grow(v);
        return bounds;
    }
    return worldBounds(subShape(shape, sub), subShapeTransform(shape, sub, bodies.transform(i)));
}

// Calls visit(sub) for each sub-shape of body i whose tight world bounds overlap `box`. A
// compound's children are few (limits::kMaxCompoundChildren): a scan of their bounds in the body
// frame against the box brought into that frame beats a tree, and skips computing the world bounds
// of children that are far (a child that reaches into the box passes both tests); they come in
// index order. A surface's triangles come from its own mid-phase (a BVH, or a height field's grid)
// queried in its frame, in that structure's fixed order.
template <class Visit>
void forEachSubShapeOverlapping(const BodyStorage& bodies, std::size_t i, const Aabb& box, Visit visit) {
    const Shape& shape = bodies.shape[i];
    if (!hasSeveralSubShapes(shape)) {
        if (bodies.bounds[i].overlaps(box)) visit(0u);
        return;
    }
    const Aabb local = boundsInFrame(box, bodies.transform(i));
    if (isSurface(shape.type)) {
        visitSurface(shape, [&](const auto& surface) {
            surface.forEachTriangleOverlapping(local, [&](std::uint32_t triangle) {
                if (subShapeWorldBounds(bodies, i, triangle).overlaps(box)) visit(triangle);
            });
        });
        return;
    }
    const auto count = static_cast<std::uint32_t>(subShapeCount(shape));
    for (std::uint32_t sub = 0; sub < count; ++sub)
        if (subShapeLocalBounds(shape, sub).overlaps(local) && subShapeWorldBounds(bodies, i, sub).overlaps(box))
            visit(sub);
}

std::uint64_t subShapePairKey(std::uint32_t subShapeA, std::uint32_t subShapeB) {
    return (std::uint64_t(subShapeA) << 32) | subShapeB;
}

// The manifold of sub-shape subA of body a against sub-shape subB of body b, normal from a to b.
// A surface's sub-shape is a triangle, collided with collideTriangleConvex (normal from the
// triangle); two surfaces never meet (neither is dynamic, so they get no contact).
void collideSubShapes(const BodyStorage& bodies, std::size_t a, std::uint32_t subA, std::size_t b, std::uint32_t subB,
                      float margin, ContactManifold& manifold) {
    const Shape& shapeA = bodies.shape[a];
    const Shape& shapeB = bodies.shape[b];
    if (isSurface(shapeA.type)) {
        collideTriangleConvex(surfaceTriangle(bodies, a, subA), subShape(shapeB, subB),
                              subShapeTransform(shapeB, subB, bodies.transform(b)), margin, manifold);
        return;
    }
    if (isSurface(shapeB.type)) {
        collideTriangleConvex(surfaceTriangle(bodies, b, subB), subShape(shapeA, subA),
                              subShapeTransform(shapeA, subA, bodies.transform(a)), margin, manifold);
        // Seen from a: the normal turns round and the points swap sides; separations stay.
        manifold.normal = -manifold.normal;
        for (int p = 0; p < manifold.pointCount; ++p) std::swap(manifold.points[p].pointA, manifold.points[p].pointB);
        return;
    }
    collideShapes(subShape(shapeA, subA), subShapeTransform(shapeA, subA, bodies.transform(a)), subShape(shapeB, subB),
                  subShapeTransform(shapeB, subB, bodies.transform(b)), margin, manifold);
}

// Keeps the manifold just made (with points), for reuseManifold.
void keepManifold(ManifoldRecord& record, const Transform& ta, const Transform& tb) {
    const ContactManifold& manifold = record.manifold;
    KeptManifold& kept = record.kept;
    kept.rotationA = ta.rotation;
    kept.rotationB = tb.rotation;
    kept.positionBInA = ta.applyInverse(tb.position);
    kept.reachB = 0.0f;
    for (int p = 0; p < manifold.pointCount; ++p) {
        kept.offsetA[p] = manifold.points[p].pointA - ta.position;
        kept.offsetB[p] = manifold.points[p].pointB - tb.position;
        kept.reachB = std::max(kept.reachB, glm::length(kept.offsetB[p]));
    }
}

// Moves the kept manifold's points with their bodies and measures their separations again, if no
// point of B has moved against A by more than `reuseDistance` since it was made. Fresh SAT and
// clipping would find the same features at points at most that far from these.
bool reuseManifold(ManifoldRecord& record, const Transform& ta, const Transform& tb, float reuseDistance) {
    const KeptManifold& kept = record.kept;
    const Vec3 shift = ta.applyInverse(tb.position) - kept.positionBInA;
    // |xyz| of the turn of B against A since then is sin(angle / 2), whichever sign the quaternion
    // has; a point at distance r from B's origin moves by 2 sin(angle / 2) r.
    const Quat bInAWhenMade = glm::conjugate(kept.rotationA) * kept.rotationB;
    const Quat turn = glm::conjugate(bInAWhenMade) * (glm::conjugate(ta.rotation) * tb.rotation);
    const float turnMove = 2.0f * glm::length(Vec3(turn.x, turn.y, turn.z)) * kept.reachB;
    if (glm::length(shift) + turnMove > reuseDistance) return false;
    const Quat turnA = ta.rotation * glm::conjugate(kept.rotationA);
    const Quat turnB = tb.rotation * glm::conjugate(kept.rotationB);
    ContactManifold& manifold = record.manifold;
    for (int p = 0; p < manifold.pointCount; ++p) {
        ContactPoint& point = manifold.points[p];
        point.pointA = ta.position + kept.offsetA[p];
        point.pointB = tb.position + kept.offsetB[p];
        const Vec3 apart = tb.position + turnB * kept.offsetB[p] - ta.position - turnA * kept.offsetA[p];
        point.separation = glm::dot(apart, manifold.normal);
    }
    return true;
}

// A contact's manifold made anew, with impulses carried over from its old points.
void storeFreshManifold(ManifoldRecord& record, const ContactManifold& manifold, const Transform& ta,
                        const Transform& tb) {
    record.impulses = matchImpulses(record.manifold, record.impulses, manifold);
    record.manifold = manifold;
    keepManifold(record, ta, tb);
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
        if (pairToSubShapeBodyPair_.find(key) != PairTable::kNotFound) continue;
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
        const bool dynamicPair = dynamicA && dynamicB;
        if (dynamicPair) {
            ++contactsOfSlot_[pair.a];
            ++contactsOfSlot_[pair.b];
        }

        if (hasSeveralSubShapes(bodies.shape[a]) || hasSeveralSubShapes(bodies.shape[b])) {
            pairToSubShapeBodyPair_.insert(key, static_cast<std::uint32_t>(subShapeBodyPairs_.size()));
            subShapeBodyPairs_.push_back({pair.a, pair.b, dynamicPair, {}});
            continue;
        }
        Contact contact;
        contact.slotA = pair.a;
        contact.slotB = pair.b;
        combineMaterials(contact, bodies, a, b);
        pairToContact_.insert(key, static_cast<std::uint32_t>(contacts_.size()));
        contact.dynamicPair = dynamicPair;
        contacts_.push_back(contact);
    }
    return refused;
}

void ContactManager::findSubShapePairs(const BodyStorage& bodies, const BroadPhase& broadPhase,
                                       float speculativeDistance, float timeStep) {
    for (std::size_t p = 0; p < subShapeBodyPairs_.size();) {
        SubShapeBodyPair& pair = subShapeBodyPairs_[p];
        const std::size_t a = bodies.denseIndexOfSlot(pair.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(pair.slotB);
        // The same tests, in the same order, as refreshManifold: a sleeping pair keeps its
        // contacts, and a pair whose fat boxes parted goes (its contacts go in the narrow phase).
        if (!bodies.isAwakeDynamic(a) && !bodies.isAwakeDynamic(b)) {
            ++p;
            continue;
        }
        if (!broadPhase.testOverlap(bodies.proxy[a], bodies.proxy[b])) {
            removeSubShapeBodyPairAt(p);
            continue;
        }
        const float margin = speculativeMargin(bodies, a, b, speculativeDistance, timeStep);
        forEachSubShapeOverlapping(bodies, a, grown(bodies.bounds[b], margin), [&](std::uint32_t subA) {
            forEachSubShapeOverlapping(bodies, b, grown(subShapeWorldBounds(bodies, a, subA), margin),
                                       [&](std::uint32_t subB) {
                const std::uint64_t key = subShapePairKey(subA, subB);
                const auto at = std::lower_bound(pair.subShapePairs.begin(), pair.subShapePairs.end(), key);
                if (at != pair.subShapePairs.end() && *at == key) return;
                pair.subShapePairs.insert(at, key);
                Contact contact;
                contact.slotA = pair.slotA;
                contact.slotB = pair.slotB;
                contact.subShapeA = subA;
                contact.subShapeB = subB;
                contact.ofSubShapeBodyPair = true;
                combineMaterials(contact, bodies, a, b);
                contacts_.push_back(contact);
            });
        });
        ++p;
    }
}

// The narrow phase for one contact: reads the bodies and writes only this contact's record. A
// contact without one that now has points is only reported: records are taken after the parallel
// pass, and its manifold is made again then (pairs begin to touch far more rarely than they stay
// in touch, and keeping those manifolds in the meantime would cost more memory than the pool saves).
ContactManager::PairChange ContactManager::refreshManifold(const Contact& contact, const BodyStorage& bodies,
                                                           const BroadPhase& broadPhase, float speculativeDistance,
                                                           float reuseDistance, float timeStep) {
    const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
    const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
    // A sleeping pair keeps its manifold, ready for when it wakes.
    if (!bodies.isAwakeDynamic(a) && !bodies.isAwakeDynamic(b)) return PairChange::None;
    // Its bodies' fat boxes no longer overlap: it goes.
    if (!broadPhase.testOverlap(bodies.proxy[a], bodies.proxy[b])) return PairChange::Separates;
    ManifoldRecord* record = contact.hasPoints() ? &manifolds_[contact.manifoldIndex] : nullptr;
    if (record && reuseManifold(*record, bodies.transform(a), bodies.transform(b), reuseDistance))
        return PairChange::None;

    const PairChange noPoints = record ? PairChange::LosesPoints : PairChange::None;
    const float margin = speculativeMargin(bodies, a, b, speculativeDistance, timeStep);
    // Fat boxes overlap long before shapes touch: when even the tight boxes, grown by the
    // margin, are apart, the pair has no points and the shape test is skipped.
    const Aabb reach = grown(subShapeWorldBounds(bodies, a, contact.subShapeA), margin);
    if (!reach.overlaps(subShapeWorldBounds(bodies, b, contact.subShapeB))) {
        // Made by the mid-phase, it goes: the mid-phase makes it again when the sub-shapes near.
        return contact.ofSubShapeBodyPair ? PairChange::Separates : noPoints;
    }

    ContactManifold manifold;
    collideSubShapes(bodies, a, contact.subShapeA, b, contact.subShapeB, margin, manifold);
    if (manifold.pointCount == 0) return noPoints;
    if (!record) return PairChange::GainsPoints;
    storeFreshManifold(*record, manifold, bodies.transform(a), bodies.transform(b));
    return PairChange::None;
}

void ContactManager::updateManifolds(const BodyStorage& bodies, const BroadPhase& broadPhase,
                                     float speculativeDistance, float reuseDistance, float timeStep, TaskPool& pool) {
    findSubShapePairs(bodies, broadPhase, speculativeDistance, timeStep);
    // Each contact's update reads the bodies and writes only that contact's record, so the contacts
    // are refreshed in parallel. What changes the pool or the list of contacts follows on this
    // thread, in contact order: records given back, then taken (and their first manifolds made, in
    // parallel again, each into its own record), then the separated contacts removed in the order a
    // single pass would remove them (removal moves the last contact into the gap: the order is part
    // of the state). A resting pile changes nothing, and then those passes are skipped.
    changes_.resize(contacts_.size());
    const std::uint64_t changed =
        pool.parallelSum(contacts_.size(), kNarrowPhaseGrain, [&](std::size_t begin, std::size_t end) {
            std::uint64_t count = 0;
            for (std::size_t c = begin; c < end; ++c) {
                changes_[c] = refreshManifold(contacts_[c], bodies, broadPhase, speculativeDistance, reuseDistance, timeStep);
                count += changes_[c] != PairChange::None;
            }
            return count;
        });
    if (changed == 0) return;
    gainingPoints_.clear();
    for (std::size_t c = 0; c < contacts_.size(); ++c) {
        if (changes_[c] == PairChange::LosesPoints) releaseManifold(contacts_[c]);
        if (changes_[c] == PairChange::GainsPoints) gainingPoints_.push_back(static_cast<std::uint32_t>(c));
    }
    // Grown once for all of them: a scene's first step takes a record for every touching pair
    // (20 540 in pyramid20), and growing one record at a time copied the pool over and over.
    const std::size_t recordsNeeded = manifolds_.size() + gainingPoints_.size() -
                                      std::min(gainingPoints_.size(), freeManifolds_.size());
    if (recordsNeeded > manifolds_.capacity()) manifolds_.reserve(std::max(recordsNeeded, 2 * manifolds_.capacity()));
    for (const std::uint32_t c : gainingPoints_) takeManifold(contacts_[c]);
    pool.parallelFor(gainingPoints_.size(), kNarrowPhaseGrain, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const Contact& contact = contacts_[gainingPoints_[k]];
            const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
            const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
            // The test refreshManifold ran, on the same bodies: the same points, bit for bit.
            ContactManifold manifold;
            collideSubShapes(bodies, a, contact.subShapeA, b, contact.subShapeB,
                             speculativeMargin(bodies, a, b, speculativeDistance, timeStep), manifold);
            storeFreshManifold(manifolds_[contact.manifoldIndex], manifold, bodies.transform(a), bodies.transform(b));
        }
    });
    for (std::size_t c = 0; c < contacts_.size();) {
        if (changes_[c] != PairChange::Separates) {
            ++c;
            continue;
        }
        changes_[c] = changes_.back();  // removeAt moves the last contact into slot c: visit it next
        changes_.pop_back();
        removeAt(c);
    }
}

// A contact that gains points takes a record with no points and no impulses: its new points start
// from zero, as they would match no old point.
void ContactManager::takeManifold(Contact& contact) {
    ++manifoldListVersion_;
    if (freeManifolds_.empty()) {
        contact.manifoldIndex = static_cast<std::uint32_t>(manifolds_.size());
        manifolds_.push_back({});  // the allocator would leave a bare emplace_back() unwritten
        return;
    }
    contact.manifoldIndex = freeManifolds_.back();
    freeManifolds_.pop_back();
    manifolds_[contact.manifoldIndex] = {};
}

void ContactManager::releaseManifold(Contact& contact) {
    ++manifoldListVersion_;
    freeManifolds_.push_back(contact.manifoldIndex);
    contact.manifoldIndex = Contact::kNoManifold;
    contact.normalImpulse = 0.0f;
}

void ContactManager::removeAt(std::size_t index) {
    ++manifoldListVersion_;
    Contact& gone = contacts_[index];
    if (gone.hasPoints()) releaseManifold(gone);
    const std::uint64_t bodyKey = PairTable::key(gone.slotA, gone.slotB);
    if (gone.ofSubShapeBodyPair) {
        // Its body pair may have gone first (fat boxes parted): then there is nothing to update.
        if (const std::uint32_t p = pairToSubShapeBodyPair_.find(bodyKey); p != PairTable::kNotFound) {
            std::vector<std::uint64_t>& list = subShapeBodyPairs_[p].subShapePairs;
            const auto at = std::lower_bound(list.begin(), list.end(), subShapePairKey(gone.subShapeA, gone.subShapeB));
            if (at != list.end() && *at == subShapePairKey(gone.subShapeA, gone.subShapeB)) list.erase(at);
        }
    } else {
        if (gone.dynamicPair) {
            --contactsOfSlot_[gone.slotA];
            --contactsOfSlot_[gone.slotB];
        }
        pairToContact_.erase(bodyKey);
    }
    if (index + 1 != contacts_.size()) {
        contacts_[index] = contacts_.back();
        if (!contacts_[index].ofSubShapeBodyPair)
            pairToContact_.assign(PairTable::key(contacts_[index].slotA, contacts_[index].slotB),
                                  static_cast<std::uint32_t>(index));
    }
    contacts_.pop_back();
}

void ContactManager::removeSubShapeBodyPairAt(std::size_t index) {
    const SubShapeBodyPair& gone = subShapeBodyPairs_[index];
    if (gone.dynamicPair) {
        --contactsOfSlot_[gone.slotA];
        --contactsOfSlot_[gone.slotB];
    }
    pairToSubShapeBodyPair_.erase(PairTable::key(gone.slotA, gone.slotB));
    if (index + 1 != subShapeBodyPairs_.size()) {
        subShapeBodyPairs_[index] = std::move(subShapeBodyPairs_.back());
        pairToSubShapeBodyPair_.assign(PairTable::key(subShapeBodyPairs_[index].slotA, subShapeBodyPairs_[index].slotB),
                                       static_cast<std::uint32_t>(index));
    }
    subShapeBodyPairs_.pop_back();
}

void ContactManager::removeContactsOf(std::uint32_t slot) {
    for (std::size_t c = 0; c < contacts_.size();) {
        if (contacts_[c].slotA == slot || contacts_[c].slotB == slot) {
            removeAt(c);
        } else {
            ++c;
        }
    }
    for (std::size_t p = 0; p < subShapeBodyPairs_.size();) {
        if (subShapeBodyPairs_[p].slotA == slot || subShapeBodyPairs_[p].slotB == slot) {
            removeSubShapeBodyPairAt(p);
        } else {
            ++p;
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
    const std::uint64_t key = PairTable::key(slotA, slotB);
    if (const std::uint32_t index = pairToContact_.find(key); index != PairTable::kNotFound) {
        removeAt(index);
        return;
    }
    const std::uint32_t pair = pairToSubShapeBodyPair_.find(key);
    if (pair == PairTable::kNotFound) return;
    for (std::size_t c = 0; c < contacts_.size();) {
        if (PairTable::key(contacts_[c].slotA, contacts_[c].slotB) == key) {
            removeAt(c);
        } else {
            ++c;
        }
    }
    removeSubShapeBodyPairAt(pair);
}

void ContactManager::clear() {
    ++manifoldListVersion_;
    contacts_.clear();
    manifolds_.clear();
    freeManifolds_.clear();
    pairToContact_.clear();
    subShapeBodyPairs_.clear();
    pairToSubShapeBodyPair_.clear();
    contactsOfSlot_.clear();
}

}  // namespace simcore
