#include "app/simulation/simulation_controller.h"

#include "app/document/scene_edits.h"
#include "app/document/undo_commands.h"

#include "simcore/io/scene_io.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <utility>

namespace interplay {

SimulationController::SimulationController(QObject* parent) : QObject(parent) {}

SimulationController::~SimulationController() {
    settle();  // the worker's batch uses the members destroyed before it
}

const simcore::World* SimulationController::world() {
    settle();
    return m_built ? &m_built->world : nullptr;
}

SimulationController::AwakeCount SimulationController::awakeCount() {
    AwakeCount count;
    if (!world()) return count;
    const simcore::World& world = m_built->world;
    for (const simcore::BodyId id : m_bodyIds) {
        if (world.motionType(id) != simcore::MotionType::Dynamic) continue;
        ++count.dynamic;
        if (world.isAwake(id)) ++count.awake;
    }
    return count;
}

int SimulationController::sceneIndexOf(simcore::BodyId id) const {
    const std::size_t authored = std::min(m_scene.bodies.size(), m_bodyIds.size());
    for (std::size_t i = 0; i < authored; ++i) {
        if (m_bodyIds[i] == id) return static_cast<int>(i);
    }
    return -1;
}

bool SimulationController::setScene(const simcore::Scene& scene, QString* error) {
    if (!build(scene, error)) return false;
    pause();
    return true;
}

bool SimulationController::build(simcore::Scene scene, QString* error) {
    settle();
    std::unique_ptr<simcore::BuiltWorld> built;
    try {
        // new T(prvalue) constructs in place, so this does not require World to be movable.
        built.reset(new simcore::BuiltWorld(simcore::buildWorld(scene)));
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    m_scene = std::move(scene);
    m_built = std::move(built);
    m_bodyIds = m_built->bodyIds;
    m_jointIds = m_built->jointIds;
    m_removedBodies.clear();
    m_colors.clear();
    m_colors.reserve(m_scene.bodies.size());
    for (const simcore::SceneBody& body : m_scene.bodies) m_colors.push_back(body.color);
    m_grab.reset();
    m_series.clear();
    m_boundWarned = false;
    m_rebuildBeforeRun = false;
    m_snapshotStale = true;
    m_announcement = {};  // of the world replaced
    discardRecording();
    emit worldRebuilt();
    return true;
}

void SimulationController::editedInPlace() {
    // Adding, removing or reordering bodies and joints, or moving bodies, leaves the
    // world as the edits made it: bodies and joints in another order, fat boxes of other sizes.
    // (Property setters do not: they leave what a build with the new value makes.) Once it has run
    // nothing is lost by keeping it; before, a fresh build makes the run the same as the saved
    // scene's.
    if (m_built->world.stepCount() == 0 && m_bodyIds.size() == m_scene.bodies.size()) m_rebuildBeforeRun = true;
}

void SimulationController::rebuildIfEditedBeforeRun() {
    if (!m_rebuildBeforeRun) return;
    QString error;
    if (!build(m_scene, &error)) emit simulationError(error);
}

// ---- Edits of the authored scene ------------------------------------------------------------------

bool SimulationController::insertBody(int index, const simcore::SceneBody& body, QString* error) {
    if (!m_built) return false;
    simcore::World& world = changeWorld();
    insertSceneBody(m_scene, index, body);
    simcore::BodyCreationSettings settings = body.body;
    // The most recent removal of this very body from this place: it returns as the run left it.
    const auto removed = std::find_if(m_removedBodies.rbegin(), m_removedBodies.rend(), [&](const RemovedBody& r) {
        return r.index == index && sameSceneBody(r.authored, body);
    });
    if (removed != m_removedBodies.rend()) {
        settings = removed->live;
        m_removedBodies.erase(std::next(removed).base());
    }
    simcore::BodyId id;  // stays invalid if the engine refuses the body, so indices stay aligned
    bool created = true;
    try {
        id = world.createBody(settings);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        created = false;
    }
    m_bodyIds.insert(m_bodyIds.begin() + index, id);
    m_colors.insert(m_colors.begin() + index, body.color);
    editedInPlace();
    emit bodiesEdited();
    return created;
}

void SimulationController::removeBody(int index) {
    if (!m_built) return;
    simcore::World& world = changeWorld();
    const simcore::BodyId id = m_bodyIds.at(static_cast<std::size_t>(index));
    if (world.contains(id)) {
        const simcore::SceneBody& authored = m_scene.bodies.at(static_cast<std::size_t>(index));
        simcore::BodyCreationSettings live = authored.body;
        live.position = world.position(id);
        live.orientation = world.orientation(id);
        live.linearVelocity = world.linearVelocity(id);
        live.angularVelocity = world.angularVelocity(id);
        m_removedBodies.push_back({index, authored, std::move(live)});
        world.destroyBody(id);
    }
    if (m_grab && m_grab->body == id) m_grab.reset();
    m_bodyIds.erase(m_bodyIds.begin() + index);
    m_colors.erase(m_colors.begin() + index);
    takeSceneBody(m_scene, index);
    editedInPlace();
    emit bodiesEdited();
}

void SimulationController::moveBody(int from, int to) {
    if (!m_built) return;
    changeWorld();  // the bodies' order: the worker reads how many there are
    moveSceneBody(m_scene, from, to);
    moveItem(m_bodyIds, from, to);
    moveItem(m_colors, from, to);
    editedInPlace();  // a fresh build would create the bodies in the new order
    emit bodiesEdited();
}

bool SimulationController::changeBody(int index, const simcore::SceneBody& body, BodyField field, QString* error) {
    if (!m_built) return false;
    simcore::World& world = changeWorld();
    const simcore::SceneBody before = std::exchange(m_scene.bodies.at(static_cast<std::size_t>(index)), body);
    const simcore::BodyId id = m_bodyIds[static_cast<std::size_t>(index)];
    if (field == BodyField::Color) {
        m_colors[static_cast<std::size_t>(index)] = body.color;
        emit bodiesEdited();
        return true;
    }
    bool posed = false;   // a pose or velocity edit, rather than one of what the body is
    bool moved = false;   // a pose edit: the body was moved in place
    try {
        if (!world.contains(id)) throw std::invalid_argument("the body is not in the running world");
        const simcore::BodyCreationSettings& b = body.body;
        switch (field) {
        case BodyField::Position:
            world.setTransform(id, world.position(id) + (b.position - before.body.position), world.orientation(id));
            posed = moved = true;
            break;
        case BodyField::Orientation:
            world.setTransform(id, world.position(id),
                               b.orientation * glm::inverse(before.body.orientation) * world.orientation(id));
            posed = moved = true;
            break;
        case BodyField::Turn:
            // The turn of a group about its centre, carried to the live bodies as the gizmo's
            // moves are: each shifted by its authored shift and turned by the same rotation, which
            // for bodies a run has moved together is the same turn about their live centre.
            world.setTransform(id, world.position(id) + (b.position - before.body.position),
                               glm::normalize(b.orientation * glm::inverse(before.body.orientation) * world.orientation(id)));
            posed = moved = true;
            break;
        case BodyField::Pose:
            world.setTransform(id, b.position, b.orientation);
            world.setLinearVelocity(id, b.linearVelocity);
            world.setAngularVelocity(id, b.angularVelocity);
            posed = moved = true;
            break;
        case BodyField::LinearVelocity:
            world.setLinearVelocity(id, b.linearVelocity);
            posed = true;
            break;
        case BodyField::AngularVelocity:
            world.setAngularVelocity(id, b.angularVelocity);
            posed = true;
            break;
        case BodyField::Name: world.setName(id, b.name); break;
        case BodyField::Shape: world.setShape(id, b.shape); break;
        case BodyField::Motion: world.setMotionType(id, b.motion); break;
        case BodyField::Mass: b.mass ? world.setMass(id, *b.mass) : world.setDensity(id, b.density); break;
        case BodyField::Friction: world.setFriction(id, b.friction); break;
        case BodyField::Restitution: world.setRestitution(id, b.restitution); break;
        case BodyField::RollingResistance: world.setRollingResistance(id, b.rollingResistance); break;
        case BodyField::Ccd: world.setCcd(id, b.ccd); break;
        case BodyField::Color: break;  // handled above: nothing of the world changes
        }
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    // A body moved in place keeps the fat box it had where the move ends inside it; a fresh build
    // fits one to the new pose, and a run from it meets its pairs at other steps. The other
    // setters leave the world as a build with the new value would make it.
    if (moved) editedInPlace();
    // A property edit keeps the body's id, joints and warm starts; views redraw the body (its
    // shape or kind may differ).
    if (posed) emit posesEdited();
    else emit bodiesEdited();
    return true;
}

simcore::Vec3 SimulationController::livePoint(std::size_t sceneBody, const simcore::Vec3& point) const {
    const simcore::BodyCreationSettings& authored = m_scene.bodies.at(sceneBody).body;
    const simcore::BodyId id = m_bodyIds.at(sceneBody);
    const simcore::World& world = m_built->world;  // the callers have settled
    return carriedPoint({authored.position, authored.orientation}, {world.position(id), world.orientation(id)}, point);
}

simcore::Vec3 SimulationController::liveDirection(std::size_t sceneBody, const simcore::Vec3& direction) const {
    return carriedDirection(m_scene.bodies.at(sceneBody).body.orientation,
                            m_built->world.orientation(m_bodyIds.at(sceneBody)), direction);
}

simcore::JointId SimulationController::createLiveJoint(const simcore::SceneJoint& joint) {
    simcore::World& world = m_built->world;  // the caller has settled
    simcore::JointCreationSettings settings = joint.joint;
    settings.bodyA = m_bodyIds.at(joint.bodyA);
    settings.bodyB = joint.bodyB ? m_bodyIds.at(*joint.bodyB) : simcore::BodyId{};
    if (!world.contains(settings.bodyA) || (joint.bodyB && !world.contains(settings.bodyB)))
        throw std::invalid_argument("a body of the joint is not in the running world");
    settings.anchor = livePoint(joint.bodyA, settings.anchor);
    settings.axis = liveDirection(joint.bodyA, settings.axis);
    if (joint.bodyB) settings.anchorB = livePoint(*joint.bodyB, settings.anchorB);
    return world.createJoint(settings);
}

bool SimulationController::insertJoint(int index, const simcore::SceneJoint& joint, QString* error) {
    if (!m_built) return false;
    changeWorld();
    m_scene.joints.insert(m_scene.joints.begin() + index, joint);
    simcore::JointId id;  // stays invalid if the engine refuses the joint, so indices stay aligned
    bool created = true;
    try {
        id = createLiveJoint(joint);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        created = false;
    }
    m_jointIds.insert(m_jointIds.begin() + index, id);
    editedInPlace();
    emit bodiesEdited();
    return created;
}

void SimulationController::removeJoint(int index) {
    if (!m_built) return;
    simcore::World& world = changeWorld();
    const simcore::JointId id = m_jointIds.at(static_cast<std::size_t>(index));
    if (world.contains(id)) world.destroyJoint(id);
    m_jointIds.erase(m_jointIds.begin() + index);
    m_scene.joints.erase(m_scene.joints.begin() + index);
    editedInPlace();
    emit bodiesEdited();
}

bool SimulationController::changeJoint(int index, const simcore::SceneJoint& joint, JointField field, QString* error) {
    if (!m_built) return false;
    simcore::World& world = changeWorld();
    const auto i = static_cast<std::size_t>(index);
    m_scene.joints.at(i) = joint;
    if (field == JointField::Placement) return true;
    const simcore::JointCreationSettings& j = joint.joint;
    try {
        if (!world.contains(m_jointIds[i])) throw std::invalid_argument("the joint is not in the running world");
        const simcore::JointId id = m_jointIds[i];
        switch (field) {
        case JointField::Name: world.setJointName(id, j.name); break;
        case JointField::Limits: world.setJointLimits(id, j.limits); break;
        case JointField::Motor: world.setJointMotor(id, j.motor); break;
        case JointField::Lengths: world.setJointLengths(id, j.minLength, j.maxLength); break;
        case JointField::Spring: world.setJointSpring(id, j.spring); break;
        case JointField::CollideConnected: world.setJointCollideConnected(id, j.collideConnected); break;
        case JointField::Anchor:
        case JointField::AnchorB:
        case JointField::Axis: {
            // The authored frame rides on the bodies as they are now: anchor and axis on body A,
            // a distance joint's second anchor on body B.
            const simcore::Vec3 anchorB = joint.bodyB ? livePoint(*joint.bodyB, j.anchorB) : j.anchorB;
            world.setJointFrame(id, livePoint(joint.bodyA, j.anchor), liveDirection(joint.bodyA, j.axis), anchorB);
            break;
        }
        case JointField::Placement: break;  // handled above
        }
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    emit bodiesEdited();
    return true;
}

bool SimulationController::applySettings(const simcore::WorldSettings& settings, QString* error) {
    if (!m_built) return false;
    try {
        changeWorld().setSettings(settings);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    m_scene.settings = settings;
    discardRecording();
    return true;
}

simcore::BodyId SimulationController::spawn(const simcore::SceneBody& body, QString* error) {
    if (!m_built) return {};
    rebuildIfEditedBeforeRun();  // the thrown body joins the world that will run
    simcore::World& world = changeWorld();
    simcore::BodyId id;
    try {
        id = world.createBody(body.body);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return {};
    }
    m_bodyIds.push_back(id);
    m_colors.push_back(body.color);
    // Thrown at a frame shown before the newest, the body starts a new future; the next frame
    // cannot be stepped to from the last keyframe.
    const int frame = currentFrame();
    if (frame >= 0) m_timeline.truncateAfter(static_cast<std::size_t>(frame));
    m_changedSinceFrame = true;
    emit bodySpawned(id);
    emit timelineChanged();
    return id;
}

void SimulationController::followDocument(const SceneDocument* document) {
    connect(document, &SceneDocument::bodyInserted, this, [this, document](int index) {
        follow(document, [&](QString* error) { return insertBody(index, document->body(index), error); });
    });
    connect(document, &SceneDocument::bodyRemoved, this, [this, document](int index) {
        follow(document, [&](QString*) { removeBody(index); return true; });
    });
    connect(document, &SceneDocument::bodyMoved, this, [this, document](int from, int to) {
        follow(document, [&](QString*) { moveBody(from, to); return true; });
    });
    connect(document, &SceneDocument::bodyChanged, this, [this, document](int index, BodyField field) {
        follow(document, [&](QString* error) { return changeBody(index, document->body(index), field, error); });
    });
    connect(document, &SceneDocument::jointInserted, this, [this, document](int index) {
        follow(document, [&](QString* error) { return insertJoint(index, document->joint(index), error); });
    });
    connect(document, &SceneDocument::jointRemoved, this, [this, document](int index) {
        follow(document, [&](QString*) { removeJoint(index); return true; });
    });
    connect(document, &SceneDocument::jointChanged, this, [this, document](int index, JointField field) {
        follow(document, [&](QString* error) { return changeJoint(index, document->joint(index), field, error); });
    });
    connect(document, &SceneDocument::settingsChanged, this, [this, document] {
        QString error;
        if (!applySettings(document->scene().settings, &error)) emit editFailed(tr("The settings cannot be used: %1").arg(error));
    });
}

void SimulationController::follow(const SceneDocument* document, const std::function<bool(QString* error)>& edit) {
    settle();
    discardRecording();  // the frames were of the scene before the edit
    QString error;
    if (edit(&error)) return;
    QString rebuildError;
    if (!setScene(document->scene(), &rebuildError))
        emit editFailed(tr("The edited scene cannot be simulated: %1").arg(rebuildError));
}

QUndoCommand* SimulationController::simulatedPoseCommand(SceneDocument* document, QString* error) {
    const simcore::World* live = world();
    QList<int> indices;
    std::vector<simcore::SceneBody> bodies;
    simcore::Scene applied = document->scene();
    for (int i = 0; live && i < document->bodyCount() && i < static_cast<int>(m_bodyIds.size()); ++i) {
        const simcore::BodyId id = m_bodyIds[static_cast<std::size_t>(i)];
        if (!live->contains(id)) continue;
        simcore::SceneBody& body = applied.bodies[static_cast<std::size_t>(i)];
        body.body.position = live->position(id);
        body.body.orientation = live->orientation(id);
        body.body.linearVelocity = live->linearVelocity(id);
        body.body.angularVelocity = live->angularVelocity(id);
        indices << i;
        bodies.push_back(body);
    }
    if (indices.isEmpty()) {
        if (error) *error = tr("There is no simulated pose to apply.");
        return nullptr;
    }
    // The joints riding on the bodies go with them, as the command will carry them.
    for (auto& [index, joint] : jointsCarriedWith(document->scene(), indices, bodies))
        applied.joints[static_cast<std::size_t>(index)] = std::move(joint);
    // The file format's own check, so the document never holds a scene it could not reopen
    // (checkScene, which also checks meshes read from files without reading them again).
    const std::vector<simcore::Diagnostic> problems = simcore::checkScene(applied);
    const auto refusal = std::find_if(problems.begin(), problems.end(),
                                      [](const simcore::Diagnostic& d) { return d.severity == simcore::Diagnostic::Severity::Error; });
    if (refusal != problems.end()) {
        if (error) *error = tr("The simulated state cannot be saved in a scene file (%1: %2).")
                                .arg(QString::fromStdString(refusal->path), QString::fromStdString(refusal->message));
        return nullptr;
    }
    // Applied at the authored pose the command is obsolete: pushed, it leaves no history entry.
    return new MoveBodies(document, tr("Apply Simulated Pose"), BodyField::Pose, indices, std::move(bodies));
}

}  // namespace interplay
