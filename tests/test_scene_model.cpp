// The Scene dock's item model: checked by QAbstractItemModelTester through every kind of edit
// (insert, remove, move, rename, whole-scene replace, joints added, changed and deleted with their
// bodies, undo and redo), rename in place and drag to reorder as undoable commands, and the rows
// following the document.

#include "app/document/body_templates.h"
#include "app/document/scene_document.h"
#include "app/document/scene_tree_model.h"
#include "app/document/undo_commands.h"

#include <QAbstractItemModelTester>
#include <QCoreApplication>
#include <QMimeData>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <memory>

using interplay::SceneDocument;
using interplay::SceneTreeModel;

namespace {

QStringList rowNames(const SceneTreeModel& model) {
    QStringList names;
    const QModelIndex group = model.bodiesGroup();
    for (int row = 0; row < model.rowCount(group); ++row) names << model.index(row, 0, group).data().toString();
    return names;
}

QStringList bodyNames(const SceneDocument& document) {
    QStringList names;
    for (int i = 0; i < document.bodyCount(); ++i) names << document.bodyName(i);
    return names;
}

}  // namespace

class TestSceneModel : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void structureAndData();
    void staysConsistentThroughEveryEdit();
    void renameInPlaceIsUndoable();
    void jointsAreListedWithTheirBodies();
    void jointEditsKeepTheModelConsistent();
    void dragToReorderIsOneUndoableEntry_data();
    void dragToReorderIsOneUndoableEntry();
    void dropWhereTheyAreChangesNothing();

private:
    std::unique_ptr<SceneDocument> m_document;
    std::unique_ptr<SceneTreeModel> m_model;
    std::unique_ptr<QAbstractItemModelTester> m_tester;
};

void TestSceneModel::init() {
    m_document = std::make_unique<SceneDocument>();
    m_document->newDefault();
    m_model = std::make_unique<SceneTreeModel>(m_document.get());
    // Fatal: any inconsistency (bad parent, row counts that disagree with signals) fails the test.
    m_tester = std::make_unique<QAbstractItemModelTester>(m_model.get(),
                                                          QAbstractItemModelTester::FailureReportingMode::QtTest);
}

void TestSceneModel::cleanup() {
    m_tester.reset();
    m_model.reset();
    m_document.reset();
}

void TestSceneModel::structureAndData() {
    QCOMPARE(m_model->rowCount(), 2);  // Bodies, Joints
    const QModelIndex group = m_model->bodiesGroup();
    QCOMPARE(group.data().toString(), QString("Bodies (%1)").arg(m_document->bodyCount()));
    QCOMPARE(m_model->rowCount(group), m_document->bodyCount());
    QCOMPARE(rowNames(*m_model), bodyNames(*m_document));
    const QModelIndex sphere = m_model->indexOfBody(2);
    QCOMPARE(m_model->index(2, SceneTreeModel::TypeColumn, group).data().toString(), QString("Sphere"));
    QCOMPARE(m_model->index(0, SceneTreeModel::DetailsColumn, group).data().toString(), QString("static"));
    QCOMPARE(m_model->bodyIndexOf(sphere), 2);
    QCOMPARE(m_model->bodyIndexOf(group), -1);
    QVERIFY(m_model->flags(sphere) & Qt::ItemIsEditable);
    QVERIFY(m_model->flags(sphere) & Qt::ItemIsDragEnabled);
    QVERIFY(!(m_model->flags(group) & Qt::ItemIsSelectable));
    QVERIFY(m_model->flags(group) & Qt::ItemIsDropEnabled);
}

void TestSceneModel::staysConsistentThroughEveryEdit() {
    QUndoStack* stack = m_document->undoStack();
    QSignalSpy inserted(m_model.get(), &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(m_model.get(), &QAbstractItemModel::rowsRemoved);
    QSignalSpy moved(m_model.get(), &QAbstractItemModel::rowsMoved);

    const int count = m_document->bodyCount();
    stack->push(new interplay::AddBodies(m_document.get(), "Add", {1, count + 1},
                                         {interplay::templateBody(simcore::ShapeType::Box, "A", {}),
                                          interplay::templateBody(simcore::ShapeType::Sphere, "B", {})}));
    QCOMPARE(inserted.count(), 2);
    QCOMPARE(rowNames(*m_model), bodyNames(*m_document));
    stack->push(new interplay::RemoveBodies(m_document.get(), {0, 3, 5}));
    QCOMPARE(removed.count(), 3);
    QCOMPARE(rowNames(*m_model), bodyNames(*m_document));
    stack->push(new interplay::ReorderBody(m_document.get(), 0, 3));
    stack->push(new interplay::ReorderBody(m_document.get(), 4, 1));
    QCOMPARE(moved.count(), 2);
    QCOMPARE(rowNames(*m_model), bodyNames(*m_document));

    simcore::SceneBody renamed = m_document->body(2);
    renamed.body.name = "Renamed";
    QSignalSpy dataChanged(m_model.get(), &QAbstractItemModel::dataChanged);
    stack->push(new interplay::ChangeBodies(m_document.get(), "Rename", interplay::BodyField::Name, {2}, {renamed}));
    QCOMPARE(dataChanged.count(), 1);
    QCOMPARE(m_model->indexOfBody(2).data().toString(), QString("Renamed"));

    while (stack->canUndo()) {
        stack->undo();
        QCOMPARE(rowNames(*m_model), bodyNames(*m_document));
    }
    while (stack->canRedo()) stack->redo();
    QCOMPARE(rowNames(*m_model), bodyNames(*m_document));

    QSignalSpy reset(m_model.get(), &QAbstractItemModel::modelReset);
    m_document->newEmpty();
    QCOMPARE(reset.count(), 1);
    QCOMPARE(m_model->rowCount(m_model->bodiesGroup()), m_document->bodyCount());
}

void TestSceneModel::renameInPlaceIsUndoable() {
    const QModelIndex box = m_model->indexOfBody(1);
    const QString oldName = box.data().toString();
    QVERIFY(m_model->setData(box, "  Crate  "));
    QCOMPARE(m_document->bodyName(1), QString("Crate"));  // trimmed
    QCOMPARE(m_document->undoStack()->undoText(), QString("Rename %1 to Crate").arg(oldName));
    QVERIFY(m_document->isModified());
    QVERIFY(!m_model->setData(box, "   "));  // a body keeps a name
    QVERIFY(!m_model->setData(m_model->index(1, SceneTreeModel::TypeColumn, m_model->bodiesGroup()), "box"));
    QVERIFY(!m_model->setData(m_model->bodiesGroup(), "Things"));
    QCOMPARE(m_document->undoStack()->count(), 1);
    m_document->undoStack()->undo();
    QCOMPARE(m_model->indexOfBody(1).data().toString(), oldName);
}

void TestSceneModel::jointsAreListedWithTheirBodies() {
    const QModelIndex joints = m_model->jointsGroup();
    QCOMPARE(m_model->rowCount(joints), 0);
    simcore::SceneJoint hinge;
    hinge.joint.type = simcore::JointType::Hinge;
    hinge.joint.name = "door";
    hinge.bodyA = 1;
    hinge.bodyB = 2;
    simcore::SceneJoint toWorld;
    toWorld.bodyA = 3;
    QSignalSpy inserted(m_model.get(), &QAbstractItemModel::rowsInserted);
    m_document->insertJoint(0, hinge);
    m_document->insertJoint(1, toWorld);
    QCOMPARE(inserted.count(), 2);
    QCOMPARE(joints.data().toString(), QString("Joints (2)"));
    QCOMPARE(m_model->index(0, SceneTreeModel::NameColumn, joints).data().toString(), QString("door"));
    QCOMPARE(m_model->index(0, SceneTreeModel::TypeColumn, joints).data().toString(), QString("hinge"));
    QCOMPARE(m_model->index(0, SceneTreeModel::DetailsColumn, joints).data().toString(),
             QString("%1 – %2").arg(m_document->bodyName(1), m_document->bodyName(2)));
    QCOMPARE(m_model->index(1, SceneTreeModel::NameColumn, joints).data().toString(), QString("ball joint"));
    QVERIFY(m_model->index(1, SceneTreeModel::DetailsColumn, joints).data().toString().endsWith("world"));
    QCOMPARE(m_model->bodyIndexOf(m_model->index(0, 0, joints)), -1);
    QCOMPARE(m_model->jointIndexOf(m_model->index(1, 0, joints)), 1);
    QCOMPARE(m_model->jointIndexOf(m_model->indexOfBody(1)), -1);
    QCOMPARE(m_model->indexOfJoint(1, SceneTreeModel::TypeColumn), m_model->index(1, SceneTreeModel::TypeColumn, joints));
    QVERIFY(!m_model->indexOfJoint(2).isValid());
    // Selectable (the Inspector edits a selected joint), but neither renamed in place nor dragged.
    const Qt::ItemFlags jointFlags = m_model->flags(m_model->index(0, 0, joints));
    QVERIFY(jointFlags & Qt::ItemIsSelectable);
    QVERIFY(!(jointFlags & (Qt::ItemIsEditable | Qt::ItemIsDragEnabled)));

    // Renaming a body shows in its joints; deleting it removes them, undo brings them back.
    QVERIFY(m_model->setData(m_model->indexOfBody(2), "Frame"));
    QVERIFY(m_model->index(0, SceneTreeModel::DetailsColumn, joints).data().toString().endsWith("Frame"));
    QSignalSpy removed(m_model.get(), &QAbstractItemModel::rowsRemoved);
    m_document->undoStack()->push(new interplay::RemoveBodies(m_document.get(), {2}));
    QCOMPARE(m_model->rowCount(joints), 1);
    QCOMPARE(removed.count(), 2);  // the joint, then the body
    m_document->undoStack()->undo();
    QCOMPARE(m_model->rowCount(joints), 2);
    QCOMPARE(m_model->index(0, SceneTreeModel::NameColumn, joints).data().toString(), QString("door"));
}

void TestSceneModel::jointEditsKeepTheModelConsistent() {
    QUndoStack* stack = m_document->undoStack();
    const QModelIndex joints = m_model->jointsGroup();
    const auto addJoint = [this, stack](simcore::JointType type, int a, std::optional<int> b) {
        stack->push(new interplay::AddJoint(
            m_document.get(), "Add", m_document->jointCount(),
            interplay::templateJoint(type, m_document->uniqueJointName("Joint"), m_document->scene().bodies, std::size_t(a),
                                     b ? std::optional<std::size_t>(std::size_t(*b)) : std::nullopt)));
    };
    addJoint(simcore::JointType::Hinge, 1, 2);
    addJoint(simcore::JointType::Ball, 3, std::nullopt);
    addJoint(simcore::JointType::Distance, 2, 4);
    QCOMPARE(m_model->rowCount(joints), 3);
    QCOMPARE(joints.data().toString(), QString("Joints (3)"));
    QCOMPARE(m_model->indexOfJoint(2, SceneTreeModel::TypeColumn).data().toString(), QString("distance"));

    // A rename shows in the joint's row, and only there.
    QSignalSpy dataChanged(m_model.get(), &QAbstractItemModel::dataChanged);
    simcore::SceneJoint renamed = m_document->joint(1);
    renamed.joint.name = "Shoulder";
    stack->push(new interplay::ChangeJoints(m_document.get(), "Rename", interplay::JointField::Name, {1}, {renamed}));
    QCOMPARE(dataChanged.count(), 1);
    QCOMPARE(dataChanged.first().at(0).toModelIndex(), m_model->indexOfJoint(1, SceneTreeModel::NameColumn));
    QCOMPARE(m_model->indexOfJoint(1).data().toString(), QString("Shoulder"));

    // Deleting the sphere takes two joints; with a joint of its own named too, one entry.
    QSignalSpy removed(m_model.get(), &QAbstractItemModel::rowsRemoved);
    stack->push(new interplay::RemoveBodies(m_document.get(), {2}, {1}));
    QCOMPARE(removed.count(), 4);  // three joints, then the body
    QCOMPARE(m_model->rowCount(joints), 0);
    const auto jointNames = [this, joints] {
        QStringList names;
        for (int row = 0; row < m_model->rowCount(joints); ++row) names << m_model->index(row, 0, joints).data().toString();
        return names;
    };
    while (stack->canUndo()) {
        stack->undo();
        QCOMPARE(m_model->rowCount(joints), m_document->jointCount());
        QCOMPARE(rowNames(*m_model), bodyNames(*m_document));
    }
    QVERIFY(jointNames().isEmpty());
    while (stack->canRedo()) stack->redo();
    QCOMPARE(m_model->rowCount(joints), 0);
    stack->undo();
    QCOMPARE(jointNames(), (QStringList{"Joint 1", "Shoulder", "Joint 3"}));
}

void TestSceneModel::dragToReorderIsOneUndoableEntry_data() {
    QTest::addColumn<QList<int>>("dragged");
    QTest::addColumn<int>("dropRow");  // -1: on the group's empty space (the end)
    QTest::addColumn<int>("dropOnBody");  // >= 0: dropped onto that body instead
    QTest::addColumn<QList<int>>("expectedOrder");  // original indices, in the new order
    QTest::newRow("one down") << QList<int>{1} << 4 << -1 << QList<int>{0, 2, 3, 1, 4, 5};
    QTest::newRow("one up") << QList<int>{4} << 1 << -1 << QList<int>{0, 4, 1, 2, 3, 5};
    QTest::newRow("two to the end") << QList<int>{1, 3} << -1 << -1 << QList<int>{0, 2, 4, 5, 1, 3};
    QTest::newRow("two to the top") << QList<int>{2, 5} << 0 << -1 << QList<int>{2, 5, 0, 1, 3, 4};
    QTest::newRow("onto a body") << QList<int>{5} << -1 << 1 << QList<int>{0, 5, 1, 2, 3, 4};
}

void TestSceneModel::dragToReorderIsOneUndoableEntry() {
    QFETCH(QList<int>, dragged);
    QFETCH(int, dropRow);
    QFETCH(int, dropOnBody);
    QFETCH(QList<int>, expectedOrder);
    QCOMPARE(m_document->bodyCount(), 6);
    const QStringList before = bodyNames(*m_document);
    QStringList expected;
    for (int i : expectedOrder) expected << before[i];

    QModelIndexList indexes;
    for (int row : dragged) {
        indexes << m_model->indexOfBody(row, SceneTreeModel::NameColumn) << m_model->indexOfBody(row, SceneTreeModel::TypeColumn);
    }
    std::unique_ptr<QMimeData> data(m_model->mimeData(indexes));
    QVERIFY(data->hasFormat(SceneTreeModel::kBodyRowsMimeType));
    const QModelIndex parent = dropOnBody >= 0 ? m_model->indexOfBody(dropOnBody) : m_model->bodiesGroup();
    QVERIFY(m_model->canDropMimeData(data.get(), Qt::MoveAction, dropRow, 0, parent));
    QVERIFY(!m_model->canDropMimeData(data.get(), Qt::CopyAction, dropRow, 0, parent));
    QVERIFY(m_model->dropMimeData(data.get(), Qt::MoveAction, dropRow, 0, parent));

    QCOMPARE(bodyNames(*m_document), expected);
    QCOMPARE(rowNames(*m_model), expected);
    QCOMPARE(m_document->undoStack()->count(), 1);
    QVERIFY(m_document->undoStack()->undoText().startsWith("Reorder"));
    m_document->undoStack()->undo();
    QCOMPARE(bodyNames(*m_document), before);
    QCOMPARE(rowNames(*m_model), before);
}

void TestSceneModel::dropWhereTheyAreChangesNothing() {
    std::unique_ptr<QMimeData> data(m_model->mimeData({m_model->indexOfBody(2)}));
    QVERIFY(m_model->dropMimeData(data.get(), Qt::MoveAction, 2, 0, m_model->bodiesGroup()));
    QVERIFY(m_model->dropMimeData(data.get(), Qt::MoveAction, 3, 0, m_model->bodiesGroup()));
    QCOMPARE(m_document->undoStack()->count(), 0);
    QVERIFY(!m_document->isModified());
}

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    TestSceneModel test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_scene_model.moc"
