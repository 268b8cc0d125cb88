#pragma once
// Owns the running world. Play runs a copy of the authored scene; Reset rebuilds it from that scene,
// so the simulation never changes what the document holds. Play runs in real time with a
// fixed-step accumulator; stepOnce/stepFrames advance deterministically, whatever the clock says.
//
// Play steps the world off the GUI thread, so a slow scene never makes the window slow, and a slow
// window (a software renderer, a busy machine) does not slow the run: one worker thread runs a
// batch of steps, each when the clock owes it (after a stall at most kMaxCatchUpSteps back to back,
// the rest of the backlog dropped). After a tick (kTickMs) and at least one step it asks the GUI
// thread, by a queued call, to take it in, and goes on while its steps are quick (a few ms), or
// else ends there. At its end it takes a WorldSnapshot (the bodies' poses, the joints and the
// overlays asked for); the GUI thread announces it (stepped() and the rest) and starts the next
// batch at once. While a batch is in flight the worker alone touches the world, the timeline and
// the recording times; the GUI thread reaches them only through settle(), which every public entry
// that reads or changes them calls first: it asks the batch to end after the step under way, waits
// for it and takes in what it did. So an edit, a pick or a panel's read waits one step at most and
// never races with the worker. The viewport draws snapshot() and never waits. The signals a batch
// causes (stepped, timelineChanged, simulationWarning, simulationError) come from the event loop,
// never from inside settle(). playbackRate() says how fast the run goes against the wall clock,
// and whether it keeps up. A step, a run and a recording are the same bits whichever thread runs
// them: what a step does never depends on how the steps are batched.
// Interaction with the running world (grabbing a body with a spring, throwing new bodies) goes
// through simcore's public API only and is forgotten on Reset.
//
// Edits of the authored scene reach the running world in place (insertBody, changeBody, ...), so a
// run paused mid-way keeps every other body's simulated state, and dragging one body of a thousand
// costs one World::setTransform, not a new world:
//   - a move or turn moves or turns the live body by as much as the edit moved the authored one
//     (a body dragged where the run left it follows the cursor); Apply Simulated Pose and
//     velocity edits set the live values; a colour is only drawn differently;
//   - any other change of a body (shape, mass, motion, friction, restitution, rolling resistance,
//     CCD, name) goes through simcore's setter: the body keeps its id, pose, velocities and
//     joints, and its contacts keep their warm starts (a shape or motion change finds them anew);
//   - a joint's limits, motor, spring, lengths, collide-connected flag and name go through
//     simcore's joint setters, which keep the rest pose it was built with;
//   - a body removed from a world that has run and inserted again where it was (Delete undone)
//     comes back in the live state it left in (pose and velocities), so its joints, re-made as
//     below, join it where the run had it rather than across the scene at its authored pose;
//   - a joint added, or given new anchors or axis, is created at its bodies' live poses: its
//     anchors and axis follow body A (a distance joint's second point follows body B), and the
//     bodies' current relative pose becomes its rest pose until Reset restores the authored one.
// A world that has not run since bodies or joints were added, removed, reordered, re-created or
// moved is rebuilt from the authored scene before its first step (the order of bodies and joints
// and the broad phase's fat boxes would differ from a fresh build's), so a run from an edited
// scene is bit for bit the run of that scene saved and reopened.
//
// The timeline (app/simulation/timeline.h): while recording (the default), every step is kept in a
// ring bounded by a memory limit. Showing a frame puts the running world back exactly as it was at
// that step, paused: the viewport and the panels show it, Apply Simulated Pose applies it, and Step
// goes on through the recorded frames. Playing from a frame shown (or stepping past the newest)
// resumes from it and drops the frames after it, as recording over a tape does; a resumed run is
// the recorded run bit for bit while nobody pulls or throws. An edit of the scene or its settings,
// Reset and a new scene discard the recording: its frames were of another scene.

#include "app/document/scene_document.h"
#include "app/simulation/real_time_meter.h"
#include "app/simulation/run_series.h"
#include "app/simulation/timeline.h"
#include "app/simulation/worker_thread.h"
#include "app/simulation/world_snapshot.h"

#include "simcore/io/scene.h"
#include "simcore/world/profiler.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

class QUndoCommand;

#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace interplay {

class SimulationController : public QObject {
    Q_OBJECT
    Q_PROPERTY(double timeScale READ timeScale WRITE setTimeScale NOTIFY timeScaleChanged)
    Q_PROPERTY(bool playing READ isPlaying WRITE setPlaying NOTIFY playingChanged)

public:
    explicit SimulationController(QObject* parent = nullptr);
    ~SimulationController() override;

    // Takes a copy of `scene` as the state Reset returns to, and builds a world from it (paused).
    // On failure (a body the engine rejects) returns false with the reason in *error and keeps the
    // previous world.
    bool setScene(const simcore::Scene& scene, QString* error = nullptr);
    // Changes the settings of the running world in place (the simulation keeps its state), and of
    // the scene Reset returns to. Returns false with the engine's reason if it rejects them.
    bool applySettings(const simcore::WorldSettings& settings, QString* error = nullptr);

    // The running world, or null before the first successful setScene. Waits for the step in
    // flight (see the top of this file); the world is the GUI thread's until control returns to the
    // event loop.
    const simcore::World* world();
    // bodyIds()[i] is the world body made from scene body i; bodies thrown in while running follow.
    const std::vector<simcore::BodyId>& bodyIds() const { return m_bodyIds; }
    // jointIds()[i] is the world joint made from scene joint i.
    const std::vector<simcore::JointId>& jointIds() const { return m_jointIds; }
    // Colours by bodyIds() index (unset when the scene leaves the choice to the viewer).
    const std::vector<std::optional<simcore::Vec3>>& authoredColors() const { return m_colors; }
    const simcore::Scene& authoredScene() const { return m_scene; }
    // The scene body a world body was made from, or -1 (thrown in, or not in this world).
    int sceneIndexOf(simcore::BodyId id) const;
    // The running world's dynamic bodies, and how many of them are awake (a new world's all are):
    // what the status bar and the Profiler show. Static bodies never sleep, so they are not counted.
    struct AwakeCount {
        int awake = 0;
        int dynamic = 0;
    };
    AwakeCount awakeCount();

    // The world as the views draw it: as the last batch of steps left it while one is in flight,
    // else as it is. Never waits; valid until control returns to the event loop.
    const WorldSnapshot& snapshot();
    // Which bounds and contact points the snapshot holds besides the bodies and joints (what the
    // viewport's overlays draw); the rest of `overlays` is ignored.
    void setSnapshotOverlays(const simcore::DebugDrawOptions& overlays);

    // How fast playback runs: simulated seconds per wall second over about the last second, and
    // whether that is the time scale asked for (at least kKeepingUpFraction of it). None while
    // paused or before a quarter second of playback is measured.
    struct PlaybackRate {
        double factor = 0.0;
        bool keepingUp = true;
    };
    std::optional<PlaybackRate> playbackRate() const;
    static constexpr double kKeepingUpFraction = 0.9;

    bool isPlaying() const { return m_playing; }
    // Simulated seconds per real second during playback (slow motion below 1).
    double timeScale() const { return m_timeScale; }
    static constexpr double kMinTimeScale = 0.05;
    static constexpr double kMaxTimeScale = 4.0;

    // Grabbing: a critically damped spring pulls the body's `localPoint` (body frame, m) towards a
    // target point, applied as a force before every step until released.
    void beginGrab(simcore::BodyId body, const simcore::Vec3& localPoint, const simcore::Vec3& target);
    void moveGrab(const simcore::Vec3& target);
    void endGrab();
    bool isGrabbing() const { return m_grab.has_value(); }
    // The grabbed point in world space (as snapshot() has the body) and its target, for drawing the
    // spring. A grab changes no state a step reads until the next batch of steps begins.
    std::optional<std::pair<simcore::Vec3, simcore::Vec3>> grabLine();

    // ---- Edits of the authored scene, applied in place (see the top of this file) ----
    // Each mirrors the SceneDocument edit of the same name, with the document's new value. On
    // false (*error says why) the engine refused the change and the world may lack the object:
    // the caller rebuilds with setScene.
    bool insertBody(int index, const simcore::SceneBody& body, QString* error = nullptr);
    void removeBody(int index);  // its joints must be removed first, as the document does
    void moveBody(int from, int to);
    bool changeBody(int index, const simcore::SceneBody& body, BodyField field, QString* error = nullptr);
    bool insertJoint(int index, const simcore::SceneJoint& joint, QString* error = nullptr);
    void removeJoint(int index);
    // A Placement change (the joint re-expressed at its bodies' new authored poses, holding the
    // same points of them) leaves the live joint as it is.
    bool changeJoint(int index, const simcore::SceneJoint& joint, JointField field, QString* error = nullptr);

    // Keeps the running world in step with `document`: each of its edits is applied in place as
    // it happens (the calls above) or, where the engine refuses that, the world is rebuilt from the
    // edited scene; a failure of both is reported through editFailed. A replaced scene (new, open,
    // revert) is left to the owner, who decides what to tell the user.
    void followDocument(const SceneDocument* document);

    // The undoable Apply Simulated Pose: every authored body takes its live pose and velocities,
    // and every joint moves with its bodies (anchors and axis with body A, a distance joint's second
    // anchor with body B), so it holds the same points of them as in the run. What a joint takes
    // from its pose when it is built then comes from the applied pose: hinge and slider limits
    // count from it, and a distance joint's rest length is its length there. Null, with
    // *error saying why, when there is nothing to apply or the live state is one the scene file
    // cannot hold (a speed beyond the loader's limits, a non-finite value).
    QUndoCommand* simulatedPoseCommand(SceneDocument* document, QString* error);

    // Adds a body to the running world only (not to the document); Reset removes it again.
    // Returns an invalid id, with the reason in *error, if the engine rejects it.
    simcore::BodyId spawn(const simcore::SceneBody& body, QString* error = nullptr);

    // The run's measures, a sample per step (the Profiler's plots): cleared when a new world is
    // built, and cut after the step a run resumes from, as the timeline is.
    const RunSeries& series() const { return m_series; }

    // ---- The timeline (see the top of this file; these wait for the step in flight) ----
    const Timeline& timeline();
    bool isRecording() const { return m_recording; }
    void setRecording(bool recording);  // off discards the recording
    void setRecordingMemoryLimit(std::size_t bytes);
    // The recorded frame the world is at, or -1 (nothing recorded).
    int currentFrame();
    // Puts the world back at recorded frame `frame`, paused. False when it is not recorded.
    bool showFrame(int frame);
    // Mean time a step's recording took over the last kRecordingMsSteps recorded steps (ms).
    double recordingMs();
    static constexpr std::size_t kRecordingMsSteps = 600;

    // Real-time catch-up limit: after a stall (debugger, a step slower than real time) at most this
    // many steps run back to back and the rest of the backlog is dropped, so the loop never spirals.
    static constexpr int kMaxCatchUpSteps = 8;
    // The tick (ms): one per display frame. A played batch is taken in at most once a tick.
    static constexpr int kTickMs = 16;

public slots:
    void play();
    // Ends the batch in flight after its step under way and announces it: nothing comes after.
    void pause();
    void setPlaying(bool playing);
    void togglePlaying();
    // One step on; at a frame shown before the newest, the next recorded frame.
    void stepOnce();
    // The recorded frame before the one the world is at (paused); nothing before the first.
    void stepBack();
    // Advances exactly `frames` steps (used by --screenshot and tests); emits stepped() once.
    void stepFrames(int frames);
    // Back to the authored scene, paused.
    void reset();
    void setTimeScale(double scale);  // clamped to [kMinTimeScale, kMaxTimeScale]

signals:
    void stepped();                     // the world advanced; views redraw
    void worldRebuilt();                // a new world replaced the old one; cached per-body data is stale
    void bodiesEdited();                // an edit added, removed, reordered, recoloured or changed bodies
                                        // or joints of the running world: cached per-body data is stale
    void posesEdited();                 // an edit moved bodies or set their velocities: views redraw
    void bodySpawned(simcore::BodyId id);  // a body joined the running world
    void playingChanged(bool playing);
    void timeScaleChanged(double scale);
    void simulationError(const QString& message);  // e.g. a non-finite state; playback stops
    // The run is no longer physical (a velocity cut to the engine's safety bound); once per run. The
    // summary fits a status bar; the details say why and what helps.
    void simulationWarning(const QString& summary, const QString& details);
    void editFailed(const QString& message);       // a followed edit could be neither applied nor rebuilt from
    void timelineChanged();  // frames recorded, dropped or discarded, or another frame shown

private:
    struct Grab {
        simcore::BodyId body;
        simcore::Vec3 localPoint{0.0f};
        simcore::Vec3 target{0.0f};
    };

    // Steps run together, on the worker while playing or at once by stepFrames, and what they did.
    struct Batch {
        std::optional<Grab> grab;            // as it was when the batch began
        simcore::DebugDrawOptions overlays;  // for the snapshot
        // Played: the clock since Play, how much of it (ns) `owed` counts, and the rate asked for.
        QElapsedTimer clock;
        qint64 counted = 0;
        double owed = 0.0;  // s of simulated time due and not yet run
        double timeScale = 1.0;
        // What it did.
        int stepsRun = 0;
        std::vector<RunSample> samples;
        std::optional<std::uint64_t> speedLimitStep;      // the first step that bounded a velocity
        std::optional<simcore::NonFiniteBody> nonFinite;  // found after the last step
        WorldSnapshot snapshot;
    };
    // What the GUI thread is to announce of the batches taken in, in this order.
    struct Announcement {
        std::optional<std::uint64_t> speedLimitStep;
        bool timelineChanged = false;
        QString error;  // playback stops
        bool stepped = false;
    };
    enum class BatchState { None, Running, Settled };  // Settled: taken in, not yet announced

    // Runs `steps` at once on this thread and announces them.
    void advance(int steps);
    // Starts Play's next batch on the worker.
    void startPlayedBatch();
    // The played batch asked to be taken in (a queued call from the worker): ended, announced, and
    // the next one started.
    void finishPlayedBatch();
    Batch beginBatch();
    // On the worker: steps in real time until it has run a tick of slow steps, is asked to stop
    // (see the top of this file) or the world goes non-finite; then asks to be taken in.
    void runPlayedBatch(Batch& batch);
    // On either thread: one step, recorded. A batch's steps touch the world, the timeline and the
    // recording times.
    void runStep(Batch& batch);
    void endBatch(Batch& batch);  // on the thread that stepped: the non-finite check, the snapshot
    void takeIn(Batch& batch);    // on the GUI thread, after the batch ended
    void announce();
    // Waits for the batch in flight, if any, after asking it to stop after the step under way, and
    // takes in what it did. After it the GUI thread has the world until it returns to the event loop.
    void settle();
    // settle(), and the snapshot is taken again when next asked for: the caller changes the world.
    simcore::World& changeWorld();
    // The grab spring's force for the next step, if `grab` holds a body.
    std::optional<AppliedForce> grabForce(const std::optional<Grab>& grab) const;
    // Records the world's state after a step that `input` acted over (nothing while not recording);
    // at a frame shown before the newest, first drops the frames after it.
    void recordStep(const std::optional<AppliedForce>& input);
    // Before stepping: starts the recording with the state to step from, or cuts the future.
    void prepareRecording();
    void discardRecording();
    bool build(simcore::Scene scene, QString* error);  // replaces the world; playing or not stays as it is
    // A world edited in place before it ran is rebuilt (see the top of this file).
    void rebuildIfEditedBeforeRun();
    void editedInPlace();
    // Applies a followed edit in place, or else rebuilds from the document's scene.
    void follow(const SceneDocument* document, const std::function<bool(QString* error)>& edit);
    // Creates scene joint `index` at its bodies' live poses.
    simcore::JointId createLiveJoint(const simcore::SceneJoint& joint);
    // A point (direction) given in the authored scene, carried along with scene body `sceneBody`
    // from its authored pose to its live one.
    simcore::Vec3 livePoint(std::size_t sceneBody, const simcore::Vec3& point) const;
    simcore::Vec3 liveDirection(std::size_t sceneBody, const simcore::Vec3& direction) const;

    simcore::Scene m_scene;
    std::unique_ptr<simcore::BuiltWorld> m_built;
    std::vector<simcore::BodyId> m_bodyIds;
    std::vector<simcore::JointId> m_jointIds;
    bool m_rebuildBeforeRun = false;
    std::vector<std::optional<simcore::Vec3>> m_colors;
    // Bodies removed from this world, with their live state, for an insertion that brings one back.
    struct RemovedBody {
        int index;                              // scene index it was removed from
        simcore::SceneBody authored;            // to recognise it when it is inserted again
        simcore::BodyCreationSettings live;     // the authored settings at the live pose and velocities
    };
    std::vector<RemovedBody> m_removedBodies;
    std::optional<Grab> m_grab;
    RunSeries m_series;
    bool m_boundWarned = false;  // simulationWarning sent for this world
    Timeline m_timeline;
    bool m_recording = true;
    bool m_changedSinceFrame = false;  // the world was changed between steps since the last frame
    std::deque<double> m_recordingMs;  // the last steps' recording times

    bool m_playing = false;
    QElapsedTimer m_clock;       // since Play
    qint64 m_counted = 0;        // ns of m_clock counted into m_accumulator
    double m_accumulator = 0.0;  // s of simulated time due and not yet run, between batches
    double m_timeScale = 1.0;
    RealTimeMeter m_meter;

    WorldSnapshot m_snapshot;
    bool m_snapshotStale = true;  // the world changed since m_snapshot; never while a batch is in flight
    simcore::DebugDrawOptions m_snapshotOverlays;
    Batch m_batch;  // the worker's while m_batchState is Running
    BatchState m_batchState = BatchState::None;
    Announcement m_announcement;
    WorkerThread m_worker;  // last: destroyed first, once nothing is in flight
};

}  // namespace interplay
