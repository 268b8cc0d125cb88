#include "app/viewport/body_batches.h"

#include "app/simulation/simulation_controller.h"
#include "app/viewport/look.h"

#include "simcore/world/world.h"

#include <glm/gtc/quaternion.hpp>

namespace interplay {
namespace {

glm::mat4 modelMatrix(const simcore::Transform& t) {
    glm::mat4 m = glm::mat4_cast(t.rotation);
    m[3] = glm::vec4(t.position, 1.0f);
    return m;
}

// The outline box of a convex shape: its local bounds, kept from collapsing to nothing.
void setOutlineBounds(const simcore::Shape& shape, glm::vec3& center, glm::vec3& halfSize) {
    const simcore::Aabb bounds = simcore::localBounds(shape);
    center = bounds.center();
    halfSize = glm::max(0.5f * (bounds.max - bounds.min), glm::vec3(1e-4f));
}

}  // namespace

glm::vec3 BodyBatches::displayColor(std::size_t sceneIndex, const std::optional<glm::vec3>& authored,
                                    simcore::MotionType motion) {
    if (authored) return *authored;
    if (motion == simcore::MotionType::Static) return look::srgb(look::kStaticColor);
    return look::srgb(look::kPalette[sceneIndex % look::kPalette.size()]);
}

void BodyBatches::clear() {
    m_draws.clear();
    m_drawOfSlot.clear();
}

void BodyBatches::rebuild(SimulationController& simulation, const std::function<int(const simcore::Shape&)>& meshFor) {
    clear();
    const simcore::World* world = simulation.world();
    if (!world) return;
    const auto& ids = simulation.bodyIds();
    const auto& colors = simulation.authoredColors();
    const int authored = static_cast<int>(simulation.authoredScene().bodies.size());
    m_draws.reserve(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!world->contains(ids[i])) continue;
        const simcore::Shape& shape = world->shape(ids[i]);
        const std::optional<glm::vec3> authoredColor = i < colors.size() ? colors[i] : std::nullopt;
        BodyDraw draw;
        draw.id = ids[i];
        draw.sceneIndex = static_cast<int>(i) < authored ? static_cast<int>(i) : -1;
        draw.color = displayColor(i, authoredColor, world->motionType(ids[i]));
        // A compound is drawn child by child; a surface is one mesh of all its triangles.
        const std::size_t parts = shape.type == simcore::ShapeType::Compound ? simcore::subShapeCount(shape) : 1;
        for (std::size_t sub = 0; sub < parts; ++sub) {
            const simcore::Shape& piece = simcore::subShape(shape, sub);
            PartDraw part;
            part.mesh = meshFor(piece);
            if (shape.type == simcore::ShapeType::Compound)
                part.pose = modelMatrix(simcore::subShapeTransform(shape, sub, simcore::Transform{}));
            setOutlineBounds(piece, part.localCenter, part.localHalfSize);
            draw.parts.push_back(part);
        }
        if (draw.id.index >= m_drawOfSlot.size()) m_drawOfSlot.resize(draw.id.index + 1, -1);
        m_drawOfSlot[draw.id.index] = static_cast<int>(m_draws.size());
        m_draws.push_back(draw);
    }
}

const BodyBatches::BodyDraw* BodyBatches::drawOf(simcore::BodyId id) const {
    if (id.index >= m_drawOfSlot.size() || m_drawOfSlot[id.index] < 0) return nullptr;
    const BodyDraw& draw = m_draws[static_cast<std::size_t>(m_drawOfSlot[id.index])];
    return draw.id == id ? &draw : nullptr;  // a slot reused by a body made since the rebuild
}

void BodyBatches::beginFrame(std::size_t meshCount, const QList<int>& selectedBodies, bool tintSleeping) {
    m_instancesByMesh.resize(meshCount);
    for (auto& instances : m_instancesByMesh) instances.clear();
    m_outlined.clear();
    m_selectedBodies = selectedBodies;
    m_tintSleeping = tintSleeping;
}

void BodyBatches::drawBody(const WorldSnapshot::Body& body) {
    const BodyDraw* draw = drawOf(body.id);
    if (!draw) return;
    const glm::mat4 bodyModel = modelMatrix(body.transform);
    const bool asleep = body.motion == simcore::MotionType::Dynamic && !body.awake;
    const glm::vec3 color = m_tintSleeping && asleep
                                ? glm::mix(draw->color, look::srgb(look::kSleepingTint), look::kSleepingTintAmount)
                                : draw->color;
    const bool selected = draw->sceneIndex >= 0 && m_selectedBodies.contains(draw->sceneIndex);
    for (const PartDraw& part : draw->parts) {
        if (part.mesh < 0 || static_cast<std::size_t>(part.mesh) >= m_instancesByMesh.size()) continue;
        const glm::mat4 model = part.pose ? bodyModel * *part.pose : bodyModel;
        m_instancesByMesh[static_cast<std::size_t>(part.mesh)].push_back({model, color});
        if (selected) m_outlined.push_back({part.mesh, model, part.localCenter, part.localHalfSize});
    }
}

}  // namespace interplay
