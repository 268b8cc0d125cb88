#include "app/simulation/simulation_controller.h"

#include <algorithm>
#include <exception>

namespace interplay {

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
    emit worldRebuilt();
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

void SimulationController::tick() {
    if (!m_built) return;
    const double dt = m_built->world.settings().timeStep;
    if (!(dt > 0.0)) return;  // the world validates this; never loop on a zero step
    m_accumulator += static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
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
    for (int i = 0; i < steps; ++i) world.step();
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
