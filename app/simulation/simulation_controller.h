#pragma once
// Owns the running world. Play runs a copy of the authored scene; Reset rebuilds it from that scene,
// so the simulation never changes what the document holds. A timer drives real-time playback with
// a fixed-step accumulator; stepOnce/stepFrames advance deterministically, whatever the clock says.

#include "simcore/io/scene.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace interplay {

class SimulationController : public QObject {
    Q_OBJECT

public:
    explicit SimulationController(QObject* parent = nullptr);
    ~SimulationController() override;

    // Takes a copy of `scene` as the state Reset returns to, and builds a world from it (paused).
    // On failure (a body the engine rejects) returns false with the reason in *error and keeps the
    // previous world.
    bool setScene(const simcore::Scene& scene, QString* error = nullptr);

    // The running world, or null before the first successful setScene.
    const simcore::World* world() const;
    // bodyIds()[i] is the world body made from scene body i.
    const std::vector<simcore::BodyId>& bodyIds() const { return m_bodyIds; }
    // Authored colours by scene index (unset when the scene leaves the choice to the viewer).
    const std::vector<std::optional<simcore::Vec3>>& authoredColors() const { return m_colors; }
    const simcore::Scene& authoredScene() const { return m_scene; }

    bool isPlaying() const { return m_timer.isActive(); }

    // Real-time catch-up limit: after a stall (debugger, slow frame) at most this many steps run
    // per tick and the rest of the backlog is dropped, so the loop never spirals.
    static constexpr int kMaxCatchUpSteps = 8;

public slots:
    void play();
    void pause();
    void setPlaying(bool playing);
    void togglePlaying();
    void stepOnce();
    // Advances exactly `frames` steps (used by --screenshot and tests); emits stepped() once.
    void stepFrames(int frames);
    // Back to the authored scene, paused.
    void reset();

signals:
    void stepped();                     // the world advanced; views redraw
    void worldRebuilt();                // a new world replaced the old one; cached per-body data is stale
    void playingChanged(bool playing);
    void simulationError(const QString& message);  // e.g. a non-finite state; playback stops

private:
    void tick();
    bool advance(int steps);  // false when the world went non-finite

    simcore::Scene m_scene;
    std::unique_ptr<simcore::BuiltWorld> m_built;
    std::vector<simcore::BodyId> m_bodyIds;
    std::vector<std::optional<simcore::Vec3>> m_colors;

    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_accumulator = 0.0;  // s of real time not yet simulated
};

}  // namespace interplay
