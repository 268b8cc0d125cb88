// World::draw: the one place that walks the world's storage for debug drawing (see debug_draw.h).

#include "simcore/world/debug_draw.h"
#include "simcore/world/world.h"

namespace simcore {

void World::draw(DebugDraw& drawer, const DebugDrawOptions& options) const {
    if (options.bodies || options.tightBounds || options.fatBounds) {
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const BodyId id = bodies_.idAt(i);
            const Transform transform = bodies_.transform(i);
            if (options.bodies) {
                drawer.drawBody({id, bodies_.shape[i], transform, bodies_.centerOfMass[i], bodies_.motion[i],
                                 bodies_.awake[i] != 0});
            }
            // Computed from the pose, not taken from bodies_.bounds: those are refreshed by the
            // broad phase, which a paused world moved by the editor has not run.
            if (options.tightBounds) drawer.drawBounds(id, worldBounds(bodies_.shape[i], transform), DebugBoundsKind::Tight);
            if (options.fatBounds) drawer.drawBounds(id, broadPhase_.fatBounds(bodies_.proxy[i]), DebugBoundsKind::Fat);
        }
    }

    if (options.contacts) {
        const auto idOfSlot = [this](std::uint32_t slot) { return bodies_.idAt(bodies_.denseIndexOfSlot(slot)); };
        for (const Contact& contact : contactManager_.contacts()) {
            if (!contact.hasPoints()) continue;
            const BodyId a = idOfSlot(contact.slotA), b = idOfSlot(contact.slotB);
            const ManifoldRecord& record = contactManager_.manifoldOf(contact);
            const ContactManifold& manifold = record.manifold;
            for (int k = 0; k < manifold.pointCount; ++k) {
                const auto point = static_cast<std::size_t>(k);
                const ContactPoint& p = manifold.points[point];
                drawer.drawContactPoint({a, b, 0.5f * (p.pointA + p.pointB), manifold.normal, p.separation,
                                         record.impulses[point].normal, p.separation > 0.0f});
            }
        }
    }

    if (options.joints) {
        for (std::size_t i = 0; i < joints_.size(); ++i) {
            const Joint& joint = joints_.joints[i];
            const JointBodyPose poseA = joints_.poseOf(joint.bodyA, bodies_);
            const JointBodyPose poseB = joints_.poseOf(joint.bodyB, bodies_);
            const JointGeometry geometry = jointGeometry(joint, poseA, poseB);
            const Vec3 anchorA = poseA.centerOfMass + geometry.armA;
            std::optional<JointLimits> limits;
            float position = 0.0f;
            switch (joint.type) {
            case JointType::Hinge:
                limits = joint.limits;
                position = geometry.hingeAngle(joint);
                break;
            case JointType::Slider:
                limits = joint.limits;
                position = geometry.slide();
                break;
            case JointType::Distance:
                limits = JointLimits{joint.minLength, joint.maxLength};
                position = glm::length(geometry.separation);
                break;
            case JointType::Ball:
            case JointType::Fixed: break;
            }
            drawer.drawJoint({joints_.idAt(i), joint.type, joint.bodyA, joint.bodyB, poseA.centerOfMass,
                              joint.bodyB.isValid() ? std::optional<Vec3>(poseB.centerOfMass) : std::nullopt, anchorA,
                              anchorA + geometry.separation, geometry.axisA, limits, position});
        }
    }
}

}  // namespace simcore
