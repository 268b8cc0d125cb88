#pragma once
// The bodies of the running world as the renderer draws them: each body's mesh and colour, chosen
// when the world is (re)built, and each frame the instances gathered from the controller's
// snapshot of the bodies (what World::draw emitted when it was taken), batched by mesh, with the
// selected bodies to outline. A compound is drawn child by
// child, each with its convex shape's mesh placed by the child's pose: the same look, and equal
// children of many compounds share one mesh.

#include "app/simulation/world_snapshot.h"
#include "app/viewport/renderer.h"

#include <QList>

#include <functional>
#include <optional>
#include <vector>

namespace interplay {

class SimulationController;

class BodyBatches {
public:
    // What each body of the controller's world is drawn with; `meshFor` uploads a shape's mesh.
    void rebuild(SimulationController& simulation, const std::function<int(const simcore::Shape&)>& meshFor);
    void clear();
    bool empty() const { return m_draws.empty(); }

    // Starts a frame: the instances of the last one are dropped. `selectedBodies` are scene
    // indices; sleeping dynamic bodies are tinted when `tintSleeping`.
    void beginFrame(std::size_t meshCount, const QList<int>& selectedBodies, bool tintSleeping);
    void drawBody(const WorldSnapshot::Body& body);

    const std::vector<std::vector<BodyInstance>>& instancesByMesh() const { return m_instancesByMesh; }
    const std::vector<OutlinedBody>& outlined() const { return m_outlined; }

    // Colour a body is drawn with (linear RGB): the authored one, else a neutral grey for static
    // bodies and a palette colour picked by scene index for the others.
    static glm::vec3 displayColor(std::size_t sceneIndex, const std::optional<glm::vec3>& authored,
                                  simcore::MotionType motion);

private:
    // One convex piece of a body: the body's whole shape, or one child of a compound.
    struct PartDraw {
        int mesh = -1;
        std::optional<glm::mat4> pose;  // a compound child's place in the body frame; none for a whole shape
        glm::vec3 localCenter{0.0f};    // of the piece's local bounds (m), for the outline
        glm::vec3 localHalfSize{0.5f};  // of the piece's local bounds (m)
    };
    struct BodyDraw {
        simcore::BodyId id;
        int sceneIndex = -1;  // -1 for a body thrown in while running
        std::vector<PartDraw> parts;
        glm::vec3 color{1.0f};
    };
    const BodyDraw* drawOf(simcore::BodyId id) const;

    std::vector<BodyDraw> m_draws;
    std::vector<int> m_drawOfSlot;  // by BodyId::index: index into m_draws, or -1
    std::vector<std::vector<BodyInstance>> m_instancesByMesh;
    std::vector<OutlinedBody> m_outlined;
    QList<int> m_selectedBodies;
    bool m_tintSleeping = true;
};

}  // namespace interplay
