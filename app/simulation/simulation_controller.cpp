#include "app/simulation/simulation_controller.h"

#include <algorithm>
#include <cmath>
#include <exception>

namespace interplay {
namespace {

// The grab spring: critically damped at this frequency, strong enough to lift a body against
// gravity yet slow enough to stay stable at one force per 1/60 s step.
constexpr float kGrabHertz = 4.0f;
// Cap on the spring's acceleration (m/s^2), so a far-away cursor cannot fling a body through walls.
constexpr float kMaxGrabAcceleration = 150.0f;

}  // namespace

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    // A tick per display frame; the accumulator, not the timer's accuracy, sets the simulated rate.
    m_timer.setInterval(16);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimulationController::tick);
}

SimulationController::~SimulationController() = default;

const simcore::World* SimulationController::world() const {
    return m_built ? &m_built->world : nullptr;
}

int SimulationController::sceneIndexOf(simcore::BodyId id) const {
    const std::size_t authored = std::min(m_scene.bodies.size(), m_bodyIds.size());
    for (std::size_t i = 0; i < authored; ++i) {
        if (m_bodyIds[i] == id) return static_cast<int>(i);
    }
    return -1;
}

bool SimulationController::setScene(const simcore::Scene& scene, QString* error) {
    std::unique_ptr<simcore::BuiltWorld> built;
    try {
        // new T(prvalue) constructs in place, so this does not require World to be movable.
        built.reset(new simcore::BuiltWorld(simcore::buildWorld(scene)));
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    pause();
    m_scene = scene;
    m_built = std::move(built);
    m_bodyIds = m_built->bodyIds;
    m_colors.clear();
    m_colors.reserve(scene.bodies.size());
    for (const simcore::SceneBody& body : scene.bodies) m_colors.push_back(body.color);
    m_grab.reset();
    m_history.clear();
    emit worldRebuilt();
    return true;
}

bool SimulationController::applySettings(const simcore::WorldSettings& settings, QString* error) {
    if (!m_built) return false;
    try {
        m_built->world.setSettings(settings);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    m_scene.settings = settings;
    return true;
}

void SimulationController::play() {
    if (!m_built || isPlaying()) return;
    m_accumulator = 0.0;
    m_clock.start();
    m_timer.start();
    emit playingChanged(true);
}

void SimulationController::pause() {
    if (!isPlaying()) return;
    m_timer.stop();
    emit playingChanged(false);
}

void SimulationController::setPlaying(bool playing) {
    playing ? play() : pause();
}

void SimulationController::togglePlaying() {
    setPlaying(!isPlaying());
}

void SimulationController::stepOnce() {
    pause();
    stepFrames(1);
}

void SimulationController::stepFrames(int frames) {
    if (!m_built || frames <= 0) return;
    advance(frames);
    emit stepped();
}

void SimulationController::reset() {
    QString error;
    // The authored scene built once already, so this only fails if the engine changed under us.
    if (!setScene(m_scene, &error)) emit simulationError(error);
}

void SimulationController::setTimeScale(double scale) {
    scale = std::clamp(scale, kMinTimeScale, kMaxTimeScale);
    if (scale == m_timeScale) return;
    m_timeScale = scale;
    emit timeScaleChanged(m_timeScale);
}

void SimulationController::beginGrab(simcore::BodyId body, const simcore::Vec3& localPoint,
                                     const simcore::Vec3& target) {
    m_grab = Grab{body, localPoint, target};
}

void SimulationController::moveGrab(const simcore::Vec3& target) {
    if (m_grab) m_grab->target = target;
}

void SimulationController::endGrab() {
    m_grab.reset();
}

std::optional<std::pair<simcore::Vec3, simcore::Vec3>> SimulationController::grabLine() const {
    if (!m_grab || !m_built || !m_built->world.contains(m_grab->body)) return std::nullopt;
    const simcore::World& world = m_built->world;
    const simcore::Vec3 point = world.position(m_grab->body) + world.orientation(m_grab->body) * m_grab->localPoint;
    return std::make_pair(point, m_grab->target);
}

simcore::BodyId SimulationController::spawn(const simcore::SceneBody& body, QString* error) {
    if (!m_built) return {};
    simcore::BodyId id;
    try {
        id = m_built->world.createBody(body.body);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return {};
    }
    m_bodyIds.push_back(id);
    m_colors.push_back(body.color);
    emit bodySpawned(id);
    return id;
}

void SimulationController::applyGrabForce() {
    simcore::World& world = m_built->world;
    if (!m_grab || !world.contains(m_grab->body)) return;
    if (world.motionType(m_grab->body) != simcore::MotionType::Dynamic) return;
    const simcore::BodyId id = m_grab->body;
    const simcore::Vec3 center = world.centerOfMass(id);
    const simcore::Vec3 point = world.position(id) + world.orientation(id) * m_grab->localPoint;
    const simcore::Vec3 lever = point - center;
    const simcore::Vec3 pointVelocity = world.linearVelocity(id) + glm::cross(world.angularVelocity(id), lever);
    const float omega = 2.0f * 3.14159265f * kGrabHertz;
    // Acceleration of a critically damped spring, capped; as a force it scales with the mass, so
    // every body follows the cursor alike.
    simcore::Vec3 acceleration = omega * omega * (m_grab->target - point) - 2.0f * omega * pointVelocity;
    const float magnitude = glm::length(acceleration);
    if (magnitude > kMaxGrabAcceleration) acceleration *= kMaxGrabAcceleration / magnitude;
    const simcore::Vec3 force = world.mass(id) * acceleration;
    world.addForce(id, force);
    world.addTorque(id, glm::cross(lever, force));
    world.wake(id);
}

void SimulationController::tick() {
    if (!m_built) return;
    const double dt = m_built->world.settings().timeStep;
    if (!(dt > 0.0)) return;  // the world validates this; never loop on a zero step
    m_accumulator += static_cast<double>(m_clock.nsecsElapsed()) * 1e-9 * m_timeScale;
    m_clock.restart();
    int steps = static_cast<int>(m_accumulator / dt);
    if (steps > kMaxCatchUpSteps) {
        steps = kMaxCatchUpSteps;
        m_accumulator = 0.0;  // drop the backlog: run slower than real time rather than stall
    } else {
        m_accumulator -= steps * dt;
    }
    if (steps == 0) return;
    advance(steps);
    emit stepped();
}

bool SimulationController::advance(int steps) {
    simcore::World& world = m_built->world;
    for (int i = 0; i < steps; ++i) {
        applyGrabForce();  // forces last one step in simcore
        world.step();
        m_history.push_back({world.simulatedTime(), world.lastStepProfile(), world.kineticEnergy(), world.potentialEnergy()});
        if (m_history.size() > kHistoryLength) m_history.pop_front();
    }
    // Checked once per batch, not per step: enough to stop playback before garbage spreads.
    if (const auto bad = world.findNonFiniteBody()) {
        pause();
        emit simulationError(tr("The simulation produced a non-finite %1 for body \"%2\" by step %3; playback stopped.")
                                 .arg(QString::fromStdString(bad->quantity), QString::fromStdString(bad->name))
                                 .arg(world.stepCount()));
        return false;
    }
    return true;
}

}  // namespace interplay
