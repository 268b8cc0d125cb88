#pragma once
// The editor without a window: a SceneDocument and a SimulationController wired as MainWindow wires
// them, so tests drive edits, undo and redo into a live simulation. Every change of the document
// reaches the running world in place as it happens; an edit the world cannot take in place rebuilds
// it from the document's scene (MainWindow::followEdit); a new scene (open, new, revert) rebuilds it.
// Errors the window would show are collected instead.

#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/simulation/simulation_controller.h"

#include <QStringList>

#include <functional>

namespace test_support {

struct EditorSession {
    interplay::SceneDocument document;
    interplay::SimulationController simulation;
    QStringList editErrors;        // edits the simulation could neither take in place nor rebuild from
    QStringList simulationErrors;  // what the controller reported (non-finite states)

    EditorSession() {
        using interplay::SceneDocument;
        interplay::SceneDocument* doc = &document;
        interplay::SimulationController* sim = &simulation;
        QObject::connect(doc, &SceneDocument::bodyInserted, doc, [=, this](int i) {
            follow([=](QString* e) { return sim->insertBody(i, doc->body(i), e); });
        });
        QObject::connect(doc, &SceneDocument::bodyRemoved, doc, [=, this](int i) {
            follow([=](QString*) { sim->removeBody(i); return true; });
        });
        QObject::connect(doc, &SceneDocument::bodyMoved, doc, [=, this](int from, int to) {
            follow([=](QString*) { sim->moveBody(from, to); return true; });
        });
        QObject::connect(doc, &SceneDocument::bodyChanged, doc, [=, this](int i, interplay::BodyField field) {
            follow([=](QString* e) { return sim->changeBody(i, doc->body(i), field, e); });
        });
        QObject::connect(doc, &SceneDocument::jointInserted, doc, [=, this](int i) {
            follow([=](QString* e) { return sim->insertJoint(i, doc->joint(i), e); });
        });
        QObject::connect(doc, &SceneDocument::jointRemoved, doc, [=, this](int i) {
            follow([=](QString*) { sim->removeJoint(i); return true; });
        });
        QObject::connect(doc, &SceneDocument::jointChanged, doc, [=, this](int i) {
            follow([=](QString* e) { return sim->changeJoint(i, doc->joint(i), e); });
        });
        QObject::connect(doc, &SceneDocument::settingsChanged, doc, [=, this] {
            QString error;
            if (!sim->applySettings(doc->scene().settings, &error)) editErrors << "applySettings: " + error;
        });
        QObject::connect(doc, &SceneDocument::sceneReplaced, doc, [=, this] {
            QString error;
            if (!sim->setScene(doc->scene(), &error)) editErrors << "setScene: " + error;
        });
        QObject::connect(sim, &interplay::SimulationController::simulationError, doc,
                         [this](const QString& message) { simulationErrors << message; });
    }

    // As MainWindow::followEdit: in place, or else a rebuild from the edited scene.
    void follow(const std::function<bool(QString*)>& edit) {
        QString error;
        if (edit(&error)) return;
        QString rebuildError;
        if (!simulation.setScene(document.scene(), &rebuildError)) editErrors << "rebuild: " + rebuildError;
    }

    // As MainWindow::applySimulatedPose: every authored body takes its live pose and velocities.
    // Null when there is nothing to apply.
    QUndoCommand* simulatedPoseCommand() {
        const simcore::World* world = simulation.world();
        if (!world) return nullptr;
        QList<int> indices;
        std::vector<simcore::SceneBody> after;
        const std::vector<simcore::BodyId>& ids = simulation.bodyIds();
        for (int i = 0; i < document.bodyCount() && i < static_cast<int>(ids.size()); ++i) {
            const simcore::BodyId id = ids[static_cast<std::size_t>(i)];
            if (!world->contains(id)) continue;
            simcore::SceneBody body = document.body(i);
            body.body.position = world->position(id);
            body.body.orientation = world->orientation(id);
            body.body.linearVelocity = world->linearVelocity(id);
            body.body.angularVelocity = world->angularVelocity(id);
            indices << i;
            after.push_back(std::move(body));
        }
        if (indices.isEmpty()) return nullptr;
        return new interplay::ChangeBodies(&document, QStringLiteral("Apply Simulated Pose"), interplay::BodyField::Pose,
                                           indices, std::move(after));
    }
};

}  // namespace test_support
