// SimulationController's playback: Play, Step and Reset, the batches of steps run on the worker
// thread and what the GUI thread takes in from them, the grab spring, and the timeline's recording
// (simulation_controller.h says how the two threads share the world).

#include "app/simulation/simulation_controller.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <utility>

namespace interplay {
namespace {

// The grab spring: critically damped at this frequency, strong enough to lift a body against
// gravity yet slow enough to stay stable at one force per 1/60 s step.
constexpr float kGrabHertz = 4.0f;
// Cap on the spring's acceleration (m/s^2), so a far-away cursor cannot fling a body through walls.
constexpr float kMaxGrabAcceleration = 150.0f;

// A played batch whose steps take less than this (ms) on average runs on after asking to be taken
// in, until it is: the GUI thread waits for about one such step.
constexpr qint64 kQuickStepMs = 4;

double seconds(const QElapsedTimer& clock) {
    return static_cast<double>(clock.nsecsElapsed()) * 1e-9;
}

}  // namespace

void SimulationController::play() {
    if (!m_built || isPlaying()) return;
    rebuildIfEditedBeforeRun();
    m_playing = true;
    m_clock.start();
    m_counted = 0;
    m_accumulator = 0.0;
    m_meter.restart(0.0);
    if (m_batchState == BatchState::None) startPlayedBatch();  // else the batch ending starts it
    emit playingChanged(true);
}

void SimulationController::pause() {
    if (!isPlaying()) return;
    m_playing = false;
    // The batch in flight ends after its step under way and is announced now: once paused,
    // nothing more is stepped or announced.
    settle();
    announce();
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
    const int frame = currentFrame();
    if (frame >= 0 && frame + 1 < static_cast<int>(m_timeline.frameCount())) {
        showFrame(frame + 1);
        return;
    }
    stepFrames(1);
}

void SimulationController::stepBack() {
    pause();
    const int frame = currentFrame();
    if (frame > 0) showFrame(frame - 1);
}

void SimulationController::stepFrames(int frames) {
    if (!m_built || frames <= 0) return;
    rebuildIfEditedBeforeRun();
    advance(frames);
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
    if (isPlaying()) m_meter.restart(seconds(m_clock));  // the rate before was another scale's
    emit timeScaleChanged(m_timeScale);
}

std::optional<SimulationController::PlaybackRate> SimulationController::playbackRate() const {
    if (!isPlaying()) return std::nullopt;
    const std::optional<double> factor = m_meter.factor();
    if (!factor) return std::nullopt;
    return PlaybackRate{*factor, *factor >= kKeepingUpFraction * m_timeScale};
}

// ---- The world between the threads ----------------------------------------------------------------

const WorldSnapshot& SimulationController::snapshot() {
    // Stale only while no batch is in flight: the world is this thread's to read.
    if (m_snapshotStale && m_built) {
        m_snapshot = WorldSnapshot::take(m_built->world, m_snapshotOverlays);
        m_snapshotStale = false;
    }
    return m_snapshot;
}

void SimulationController::setSnapshotOverlays(const simcore::DebugDrawOptions& overlays) {
    settle();
    m_snapshotOverlays = overlays;
    m_snapshotStale = true;
}

void SimulationController::settle() {
    if (m_batchState != BatchState::Running) return;
    m_worker.stop();
    m_batchState = BatchState::Settled;
    m_accumulator = m_batch.owed;  // what was due and not run is due still
    m_counted = m_batch.counted;
    // At the batch's end, not now: the wall time it ran is the time its steps were run in.
    m_meter.add(static_cast<double>(m_batch.counted) * 1e-9, m_batch.stepsRun * m_built->world.settings().timeStep);
    takeIn(m_batch);
}

simcore::World& SimulationController::changeWorld() {
    settle();
    m_snapshotStale = true;
    return m_built->world;
}

// ---- Batches of steps -----------------------------------------------------------------------------

void SimulationController::advance(int steps) {
    settle();
    Batch batch = beginBatch();
    for (int i = 0; i < steps; ++i) runStep(batch);
    endBatch(batch);
    takeIn(batch);
    announce();
}

void SimulationController::startPlayedBatch() {
    snapshot();  // up to date before the worker has the world: the views draw it meanwhile
    m_batch = beginBatch();
    m_batch.clock = m_clock;
    m_batch.counted = m_counted;
    m_batch.owed = m_accumulator;
    m_batch.timeScale = m_timeScale;
    m_batchState = BatchState::Running;
    m_worker.start([this] { runPlayedBatch(m_batch); });
}

void SimulationController::finishPlayedBatch() {
    settle();
    m_batchState = BatchState::None;
    announce();
    // Unless a slot of announce()'s paused, or paused and played again (which started one).
    if (isPlaying() && m_batchState == BatchState::None) startPlayedBatch();
}

SimulationController::Batch SimulationController::beginBatch() {
    prepareRecording();
    // Resumed from a frame shown, the samples of the steps after it were of the dropped future.
    m_series.truncateAfterStep(m_built->world.stepCount());
    Batch batch;
    batch.grab = m_grab;
    batch.overlays = m_snapshotOverlays;
    return batch;
}

void SimulationController::runPlayedBatch(Batch& batch) {
    const simcore::World& world = m_built->world;
    const double dt = world.settings().timeStep;
    // Every nanosecond since Play is counted once, up to the moment the batch ends.
    const auto countTime = [&batch] {
        const qint64 now = batch.clock.nsecsElapsed();
        batch.owed += static_cast<double>(now - batch.counted) * 1e-9 * batch.timeScale;
        batch.counted = now;
    };
    const qint64 began = batch.clock.nsecsElapsed();
    qint64 steppingNs = 0;  // the wall time its steps took
    bool asked = false;     // to be taken in
    const auto askToBeTakenIn = [&] {
        asked = true;
        QMetaObject::invokeMethod(this, &SimulationController::finishPlayedBatch, Qt::QueuedConnection);
    };
    while (!m_worker.stopRequested()) {
        countTime();
        if (batch.owed >= dt) {
            // After a stall, or when steps take longer than they simulate, the backlog beyond
            // kMaxCatchUpSteps is dropped: slower than real time rather than a spiral.
            batch.owed = std::min(batch.owed, kMaxCatchUpSteps * dt) - dt;
            const qint64 stepBegan = batch.clock.nsecsElapsed();
            runStep(batch);
            steppingNs += batch.clock.nsecsElapsed() - stepBegan;
            if (world.findNonFiniteBody()) break;
            if (batch.clock.nsecsElapsed() - began >= kTickMs * 1'000'000LL) {
                // Quick steps go on until the GUI thread takes the batch in, so a slow frame does
                // not slow the run; slow ones end the batch, taken in without a wait. On average:
                // a step the machine's other work held up is no slow scene.
                if (steppingNs >= kQuickStepMs * 1'000'000LL * batch.stepsRun) break;
                if (!asked) askToBeTakenIn();
            }
        } else if (!m_worker.sleepFor(std::chrono::nanoseconds(
                       static_cast<std::int64_t>((dt - batch.owed) / batch.timeScale * 1e9)))) {
            break;
        }
    }
    countTime();
    endBatch(batch);
    if (!asked) askToBeTakenIn();
}

void SimulationController::runStep(Batch& batch) {
    simcore::World& world = m_built->world;
    const std::optional<AppliedForce> grab = grabForce(batch.grab);  // forces last one step in simcore
    if (grab) applyForce(world, *grab);
    world.step();
    recordStep(grab);
    batch.samples.push_back(RunSeries::sample(world));
    ++batch.stepsRun;
    if (!batch.speedLimitStep && world.lastStepProfile().counters.boundedVelocities > 0)
        batch.speedLimitStep = world.stepCount();
}

void SimulationController::endBatch(Batch& batch) {
    // Once per batch (a played one also looks after each step): enough to stop before garbage spreads.
    batch.nonFinite = m_built->world.findNonFiniteBody();
    batch.snapshot = WorldSnapshot::take(m_built->world, batch.overlays);
}

void SimulationController::takeIn(Batch& batch) {
    const simcore::World& world = m_built->world;
    for (const RunSample& sample : batch.samples) m_series.append(sample);
    m_snapshot = std::move(batch.snapshot);
    m_snapshotStale = false;
    if (!m_boundWarned && batch.speedLimitStep) {
        m_boundWarned = true;
        m_announcement.speedLimitStep = batch.speedLimitStep;
    }
    if (m_recording) m_announcement.timelineChanged = true;
    if (batch.nonFinite) {
        m_announcement.error =
            tr("The simulation produced a non-finite %1 for body \"%2\" by step %3; playback stopped.")
                .arg(QString::fromStdString(batch.nonFinite->quantity), QString::fromStdString(batch.nonFinite->name))
                .arg(world.stepCount());
    }
    m_announcement.stepped = true;
}

void SimulationController::announce() {
    const Announcement news = std::exchange(m_announcement, {});
    if (news.speedLimitStep) {
        emit simulationWarning(
            tr("Step %1: a body reached the speed limit; the motion is no longer physical").arg(*news.speedLimitStep),
            tr("The engine bounds every body to 100 km/s and a quarter turn per substep. Unstable assemblies "
               "(a joint torn far apart, a violent overlap) get there; more substeps or a smaller time step help."));
    }
    if (news.timelineChanged) emit timelineChanged();
    if (!news.error.isEmpty()) {
        pause();
        emit simulationError(news.error);
    }
    if (news.stepped) emit stepped();
}

// ---- Grabbing -------------------------------------------------------------------------------------

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

std::optional<std::pair<simcore::Vec3, simcore::Vec3>> SimulationController::grabLine() {
    if (!m_grab) return std::nullopt;
    const WorldSnapshot::Body* body = snapshot().find(m_grab->body);
    if (!body) return std::nullopt;
    return std::make_pair(body->transform.apply(m_grab->localPoint), m_grab->target);
}

std::optional<AppliedForce> SimulationController::grabForce(const std::optional<Grab>& grab) const {
    const simcore::World& world = m_built->world;
    if (!grab || !world.contains(grab->body)) return std::nullopt;
    if (world.motionType(grab->body) != simcore::MotionType::Dynamic) return std::nullopt;
    const simcore::BodyId id = grab->body;
    const simcore::Vec3 center = world.centerOfMass(id);
    const simcore::Vec3 point = world.position(id) + world.orientation(id) * grab->localPoint;
    const simcore::Vec3 lever = point - center;
    const simcore::Vec3 pointVelocity = world.linearVelocity(id) + glm::cross(world.angularVelocity(id), lever);
    const float omega = 2.0f * 3.14159265f * kGrabHertz;
    // Acceleration of a critically damped spring, capped; as a force it scales with the mass, so
    // every body follows the cursor alike.
    simcore::Vec3 acceleration = omega * omega * (grab->target - point) - 2.0f * omega * pointVelocity;
    const float magnitude = glm::length(acceleration);
    if (magnitude > kMaxGrabAcceleration) acceleration *= kMaxGrabAcceleration / magnitude;
    const simcore::Vec3 force = world.mass(id) * acceleration;
    return AppliedForce{id, force, glm::cross(lever, force)};
}

// ---- The timeline ---------------------------------------------------------------------------------

const Timeline& SimulationController::timeline() {
    settle();
    return m_timeline;
}

void SimulationController::setRecording(bool recording) {
    if (recording == m_recording) return;
    settle();
    m_recording = recording;
    discardRecording();
}

void SimulationController::setRecordingMemoryLimit(std::size_t bytes) {
    settle();
    m_timeline.setMemoryLimit(bytes);
    emit timelineChanged();
}

int SimulationController::currentFrame() {
    settle();
    // Frames are consecutive steps, and the world is always at one of them while any is recorded:
    // whatever changes it otherwise discards or cuts the recording.
    if (!m_built || m_timeline.empty()) return -1;
    const std::uint64_t step = m_built->world.stepCount();
    const std::uint64_t first = m_timeline.stepOf(0);
    if (step < first || step - first >= m_timeline.frameCount()) return -1;
    return static_cast<int>(step - first);
}

bool SimulationController::showFrame(int frame) {
    settle();
    if (!m_built || frame < 0 || frame >= static_cast<int>(m_timeline.frameCount())) return false;
    pause();
    simcore::World& world = changeWorld();
    const std::size_t bodiesBefore = world.bodyCount();
    world = m_timeline.restore(static_cast<std::size_t>(frame));
    m_grab.reset();
    m_changedSinceFrame = false;
    // Bodies thrown in later keep their ids (a later frame has them again); views skip them here.
    if (world.bodyCount() != bodiesBefore) emit bodiesEdited();
    emit stepped();
    emit timelineChanged();
    return true;
}

double SimulationController::recordingMs() {
    settle();
    if (m_recordingMs.empty()) return 0.0;
    double sum = 0.0;
    for (double ms : m_recordingMs) sum += ms;
    return sum / static_cast<double>(m_recordingMs.size());
}

void SimulationController::prepareRecording() {
    if (!m_recording) return;
    const int frame = currentFrame();
    if (frame < 0) {
        m_timeline.clear();
        m_timeline.record(m_built->world, std::nullopt, true, m_bodyIds.size());
        return;
    }
    if (frame + 1 == static_cast<int>(m_timeline.frameCount())) return;
    // Resuming from a frame shown: the future recorded after it is dropped, and so are the ids of
    // the bodies thrown in there (a new throw may reuse their slots).
    m_timeline.truncateAfter(static_cast<std::size_t>(frame));
    const std::size_t tracked = m_timeline.trackedBodiesOf(static_cast<std::size_t>(frame));
    if (tracked < m_bodyIds.size()) {
        m_bodyIds.resize(tracked);
        m_colors.resize(tracked);
        emit bodiesEdited();
    }
}

void SimulationController::recordStep(const std::optional<AppliedForce>& input) {
    if (!m_recording) return;
    QElapsedTimer timer;
    timer.start();
    m_timeline.record(m_built->world, input, std::exchange(m_changedSinceFrame, false), m_bodyIds.size());
    m_recordingMs.push_back(static_cast<double>(timer.nsecsElapsed()) * 1e-6);
    if (m_recordingMs.size() > kRecordingMsSteps) m_recordingMs.pop_front();
}

void SimulationController::discardRecording() {
    m_timeline.clear();
    m_changedSinceFrame = false;
    emit timelineChanged();
}

}  // namespace interplay
