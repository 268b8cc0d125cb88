// Over 800 lines because it is the document layer's one suite: a test per undo command type (with
// undo, redo, merging and the clean state) and per panel model, each short.
// The editor's document layer without a window: every undo command (add, remove, reorder, change
// bodies, add/change/delete joints, change settings) with undo/redo, merging of continuous edits,
// the clean state and what "modified" means, open/save round trips, thesis import, load
// errors, and the panels' editing models (inspector rows for bodies and joints, simulation
// settings) pushing commands and refusing bad input.

#include "app/document/body_templates.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/panels/inspector_panel.h"
#include "app/panels/number_field.h"
#include "app/panels/simulation_settings_model.h"

#include "simcore/io/scene_io.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using interplay::AddBodies;
using interplay::AddJoint;
using interplay::BodyField;
using interplay::ChangeBodies;
using interplay::ChangeJoints;
using interplay::JointField;
using interplay::ChangeSettings;
using interplay::RemoveBodies;
using interplay::ReorderBody;
using interplay::SceneDocument;

namespace {

QStringList bodyNames(const SceneDocument& document) {
    QStringList names;
    for (int i = 0; i < document.bodyCount(); ++i) names << document.bodyName(i);
    return names;
}

std::string text(const simcore::Scene& scene) {
    return simcore::serializeScene(scene);
}

// Moves body `index` by `offset` as one command.
void pushMove(SceneDocument& document, int index, const simcore::Vec3& offset, bool mergeable) {
    simcore::SceneBody body = document.body(index);
    body.body.position += offset;
    document.undoStack()->push(new ChangeBodies(&document, QStringLiteral("Move %1").arg(document.bodyName(index)),
                                                BodyField::Position, {index}, {body}, mergeable));
}

// A joint made as Add Joint makes it, between bodies `a` and `b` (or `a` and the world).
simcore::SceneJoint jointOf(const SceneDocument& document, simcore::JointType type, int a, std::optional<int> b = {}) {
    return interplay::templateJoint(type, document.uniqueJointName("Joint"), document.scene().bodies, std::size_t(a),
                                    b ? std::optional<std::size_t>(std::size_t(*b)) : std::nullopt);
}

void pushJoint(SceneDocument& document, simcore::JointType type, int a, std::optional<int> b = {}) {
    document.undoStack()->push(new AddJoint(&document, "Add Joint", document.jointCount(), jointOf(document, type, a, b)));
}

void typeInto(QLineEdit* field, const QString& text) {
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

}  // namespace

class TestDocument : public QObject {
    Q_OBJECT

private slots:
    void init();

    void addBodiesUndoRedo();
    void removeBodiesRestoresOrderAndSelection();
    void reorderBodyUndoRedo();
    void jointsFollowTheirBodies();
    void changeBodiesUndoRedo();
    void rollingResistanceEditsMergeUndoAndSave();
    void continuousEditsMergeIntoOneEntry();
    void editBackToTheStartIsDropped();
    void changeSettingsUndoRedoAndMerge();
    void modifiedFollowsTheCleanState();
    void selectionNeverDirties();
    void uniqueBodyNames();

    void templateJointsAreAccepted_data();
    void templateJointsAreAccepted();
    void addJointUndoRedo();
    void deleteJointsBodiesOrBothInOneStep();
    void changeJointsUndoRedoMergeAndClean();
    void jointSelectionFollowsTheJoints();

    void saveLoadRoundTripIsExact();
    void failedSaveLeavesTheOldFile();
    void thesisSceneIsImportedWithoutAPath();
    void loadErrorNamesFileAndJsonPath();

    void inspectorEditPushesACommand();
    void inspectorEditsEverySelectedBody();
    void inspectorRejectsBadInput_data();
    void inspectorRejectsBadInput();
    void inspectorShapeAndMotionChoices();
    void settingsModelPushesAndRejects();
    void inspectorEditsJoints();
    void inspectorRejectsBadJointInput_data();
    void inspectorRejectsBadJointInput();

private:
    SceneDocument m_document;
    QTemporaryDir m_dir;
};

void TestDocument::init() {
    m_document.newDefault();
    QVERIFY(m_dir.isValid());
}

void TestDocument::addBodiesUndoRedo() {
    const QStringList before = bodyNames(m_document);
    const int count = m_document.bodyCount();
    simcore::SceneBody box = interplay::templateBody(simcore::ShapeType::Box, m_document.uniqueBodyName("Box"), {0, 3, 0});
    m_document.undoStack()->push(new AddBodies(&m_document, "Add Box 1", {count}, {box}));
    QCOMPARE(m_document.bodyCount(), count + 1);
    QCOMPARE(m_document.bodyName(count), QString("Box 1"));
    QCOMPARE(m_document.selectedBodies(), QList<int>{count});  // the new body is selected
    QCOMPARE(m_document.undoStack()->undoText(), QString("Add Box 1"));

    m_document.undoStack()->undo();
    QCOMPARE(bodyNames(m_document), before);
    QVERIFY(m_document.selectedBodies().isEmpty());
    m_document.undoStack()->redo();
    QCOMPARE(m_document.bodyName(count), QString("Box 1"));

    // Inserting in the middle shifts the selection with the bodies it names.
    m_document.setSelectedBodies({2});
    const QString selectedName = m_document.bodyName(2);
    m_document.insertBody(1, box);
    QCOMPARE(m_document.bodyName(m_document.selectedBodies().first()), selectedName);
}

void TestDocument::removeBodiesRestoresOrderAndSelection() {
    const QStringList before = bodyNames(m_document);
    m_document.setSelectedBodies({1, 3});
    auto* remove = new RemoveBodies(&m_document, {3, 1});
    QCOMPARE(remove->text(), QString("Delete 2 Bodies"));
    m_document.undoStack()->push(remove);
    QCOMPARE(m_document.bodyCount(), before.size() - 2);
    QVERIFY(!bodyNames(m_document).contains(before[1]));
    QVERIFY(!bodyNames(m_document).contains(before[3]));
    QVERIFY(m_document.selectedBodies().isEmpty());

    m_document.undoStack()->undo();
    QCOMPARE(bodyNames(m_document), before);
    QCOMPARE(m_document.selectedBodies(), (QList<int>{1, 3}));

    auto* single = new RemoveBodies(&m_document, {2});
    QCOMPARE(single->text(), QString("Delete %1").arg(before[2]));
    delete single;
}

void TestDocument::reorderBodyUndoRedo() {
    const QStringList before = bodyNames(m_document);
    m_document.setSelectedBodies({1});
    m_document.undoStack()->push(new ReorderBody(&m_document, 1, 4));
    QStringList expected = before;
    expected.move(1, 4);
    QCOMPARE(bodyNames(m_document), expected);
    QCOMPARE(m_document.selectedBodies(), QList<int>{4});  // selection follows the body
    m_document.undoStack()->undo();
    QCOMPARE(bodyNames(m_document), before);
    QCOMPARE(m_document.selectedBodies(), QList<int>{1});
    m_document.undoStack()->redo();
    QCOMPARE(bodyNames(m_document), expected);
}

void TestDocument::jointsFollowTheirBodies() {
    // Joints name bodies by index: every edit that moves bodies must renumber them.
    const QString second = m_document.bodyName(2), third = m_document.bodyName(3), fifth = m_document.bodyName(5);
    simcore::SceneJoint between;
    between.bodyA = 2;
    between.bodyB = 3;
    simcore::SceneJoint toWorld;
    toWorld.bodyA = 5;
    m_document.insertJoint(0, between);
    m_document.insertJoint(1, toWorld);
    const auto jointBodies = [this](int joint) {
        const simcore::SceneJoint& j = m_document.scene().joints.at(static_cast<std::size_t>(joint));
        return QStringList{m_document.bodyName(int(j.bodyA)), j.bodyB ? m_document.bodyName(int(*j.bodyB)) : "world"};
    };
    QStringList expectedBetween{second, third}, expectedToWorld{fifth, "world"};

    m_document.undoStack()->push(new AddBodies(&m_document, "Add", {0},
                                               {interplay::templateBody(simcore::ShapeType::Box, "New", {})}));
    QCOMPARE(jointBodies(0), expectedBetween);
    m_document.undoStack()->push(new ReorderBody(&m_document, 3, 0));
    QCOMPARE(jointBodies(0), expectedBetween);
    QCOMPARE(jointBodies(1), expectedToWorld);

    // Deleting a body takes its joints with it; undo brings both back.
    const int thirdIndex = static_cast<int>(bodyNames(m_document).indexOf(third));
    m_document.undoStack()->push(new RemoveBodies(&m_document, {thirdIndex}));
    QCOMPARE(m_document.scene().joints.size(), std::size_t(1));
    QCOMPARE(jointBodies(0), expectedToWorld);
    m_document.undoStack()->undo();
    QCOMPARE(m_document.scene().joints.size(), std::size_t(2));
    QCOMPARE(jointBodies(0), expectedBetween);
    QCOMPARE(jointBodies(1), expectedToWorld);
    while (m_document.undoStack()->canUndo()) m_document.undoStack()->undo();
    QCOMPARE(m_document.scene().joints.at(0).bodyA, std::size_t(2));
    QCOMPARE(m_document.scene().joints.at(1).bodyA, std::size_t(5));
}

void TestDocument::changeBodiesUndoRedo() {
    const simcore::SceneBody original = m_document.body(2);
    simcore::SceneBody changed = original;
    changed.body.friction = 0.9f;
    changed.body.restitution = 0.4f;
    QSignalSpy bodyChanged(&m_document, &SceneDocument::bodyChanged);
    m_document.undoStack()->push(new ChangeBodies(&m_document, "Change Friction", BodyField::Friction, {2}, {changed}));
    QCOMPARE(bodyChanged.count(), 1);
    QCOMPARE(bodyChanged.first().at(1).value<BodyField>(), BodyField::Friction);
    QCOMPARE(m_document.body(2).body.friction, 0.9f);
    m_document.undoStack()->undo();
    QVERIFY(interplay::sameSceneBody(m_document.body(2), original));
    m_document.undoStack()->redo();
    QCOMPARE(m_document.body(2).body.restitution, 0.4f);

    // A change to identical values is not history.
    m_document.undoStack()->push(new ChangeBodies(&m_document, "Nothing", BodyField::Friction, {2}, {m_document.body(2)}));
    QCOMPARE(m_document.undoStack()->count(), 1);
}

void TestDocument::rollingResistanceEditsMergeUndoAndSave() {
    const simcore::SceneBody original = m_document.body(2);
    QCOMPARE(original.body.rollingResistance, 0.0f);
    // Continuous edits of the field (a scrub) are one entry holding the first value and the last.
    for (float c : {0.01f, 0.02f, 0.05f}) {
        simcore::SceneBody changed = m_document.body(2);
        changed.body.rollingResistance = c;
        m_document.undoStack()->push(new ChangeBodies(&m_document, "Change Rolling Resistance", BodyField::RollingResistance,
                                                      {2}, {changed}, true));
    }
    QCOMPARE(m_document.undoStack()->count(), 1);
    QCOMPARE(m_document.body(2).body.rollingResistance, 0.05f);
    QVERIFY(m_document.isModified());
    // Only rolling resistance differs, and that is a difference: undo gives the original back.
    QVERIFY(!interplay::sameSceneBody(m_document.body(2), original));
    m_document.undoStack()->undo();
    QVERIFY(interplay::sameSceneBody(m_document.body(2), original));
    QVERIFY(!m_document.isModified());
    m_document.undoStack()->redo();
    QCOMPARE(m_document.body(2).body.rollingResistance, 0.05f);

    // It is saved and read back.
    const QString path = m_dir.filePath("rolling.json");
    QString error;
    QVERIFY2(m_document.save(path, &error), qPrintable(error));
    SceneDocument loaded;
    QVERIFY2(loaded.load(path, &error), qPrintable(error));
    QCOMPARE(loaded.body(2).body.rollingResistance, 0.05f);
    QCOMPARE(text(loaded.scene()), text(m_document.scene()));
}

void TestDocument::continuousEditsMergeIntoOneEntry() {
    const simcore::Vec3 start = m_document.body(1).body.position;
    pushMove(m_document, 1, {1, 0, 0}, false);
    for (int i = 0; i < 20; ++i) pushMove(m_document, 1, {0.1f, 0, 0}, true);
    QCOMPARE(m_document.undoStack()->count(), 1);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Move %1").arg(m_document.bodyName(1)));
    QVERIFY(glm::length(m_document.body(1).body.position - (start + simcore::Vec3(3, 0, 0))) < 1e-4f);

    // A new drag (not mergeable), another body or another field: new entries.
    pushMove(m_document, 1, {0, 1, 0}, false);
    pushMove(m_document, 2, {0, 1, 0}, true);
    simcore::SceneBody spun = m_document.body(2);
    spun.body.angularVelocity = {0, 5, 0};
    m_document.undoStack()->push(new ChangeBodies(&m_document, "Spin", BodyField::AngularVelocity, {2}, {spun}, true));
    QCOMPARE(m_document.undoStack()->count(), 4);

    // One undo takes back the whole first drag.
    for (int i = 0; i < 4; ++i) m_document.undoStack()->undo();
    QCOMPARE(m_document.body(1).body.position, start);
}

void TestDocument::editBackToTheStartIsDropped() {
    pushMove(m_document, 1, {1, 0, 0}, false);
    pushMove(m_document, 1, {-1, 0, 0}, true);  // dragged back where it was
    QCOMPARE(m_document.undoStack()->count(), 0);
    QVERIFY(!m_document.isModified());
}

void TestDocument::changeSettingsUndoRedoAndMerge() {
    const simcore::WorldSettings original = m_document.scene().settings;
    QSignalSpy settingsChanged(&m_document, &SceneDocument::settingsChanged);
    simcore::WorldSettings after = original;
    for (int i = 1; i <= 5; ++i) {
        after.gravity.y = -9.81f + static_cast<float>(i);
        m_document.undoStack()->push(new ChangeSettings(&m_document, "Change Gravity", "gravity", after, i > 1));
    }
    QCOMPARE(m_document.undoStack()->count(), 1);
    QCOMPARE(settingsChanged.count(), 5);
    QCOMPARE(m_document.scene().settings.gravity.y, -9.81f + 5.0f);
    after.substeps = 9;
    m_document.undoStack()->push(new ChangeSettings(&m_document, "Change Substeps", "substeps", after, true));
    QCOMPARE(m_document.undoStack()->count(), 2);  // another key never merges
    m_document.undoStack()->undo();
    m_document.undoStack()->undo();
    QVERIFY(m_document.scene().settings == original);
}

void TestDocument::modifiedFollowsTheCleanState() {
    QSignalSpy modified(&m_document, &SceneDocument::modifiedChanged);
    QVERIFY(!m_document.isModified());
    pushMove(m_document, 1, {1, 0, 0}, false);
    QVERIFY(m_document.isModified());
    QCOMPARE(modified.count(), 1);
    m_document.undoStack()->undo();
    QVERIFY(!m_document.isModified());  // back at the saved state
    m_document.undoStack()->redo();
    const QString path = m_dir.filePath("clean.json");
    QVERIFY(m_document.save(path));
    QVERIFY(!m_document.isModified());
    m_document.undoStack()->undo();
    QVERIFY(m_document.isModified());   // before the save is a change too
    m_document.undoStack()->redo();
    QVERIFY(!m_document.isModified());
    // A merge never continues across the save: the saved state stays reachable.
    pushMove(m_document, 1, {1, 0, 0}, true);
    QCOMPARE(m_document.undoStack()->count(), 2);
    m_document.undoStack()->undo();
    QVERIFY(!m_document.isModified());
}

void TestDocument::selectionNeverDirties() {
    QSignalSpy selection(&m_document, &SceneDocument::selectionChanged);
    m_document.setSelectedBodies({3, 1, 1, 99, -1});
    QCOMPARE(m_document.selectedBodies(), (QList<int>{1, 3}));  // sorted, deduplicated, in range
    QCOMPARE(selection.count(), 1);
    m_document.setSelectedBodies({1, 3});
    QCOMPARE(selection.count(), 1);  // no change, no signal
    QCOMPARE(m_document.undoStack()->count(), 0);
    QVERIFY(!m_document.isModified());
}

void TestDocument::uniqueBodyNames() {
    QCOMPARE(m_document.uniqueBodyName("Box"), QString("Box 1"));
    m_document.insertBody(0, interplay::templateBody(simcore::ShapeType::Box, "Box 1", {}));
    m_document.insertBody(0, interplay::templateBody(simcore::ShapeType::Box, "Box 3", {}));
    QCOMPARE(m_document.uniqueBodyName("Box"), QString("Box 2"));
}

void TestDocument::templateJointsAreAccepted_data() {
    QTest::addColumn<int>("type");
    QTest::addColumn<bool>("toWorld");
    for (simcore::JointType type : {simcore::JointType::Ball, simcore::JointType::Hinge, simcore::JointType::Slider,
                                    simcore::JointType::Fixed, simcore::JointType::Distance}) {
        const QByteArray name = interplay::jointTypeDisplayName(type).toLatin1();
        QTest::newRow(name + " between two bodies") << int(type) << false;
        QTest::newRow(name + " to the world") << int(type) << true;
    }
}

void TestDocument::templateJointsAreAccepted() {
    QFETCH(int, type);
    QFETCH(bool, toWorld);
    const simcore::SceneJoint joint =
        jointOf(m_document, simcore::JointType(type), 1, toWorld ? std::nullopt : std::optional<int>(2));
    QCOMPARE(m_document.jointProblem(joint), QString());
    const simcore::Vec3 a = m_document.body(1).body.position, b = m_document.body(2).body.position;
    if (toWorld) {
        QVERIFY(!joint.bodyB);
        QCOMPARE(joint.joint.anchor, a);  // at the body
    } else if (joint.joint.type == simcore::JointType::Distance) {
        QCOMPARE(joint.joint.anchor, a);  // a rod between the origins
        QCOMPARE(joint.joint.anchorB, b);
    } else {
        QVERIFY(glm::length(joint.joint.anchor - 0.5f * (a + b)) < 1e-5f);  // midway
    }
    if (joint.joint.type == simcore::JointType::Hinge && !toWorld) {
        QVERIFY(std::abs(glm::dot(joint.joint.axis, b - a)) < 1e-4f);  // square to the line: they swing
    }
    // And what the engine refuses is said: a rod of no length.
    simcore::SceneJoint rod = jointOf(m_document, simcore::JointType::Distance, 1, 2);
    rod.joint.anchorB = rod.joint.anchor;
    QVERIFY(m_document.jointProblem(rod).contains("anchorB"));
}

void TestDocument::addJointUndoRedo() {
    QSignalSpy inserted(&m_document, &SceneDocument::jointInserted);
    m_document.setSelectedBodies({1, 2});
    m_document.undoStack()->push(new AddJoint(&m_document, "Add Hinge Joint", 0, jointOf(m_document, simcore::JointType::Hinge, 1, 2)));
    QCOMPARE(m_document.jointCount(), 1);
    QCOMPARE(inserted.count(), 1);
    QCOMPARE(m_document.jointName(0), QString("Joint 1"));
    QCOMPARE(m_document.uniqueJointName("Joint"), QString("Joint 2"));
    QCOMPARE(m_document.undoStack()->undoText(), QString("Add Hinge Joint"));
    // The new joint is the selection, on its own.
    QCOMPARE(m_document.selectedJoints(), QList<int>{0});
    QVERIFY(m_document.selectedBodies().isEmpty());
    QVERIFY(m_document.isModified());

    m_document.undoStack()->undo();
    QCOMPARE(m_document.jointCount(), 0);
    QVERIFY(m_document.selectedJoints().isEmpty());
    QVERIFY(!m_document.isModified());
    m_document.undoStack()->redo();
    QCOMPARE(m_document.joint(0).joint.type, simcore::JointType::Hinge);
    QCOMPARE(m_document.joint(0).bodyA, std::size_t(1));
    QCOMPARE(m_document.joint(0).bodyB, std::optional<std::size_t>(2));
}

void TestDocument::deleteJointsBodiesOrBothInOneStep() {
    pushJoint(m_document, simcore::JointType::Hinge, 1, 2);  // Joint 1
    pushJoint(m_document, simcore::JointType::Ball, 3);      // Joint 2, capsule to the world
    pushJoint(m_document, simcore::JointType::Fixed, 4, 5);  // Joint 3
    const std::string before = text(m_document.scene());
    const int entries = m_document.undoStack()->count();
    QUndoStack* stack = m_document.undoStack();

    // A joint alone.
    stack->push(new RemoveBodies(&m_document, {}, {1}));
    QCOMPARE(stack->undoText(), QString("Delete Joint 2"));
    QCOMPARE(m_document.jointCount(), 2);
    QCOMPARE(m_document.bodyCount(), 6);
    stack->undo();
    QCOMPARE(text(m_document.scene()), before);
    QCOMPARE(m_document.selectedJoints(), QList<int>{1});  // undo selects what came back

    // A body takes its joint with it; the joints after it are renumbered, and undo puts all back.
    const QString capsule = m_document.bodyName(3);
    stack->push(new RemoveBodies(&m_document, {2}));
    QCOMPARE(m_document.jointCount(), 2);
    QCOMPARE(m_document.bodyName(int(m_document.joint(0).bodyA)), capsule);  // body 3 is now 2
    QCOMPARE(m_document.joint(1).bodyA, std::size_t(3));
    QCOMPARE(m_document.joint(1).bodyB, std::optional<std::size_t>(4));
    stack->undo();
    QCOMPARE(text(m_document.scene()), before);

    // Both, and a joint that is also attached to a deleted body: one entry, each removed once.
    const QString cylinder = m_document.bodyName(4);
    stack->push(new RemoveBodies(&m_document, {4}, {2, 0}));
    QCOMPARE(stack->undoText(), QString("Delete %1 and 2 Joints").arg(cylinder));
    QCOMPARE(m_document.jointCount(), 1);
    QCOMPARE(m_document.jointName(0), QString("Joint 2"));
    QCOMPARE(stack->count(), entries + 1);
    stack->undo();
    QCOMPARE(text(m_document.scene()), before);
    QCOMPARE(m_document.selectedBodies(), QList<int>{4});
    QCOMPARE(m_document.selectedJoints(), (QList<int>{0, 2}));
    stack->redo();
    QCOMPARE(m_document.jointCount(), 1);
}

void TestDocument::changeJointsUndoRedoMergeAndClean() {
    pushJoint(m_document, simcore::JointType::Hinge, 1, 2);
    QVERIFY(m_document.save(m_dir.filePath("joints.json")));
    const simcore::SceneJoint original = m_document.joint(0);
    QSignalSpy changed(&m_document, &SceneDocument::jointChanged);
    QUndoStack* stack = m_document.undoStack();
    const int saved = stack->count();

    simcore::SceneJoint motor = original;
    motor.joint.motor = simcore::JointMotor{1.0f, 50.0f};
    stack->push(new ChangeJoints(&m_document, "Change Motor of Joint 1", JointField::Motor, {0}, {motor}));
    for (int i = 2; i <= 10; ++i) {  // a continuous edit of the speed: one entry
        motor.joint.motor->speed = float(i);
        stack->push(new ChangeJoints(&m_document, "Change Motor of Joint 1", JointField::Motor, {0}, {motor}, true));
    }
    QCOMPARE(stack->count(), saved + 1);
    QCOMPARE(changed.count(), 10);
    QCOMPARE(changed.last().at(1).value<JointField>(), JointField::Motor);
    QCOMPARE(m_document.joint(0).joint.motor->speed, 10.0f);
    QVERIFY(m_document.isModified());

    // Another field is another entry; the same values again are no entry at all.
    simcore::SceneJoint limited = m_document.joint(0);
    limited.joint.limits = simcore::JointLimits{-0.5f, 0.5f};
    stack->push(new ChangeJoints(&m_document, "Change Limits of Joint 1", JointField::Limits, {0}, {limited}, true));
    QCOMPARE(stack->count(), saved + 2);
    stack->push(new ChangeJoints(&m_document, "Nothing", JointField::Limits, {0}, {m_document.joint(0)}));
    QCOMPARE(stack->count(), saved + 2);

    stack->undo();
    QVERIFY(!m_document.joint(0).joint.limits);
    stack->undo();
    QVERIFY(interplay::sameSceneJoint(m_document.joint(0), original));
    QVERIFY(!m_document.isModified());  // back at the saved state
    stack->redo();
    QCOMPARE(m_document.joint(0).joint.motor->speed, 10.0f);

    // Edited back to where it started: the entry is dropped.
    simcore::SceneJoint moved = m_document.joint(0);
    moved.joint.anchor.y += 1.0f;
    stack->push(new ChangeJoints(&m_document, "Change Anchor of Joint 1", JointField::Anchor, {0}, {moved}));
    stack->push(new ChangeJoints(&m_document, "Change Anchor of Joint 1", JointField::Anchor, {0},
                                 {m_document.joint(0)}, true));
    moved.joint.anchor.y -= 1.0f;
    stack->push(new ChangeJoints(&m_document, "Change Anchor of Joint 1", JointField::Anchor, {0}, {moved}, true));
    QCOMPARE(stack->count(), saved + 1);
}

void TestDocument::jointSelectionFollowsTheJoints() {
    pushJoint(m_document, simcore::JointType::Ball, 1);
    pushJoint(m_document, simcore::JointType::Ball, 2);
    pushJoint(m_document, simcore::JointType::Ball, 3);
    QSignalSpy selection(&m_document, &SceneDocument::selectionChanged);
    m_document.setSelection({1}, {2, 0, 2, 7});
    QCOMPARE(m_document.selectedJoints(), (QList<int>{0, 2}));  // sorted, deduplicated, in range
    QCOMPARE(selection.count(), 1);
    m_document.insertJoint(1, jointOf(m_document, simcore::JointType::Ball, 4));
    QCOMPARE(m_document.selectedJoints(), (QList<int>{0, 3}));  // the selected joints, not the rows
    m_document.takeJoint(0);
    QCOMPARE(m_document.selectedJoints(), QList<int>{2});
    QCOMPARE(m_document.jointName(2), QString("Joint 3"));
    // Picking a body starts a new selection.
    m_document.setSelectedBodies({2});
    QVERIFY(m_document.selectedJoints().isEmpty());
    QCOMPARE(m_document.undoStack()->count(), 3);  // selecting is not editing
}

void TestDocument::saveLoadRoundTripIsExact() {
    pushMove(m_document, 1, {0.123456789f, 0, 0}, false);
    const QString path = m_dir.filePath("round.json");
    QSignalSpy saved(&m_document, &SceneDocument::saved);
    QString error;
    QVERIFY2(m_document.save(path, &error), qPrintable(error));
    QCOMPARE(saved.count(), 1);
    QCOMPARE(m_document.filePath(), QFileInfo(path).absoluteFilePath());
    QCOMPARE(m_document.displayName(), QString("round.json"));

    SceneDocument loaded;
    QVERIFY2(loaded.load(path, &error), qPrintable(error));
    QCOMPARE(text(loaded.scene()), text(m_document.scene()));
    QVERIFY(!loaded.isModified());
    QCOMPARE(loaded.undoStack()->count(), 0);
}

void TestDocument::failedSaveLeavesTheOldFile() {
    // /proc does not take new files, even for root: the temporary file QSaveFile needs fails.
    const QString target = "/proc/version";
    QFile before(target);
    QVERIFY(before.open(QIODevice::ReadOnly));
    const QByteArray original = before.readAll();
    pushMove(m_document, 1, {1, 0, 0}, false);
    QString error;
    QVERIFY(!m_document.save(target, &error));
    QVERIFY2(error.contains(target), qPrintable(error));
    QFile after(target);
    QVERIFY(after.open(QIODevice::ReadOnly));
    QCOMPARE(after.readAll(), original);
    QVERIFY(m_document.isModified());  // still unsaved
    QVERIFY(m_document.filePath().isEmpty());

    QVERIFY(!m_document.save(m_dir.filePath("no/such/folder/scene.json"), &error));
    QVERIFY(!QFile::exists(m_dir.filePath("no/such/folder/scene.json")));
}

void TestDocument::thesisSceneIsImportedWithoutAPath() {
    QString error;
    QVERIFY2(m_document.load(INTERPLAY_SOURCE_DIR "/scenes/thesis/slope.json", &error), qPrintable(error));
    QVERIFY(m_document.filePath().isEmpty());  // Save must ask where to write v1
    QVERIFY(m_document.isModified());
    QCOMPARE(m_document.displayName(), QString("slope.json (imported)"));
    QVERIFY(m_document.bodyCount() > 0);

    QVERIFY(m_document.load(INTERPLAY_SOURCE_DIR "/scenes/incline.json", &error));
    QVERIFY(!m_document.isModified());
    QCOMPARE(m_document.displayName(), QString("incline.json"));
}

void TestDocument::loadErrorNamesFileAndJsonPath() {
    const QString path = m_dir.filePath("broken.json");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "interplay.scene", "version": 1,
                  "bodies": [{"name": "b", "shape": {"type": "sphere", "radius": -1}}]})");
    file.close();
    pushMove(m_document, 1, {1, 0, 0}, false);
    const std::string before = text(m_document.scene());
    QSignalSpy replaced(&m_document, &SceneDocument::sceneReplaced);
    QString error;
    QVERIFY(!m_document.load(path, &error));
    QVERIFY2(error.contains("broken.json") && error.contains("/bodies/0/shape/radius"), qPrintable(error));
    QCOMPARE(text(m_document.scene()), before);
    QCOMPARE(m_document.undoStack()->count(), 1);  // history kept too
    QCOMPARE(replaced.count(), 0);
}

void TestDocument::inspectorEditPushesACommand() {
    interplay::InspectorPanel inspector(&m_document);
    m_document.setSelectedBodies({1});
    interplay::NumberField* friction = inspector.numberField("friction");
    QVERIFY(friction);
    QCOMPARE(friction->text(), QString::number(m_document.body(1).body.friction));
    typeInto(friction, "0.85");
    QCOMPARE(m_document.body(1).body.friction, 0.85f);
    QCOMPARE(m_document.undoStack()->count(), 1);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Friction of %1").arg(m_document.bodyName(1)));

    typeInto(inspector.numberField("position.y"), "7.5");
    QCOMPARE(m_document.body(1).body.position.y, 7.5f);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Move %1").arg(m_document.bodyName(1)));

    typeInto(inspector.numberField("orientation.y"), "90");
    const simcore::Vec3 forward = m_document.body(1).body.orientation * simcore::Vec3(1, 0, 0);
    QVERIFY2(glm::length(forward - simcore::Vec3(0, 0, -1)) < 1e-4f, "90 degrees about y turns x into -z");
    QCOMPARE(m_document.undoStack()->undoText(), QString("Rotate %1").arg(m_document.bodyName(1)));

    typeInto(inspector.nameField(), "Crate");
    QCOMPARE(m_document.bodyName(1), QString("Crate"));
    QVERIFY(m_document.undoStack()->undoText().startsWith("Rename"));

    // Undo shows in the panel: the field follows the document.
    m_document.undoStack()->undo();
    m_document.undoStack()->undo();
    m_document.undoStack()->undo();
    QCOMPARE(inspector.numberField("position.y")->text(), QString::number(m_document.body(1).body.position.y));
    // Retyping the shown value is not an edit.
    typeInto(friction, friction->text());
    QCOMPARE(m_document.undoStack()->index(), 1);
}

void TestDocument::inspectorEditsEverySelectedBody() {
    interplay::InspectorPanel inspector(&m_document);
    m_document.setSelectedBodies({1, 2, 3});
    typeInto(inspector.numberField("restitution"), "0.25");
    QCOMPARE(m_document.undoStack()->count(), 1);  // one entry for all three
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Restitution of 3 Bodies"));
    for (int i : {1, 2, 3}) QCOMPARE(m_document.body(i).body.restitution, 0.25f);
    QCOMPARE(m_document.body(4).body.restitution, 0.0f);

    // Rolling resistance, next to it, the same way.
    interplay::NumberField* rolling = inspector.numberField("rollingResistance");
    QVERIFY(rolling);
    QCOMPARE(rolling->text(), QString::number(0.0));
    typeInto(rolling, "0.05");
    QCOMPARE(m_document.undoStack()->count(), 2);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Rolling Resistance of 3 Bodies"));
    for (int i : {1, 2, 3}) QCOMPARE(m_document.body(i).body.rollingResistance, 0.05f);
    QCOMPARE(m_document.body(4).body.rollingResistance, 0.0f);
    m_document.setSelectedBodies({3, 4});  // 0.05 and 0: mixed
    QVERIFY(rolling->text().isEmpty());
    QCOMPARE(rolling->placeholderText(), QString("mixed"));
    m_document.setSelectedBodies({1, 2, 3});
    QCOMPARE(rolling->text(), QString::number(0.05f));
    m_document.undoStack()->undo();
    for (int i : {1, 2, 3}) QCOMPARE(m_document.body(i).body.rollingResistance, 0.0f);
    QCOMPARE(rolling->text(), QString::number(0.0));
    m_document.setSelectedBodies({1, 2, 3});

    // Differing values show as "mixed": the x positions of a row of bodies.
    QVERIFY(inspector.numberField("position.x")->text().isEmpty());
    QCOMPARE(inspector.numberField("position.x")->placeholderText(), QString("mixed"));
    // A radius applies to the sphere, capsule and cylinder, not to the box: only they change.
    m_document.setSelectedBodies({1, 2});  // box, sphere
    typeInto(inspector.numberField("radius"), "0.7");
    QCOMPARE(m_document.body(2).body.shape.radius, 0.7f);
    QCOMPARE(m_document.body(1).body.shape.type, simcore::ShapeType::Box);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Radius of %1").arg(m_document.bodyName(2)));
}

void TestDocument::inspectorRejectsBadInput_data() {
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("reason");
    QTest::newRow("NaN friction") << "friction" << "nan" << "not a number";
    QTest::newRow("negative friction") << "friction" << "-0.5" << "between";
    QTest::newRow("restitution above 1") << "restitution" << "1.5" << "between";
    QTest::newRow("negative rolling resistance") << "rollingResistance" << "-0.1" << "between";
    QTest::newRow("NaN rolling resistance") << "rollingResistance" << "nan" << "not a number";
    QTest::newRow("rolling resistance beyond the format's range") << "rollingResistance" << "150" << "between";
    QTest::newRow("negative mass") << "mass" << "-2" << "between";
    QTest::newRow("density beyond the format's range") << "mass" << "5e7" << "between";  // the box is given by density
    QTest::newRow("zero half extent") << "halfExtents.x" << "0" << "between";
    QTest::newRow("infinite position") << "position.z" << "inf" << "not a number";
    QTest::newRow("huge position") << "position.x" << "1e9" << "between";
    QTest::newRow("text velocity") << "linearVelocity.y" << "fast" << "not a number";
}

void TestDocument::inspectorRejectsBadInput() {
    QFETCH(QString, field);
    QFETCH(QString, input);
    QFETCH(QString, reason);
    interplay::InspectorPanel inspector(&m_document);
    m_document.setSelectedBodies({1});  // the box: dynamic, so mass applies
    QSignalSpy rejected(&inspector, &interplay::InspectorPanel::rejected);
    const std::string before = text(m_document.scene());
    interplay::NumberField* number = inspector.numberField(field);
    QVERIFY(number);
    const QString shown = number->text();
    typeInto(number, input);
    QCOMPARE(rejected.count(), 1);
    QVERIFY2(inspector.message().contains(reason), qPrintable(inspector.message()));
    QCOMPARE(number->text(), shown);  // the old value again
    QCOMPARE(text(m_document.scene()), before);
    QCOMPARE(m_document.undoStack()->count(), 0);
    // A valid edit afterwards clears the message.
    typeInto(inspector.numberField("friction"), "0.3");
    QVERIFY(inspector.message().isEmpty());
}

void TestDocument::inspectorShapeAndMotionChoices() {
    interplay::InspectorPanel inspector(&m_document);
    m_document.setSelectedBodies({2});  // sphere
    QComboBox* shape = inspector.shapeTypeBox();
    const int cylinder = shape->findData(static_cast<int>(simcore::ShapeType::Cylinder));
    QVERIFY(cylinder >= 0);
    shape->setCurrentIndex(cylinder);
    emit shape->activated(cylinder);  // as a user's choice does
    QCOMPARE(m_document.body(2).body.shape.type, simcore::ShapeType::Cylinder);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Shape of %1").arg(m_document.bodyName(2)));

    QComboBox* motion = inspector.motionBox();
    const int staticRow = motion->findData(static_cast<int>(simcore::MotionType::Static));
    emit motion->activated(staticRow);
    QCOMPARE(m_document.body(2).body.motion, simcore::MotionType::Static);
    QVERIFY(!inspector.numberField("mass")->isVisibleTo(&inspector));  // a static body has no mass
    m_document.undoStack()->undo();
    m_document.undoStack()->undo();
    QCOMPARE(m_document.body(2).body.shape.type, simcore::ShapeType::Sphere);
}

void TestDocument::settingsModelPushesAndRejects() {
    interplay::SimulationSettingsModel model(&m_document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy changed(&model, &interplay::SimulationSettingsModel::changed);
    QSignalSpy rejected(&model, &interplay::SimulationSettingsModel::rejected);

    QVERIFY(model.setValue("substeps", 7));
    QCOMPARE(m_document.scene().settings.substeps, 7);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Substeps"));
    QVERIFY(changed.count() >= 1);
    QCOMPARE(model.preset(), -1);  // 7 substeps is no preset

    model.setPreset(2);  // Accurate
    QCOMPARE(model.preset(), 2);
    QCOMPARE(m_document.scene().settings.substeps, 8);

    QVERIFY(model.setValue("integrator", static_cast<int>(simcore::Integrator::VelocityVerlet)));
    QCOMPARE(m_document.scene().settings.integrator, simcore::Integrator::VelocityVerlet);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Integrator"));
    const int integratorRow = static_cast<int>(model.keys().indexOf("integrator"));
    QCOMPARE(model.index(integratorRow).data(interplay::SimulationSettingsModel::ChoicesRole).toStringList().size(), 3);
    QVERIFY(!model.setValue("integrator", 3));  // no such integrator: refused, nothing pushed
    QCOMPARE(rejected.count(), 1);
    QCOMPARE(m_document.undoStack()->undoText(), QString("Change Integrator"));
    QCOMPARE(m_document.scene().settings.integrator, simcore::Integrator::VelocityVerlet);

    QVERIFY(model.setValue("effects.friction", false));
    QVERIFY(!m_document.scene().settings.effects[simcore::Effect::Friction]);
    QCOMPARE(model.value("effects.friction").toBool(), false);

    const int entries = m_document.undoStack()->count();
    QVERIFY(!model.setValue("substeps", 0));
    QVERIFY(!model.setValue("timeStep", 0.0));
    QVERIFY(!model.setValue("gravity", QVariantList{0.0, std::nan(""), 0.0}));
    QVERIFY(!model.setValue("damping.linear", -1.0));
    QVERIFY(!model.setValue("damping.linear", QStringLiteral("fast")));  // not a number
    QVERIFY(!model.setValue("solver.bogus", 1));
    QCOMPARE(rejected.count(), 7);
    QCOMPARE(rejected.at(1).at(0).toString(), QString("Substeps not changed: substeps must be between 1 and 64, got 0"));
    QCOMPARE(rejected.at(3).at(0).toString(), QString("Gravity not changed: gravity[1] must be a finite number"));
    QCOMPARE(m_document.undoStack()->count(), entries);
    QCOMPARE(m_document.scene().settings.substeps, 8);

    // A drag (or a held spin box arrow) is one entry.
    model.setInteracting(true);
    for (int i = 1; i <= 10; ++i) QVERIFY(model.setValue("gravity", QVariantList{0.0, -double(i), 0.0}));
    model.setInteracting(false);
    QCOMPARE(m_document.undoStack()->count(), entries + 1);
    QCOMPARE(model.value("gravity").toList().at(1).toDouble(), -10.0);
}

void TestDocument::inspectorEditsJoints() {
    interplay::InspectorPanel inspector(&m_document);
    pushJoint(m_document, simcore::JointType::Hinge, 1, 2);  // selects it
    QUndoStack* stack = m_document.undoStack();
    const int entries = stack->count();
    // The joint's form, not the body form.
    QVERIFY(inspector.numberField("axis.x")->isVisibleTo(&inspector));
    QVERIFY(!inspector.numberField("friction")->isVisibleTo(&inspector));
    QVERIFY(!inspector.numberField("anchorB.x")->isVisibleTo(&inspector));  // distance joints only
    QVERIFY(!inspector.numberField("hingeMotorSpeed")->isVisibleTo(&inspector));  // the motor is off
    QCOMPARE(inspector.numberField("anchor.y")->text(), QString::number(m_document.joint(0).joint.anchor.y));

    typeInto(inspector.numberField("anchor.y"), "2.5");
    QCOMPARE(m_document.joint(0).joint.anchor.y, 2.5f);
    QCOMPARE(stack->undoText(), QString("Change Anchor of Joint 1"));

    inspector.motorBox()->click();
    QVERIFY(m_document.joint(0).joint.motor.has_value());
    QCOMPARE(stack->undoText(), QString("Change Motor of Joint 1"));
    QVERIFY(inspector.numberField("hingeMotorSpeed")->isVisibleTo(&inspector));
    QVERIFY(!inspector.numberField("sliderMotorSpeed")->isVisibleTo(&inspector));
    typeInto(inspector.numberField("hingeMotorSpeed"), "-3");
    QCOMPARE(m_document.joint(0).joint.motor->speed, -3.0f);
    QCOMPARE(stack->undoText(), QString("Change Hinge Motor Speed of Joint 1"));

    // Hinge limits read and write degrees; the scene keeps radians.
    inspector.limitsBox()->click();
    QCOMPARE(inspector.numberField("hingeUpper")->text(), QString("45"));
    typeInto(inspector.numberField("hingeUpper"), "90");
    QVERIFY(std::abs(m_document.joint(0).joint.limits->upper - simcore::kPi / 2) < 1e-6f);

    typeInto(inspector.jointNameField(), "Elbow");
    QCOMPARE(m_document.jointName(0), QString("Elbow"));
    QCOMPARE(stack->undoText(), QString("Rename Joint 1 to Elbow"));

    QCOMPARE(stack->count(), entries + 6);
    while (stack->index() > entries) stack->undo();
    QVERIFY(!m_document.joint(0).joint.motor);
    QVERIFY(!inspector.motorBox()->isChecked());  // the panel follows undo
    QCOMPARE(inspector.jointNameField()->text(), QString("Joint 1"));

    // A distance joint shows its own rows, and its spring can be switched on.
    pushJoint(m_document, simcore::JointType::Distance, 3, 4);
    QVERIFY(inspector.numberField("anchorB.x")->isVisibleTo(&inspector));
    QVERIFY(!inspector.numberField("axis.x")->isVisibleTo(&inspector));
    inspector.springBox()->click();
    typeInto(inspector.numberField("springHertz"), "4");
    QCOMPARE(m_document.joint(1).joint.spring->hertz, 4.0f);
    inspector.lengthsBox()->click();
    typeInto(inspector.numberField("maxLength"), "3");
    QCOMPARE(m_document.joint(1).joint.maxLength, std::optional<float>(3.0f));
}

void TestDocument::inspectorRejectsBadJointInput_data() {
    QTest::addColumn<int>("type");
    QTest::addColumn<QString>("option");  // a check box to switch on first, or empty
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("reason");
    const int hinge = int(simcore::JointType::Hinge), slider = int(simcore::JointType::Slider),
              distance = int(simcore::JointType::Distance);
    QTest::newRow("NaN anchor") << hinge << "" << "anchor.x" << "nan" << "not a number";
    QTest::newRow("infinite anchor") << hinge << "" << "anchor.z" << "-inf" << "not a number";
    QTest::newRow("zero axis") << hinge << "" << "axis.z" << "0" << "axis must not be zero";  // x and y are 0 already
    QTest::newRow("hinge limit beyond 180°") << hinge << "limits" << "hingeUpper" << "200" << "between";
    QTest::newRow("lower above upper") << hinge << "limits" << "hingeLower" << "50" << "exceeds upper";
    QTest::newRow("negative torque") << hinge << "motor" << "hingeMaxTorque" << "-1" << "between";
    QTest::newRow("text speed") << slider << "motor" << "sliderMotorSpeed" << "quick" << "not a number";
    QTest::newRow("slider lower above upper") << slider << "limits" << "sliderLower" << "2" << "exceeds upper";
    QTest::newRow("zero spring frequency") << distance << "spring" << "springHertz" << "0" << "hertz must be positive";
    QTest::newRow("minimum above maximum") << distance << "lengths" << "minLength" << "100" << "exceeds maxLength";
}

void TestDocument::inspectorRejectsBadJointInput() {
    QFETCH(int, type);
    QFETCH(QString, option);
    QFETCH(QString, field);
    QFETCH(QString, input);
    QFETCH(QString, reason);
    interplay::InspectorPanel inspector(&m_document);
    // Bodies on one line along x: the hinge axis is z, the slider axis x.
    m_document.undoStack()->push(new AddJoint(&m_document, "Add", 0, jointOf(m_document, simcore::JointType(type), 1, 2)));
    if (!option.isEmpty()) inspector.findChild<QCheckBox*>(option)->click();
    const std::string before = text(m_document.scene());
    const int entries = m_document.undoStack()->count();
    QSignalSpy rejected(&inspector, &interplay::InspectorPanel::rejected);
    interplay::NumberField* number = inspector.numberField(field);
    QVERIFY(number);
    QVERIFY(number->isVisibleTo(&inspector));
    const QString shown = number->text();
    typeInto(number, input);
    QCOMPARE(rejected.count(), 1);
    QVERIFY2(inspector.message().contains(reason), qPrintable(inspector.message()));
    QCOMPARE(number->text(), shown);
    QCOMPARE(text(m_document.scene()), before);
    QCOMPARE(m_document.undoStack()->count(), entries);
    // A valid edit afterwards clears the message.
    typeInto(inspector.numberField("anchor.y"), "3");
    QVERIFY(inspector.message().isEmpty());
}

int main(int argc, char* argv[]) {
    QApplication app(argc, argv);
    TestDocument test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_document.moc"
