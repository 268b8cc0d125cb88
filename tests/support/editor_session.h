#pragma once
// The editor without a window: a SceneDocument and a SimulationController that follows it, as in
// MainWindow, so tests drive edits, undo and redo into a live simulation. A new scene (open, new,
// revert) rebuilds the world. Errors the window would show are collected instead.

#include "app/document/scene_document.h"
#include "app/simulation/simulation_controller.h"

#include <QStringList>

namespace test_support {

struct EditorSession {
    interplay::SceneDocument document;
    interplay::SimulationController simulation;
    QStringList editErrors;        // edits the simulation could neither take in place nor rebuild from
    QStringList simulationErrors;  // what the controller reported (non-finite states)
    QStringList simulationWarnings;  // runs that stopped being physical (the speed bound)

    EditorSession() {
        simulation.followDocument(&document);
        QObject::connect(&simulation, &interplay::SimulationController::editFailed, &document,
                         [this](const QString& message) { editErrors << message; });
        QObject::connect(&document, &interplay::SceneDocument::sceneReplaced, &document, [this] {
            QString error;
            if (!simulation.setScene(document.scene(), &error)) editErrors << "setScene: " + error;
        });
        QObject::connect(&simulation, &interplay::SimulationController::simulationError, &document,
                         [this](const QString& message) { simulationErrors << message; });
        QObject::connect(&simulation, &interplay::SimulationController::simulationWarning, &document,
                         [this](const QString& summary, const QString& details) {
                             simulationWarnings << summary + QLatin1Char('\n') + details;
                         });
    }

    // Apply Simulated Pose, as the window's action makes it.
    QUndoCommand* simulatedPoseCommand(QString* error = nullptr) { return simulation.simulatedPoseCommand(&document, error); }
};

}  // namespace test_support
