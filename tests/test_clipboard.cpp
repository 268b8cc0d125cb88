// The clipboard's model layer, without a window: a selection becomes a scene fragment (its bodies
// and the joints among them) and scene file text, which parses back to the identical bodies and
// joints; a joint to a body left out is dropped; pasted names are made unique against the document;
// text that is no scene is refused with the loader's reason; the offsets place copies beside their
// originals or on a point; and the paste command adds all of it as one undo entry.

#include "app/document/scene_clipboard.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"

#include "simcore/io/scene_io.h"
#include "simcore/shapes/shape.h"

#include <QMimeData>
#include <QTest>
#include <QUndoStack>

#include <glm/glm.hpp>

using simcore::Scene;
using simcore::SceneBody;
using simcore::SceneJoint;
using simcore::Vec3;

namespace {

SceneBody box(const char* name, const Vec3& position, const Vec3& halfExtents = Vec3(0.5f)) {
    SceneBody body;
    body.body.name = name;
    body.body.shape = simcore::Shape::box(halfExtents);
    body.body.position = position;
    body.body.mass = 2.0f;
    body.body.friction = 0.3f;
    body.color = Vec3(0.2f, 0.4f, 0.8f);
    return body;
}

SceneJoint joint(simcore::JointType type, const char* name, std::size_t a, std::optional<std::size_t> b,
                 const Vec3& anchor) {
    SceneJoint j;
    j.joint.type = type;
    j.joint.name = name;
    j.joint.anchor = anchor;
    // Only hinges and sliders have an axis a file keeps.
    if (type == simcore::JointType::Hinge || type == simcore::JointType::Slider) j.joint.axis = Vec3(0.0f, 0.0f, 1.0f);
    j.bodyA = a;
    j.bodyB = b;
    return j;
}

// Three boxes in a row along x, 2 m apart: a hinge between the first two, a ball joint between the
// last two, and a hinge holding the first to the world.
Scene threeJointedBoxes() {
    Scene scene;
    scene.settings.substeps = 6;
    scene.bodies = {box("Box 1", {0.0f, 1.0f, 0.0f}), box("Box 2", {2.0f, 1.0f, 0.0f}),
                    box("Box 3", {4.0f, 1.0f, 0.0f})};
    scene.joints = {joint(simcore::JointType::Hinge, "door hinge", 0, 1, {1.0f, 1.0f, 0.0f}),
                    joint(simcore::JointType::Ball, "", 1, 2, {3.0f, 1.0f, 0.0f}),
                    joint(simcore::JointType::Hinge, "post", 0, std::nullopt, {0.0f, 1.0f, 0.0f})};
    return scene;
}

QString errorsOf(const std::vector<simcore::Diagnostic>& diagnostics) {
    QStringList errors;
    for (const simcore::Diagnostic& d : diagnostics) {
        if (d.severity == simcore::Diagnostic::Severity::Error) errors << QString::fromStdString(d.toString());
    }
    return errors.join('\n');
}

}  // namespace

class TestClipboard : public QObject {
    Q_OBJECT

private slots:
    void fragmentRoundTripsBodiesAndJoints();
    void jointToABodyLeftOutIsDropped();
    void namesAreMadeUnique();
    void badTextIsRefusedWithAMessage_data();
    void badTextIsRefusedWithAMessage();
    void offsetsPlaceBesideOrOnAPoint();
    void mimeDataCarriesOurTypeAndPlainText();
    void pasteIsOneUndoEntry();
};

void TestClipboard::fragmentRoundTripsBodiesAndJoints() {
    const Scene scene = threeJointedBoxes();
    const Scene fragment = interplay::sceneFragment(scene, {2, 0, 1, 1});  // any order, duplicates
    QCOMPARE(fragment.bodies.size(), std::size_t(3));
    QCOMPARE(fragment.joints.size(), std::size_t(3));

    const interplay::ParsedFragment parsed = interplay::parseFragment(interplay::fragmentText(fragment));
    QVERIFY2(parsed.fragment, qPrintable(parsed.error));
    QVERIFY(parsed.error.isEmpty());
    const Scene& back = *parsed.fragment;
    QCOMPARE(back.settings.substeps, 6);  // the settings travel, so the fragment runs as it did
    QCOMPARE(back.bodies.size(), scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        QVERIFY2(interplay::sameSceneBody(back.bodies[i], scene.bodies[i]), scene.bodies[i].body.name.c_str());
    }
    QCOMPARE(back.joints.size(), scene.joints.size());
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
        // The loader names an unnamed joint after its row, as it names it in a file.
        SceneJoint expected = scene.joints[i];
        expected.joint.name = back.joints[i].joint.name;
        QVERIFY2(interplay::sameSceneJoint(back.joints[i], expected), qPrintable(QString::number(i)));
    }
    QCOMPARE(back.joints[0].joint.name, std::string("door hinge"));
}

void TestClipboard::jointToABodyLeftOutIsDropped() {
    const Scene scene = threeJointedBoxes();
    // Boxes 2 and 3: the ball joint between them stays (renumbered 0-1), both hinges use box 1.
    const Scene lastTwo = interplay::sceneFragment(scene, {1, 2});
    QCOMPARE(lastTwo.bodies.size(), std::size_t(2));
    QCOMPARE(lastTwo.bodies[0].body.name, std::string("Box 2"));
    QCOMPARE(lastTwo.joints.size(), std::size_t(1));
    QCOMPARE(lastTwo.joints[0].joint.type, simcore::JointType::Ball);
    QCOMPARE(lastTwo.joints[0].bodyA, std::size_t(0));
    QCOMPARE(lastTwo.joints[0].bodyB, std::optional<std::size_t>(1));

    // Box 1 alone keeps the hinge that holds it to the world, not the one to box 2.
    const Scene first = interplay::sceneFragment(scene, {0});
    QCOMPARE(first.joints.size(), std::size_t(1));
    QCOMPARE(first.joints[0].joint.name, std::string("post"));
    QVERIFY(!first.joints[0].bodyB);

    // Boxes 1 and 3: no joint joins just them, but box 1's world joint comes along.
    const Scene ends = interplay::sceneFragment(scene, {0, 2});
    QCOMPARE(ends.joints.size(), std::size_t(1));
    QCOMPARE(ends.joints[0].joint.name, std::string("post"));
    // And each of these is a scene the loader opens.
    for (const Scene* s : {&lastTwo, &first, &ends})
        QVERIFY2(errorsOf(simcore::checkScene(*s)).isEmpty(), qPrintable(errorsOf(simcore::checkScene(*s))));
}

void TestClipboard::namesAreMadeUnique() {
    interplay::SceneDocument document;
    document.restoreRecovered(threeJointedBoxes(), {});
    Scene fragment = interplay::sceneFragment(document.scene(), {0, 1, 2});
    fragment.bodies[2].body.name = "ground";                       // an unnumbered name the document does not use...
    fragment.bodies.push_back(box("ground", {8.0f, 1.0f, 0.0f}));  // ...twice in the fragment
    interplay::giveUniqueNames(fragment, document);
    QCOMPARE(fragment.bodies[0].body.name, std::string("Box 4"));
    QCOMPARE(fragment.bodies[1].body.name, std::string("Box 5"));
    QCOMPARE(fragment.bodies[2].body.name, std::string("ground 1"));
    QCOMPARE(fragment.bodies[3].body.name, std::string("ground 2"));
    QCOMPARE(fragment.joints[0].joint.name, std::string("door hinge 1"));
    QCOMPARE(fragment.joints[2].joint.name, std::string("post 1"));

    // Added to the document, the scene is one the loader opens: no name a joint needs is shared.
    Scene merged = document.scene();
    const std::size_t first = merged.bodies.size();
    merged.bodies.insert(merged.bodies.end(), fragment.bodies.begin(), fragment.bodies.end());
    for (SceneJoint j : fragment.joints) {
        j.bodyA += first;
        if (j.bodyB) *j.bodyB += first;
        merged.joints.push_back(j);
    }
    QVERIFY2(errorsOf(simcore::checkScene(merged)).isEmpty(), qPrintable(errorsOf(simcore::checkScene(merged))));
}

void TestClipboard::badTextIsRefusedWithAMessage_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("says");  // a part of the message that names what is wrong
    QTest::newRow("empty") << QByteArray("  \n") << "it is empty";
    QTest::newRow("prose") << QByteArray("hello, world") << "clipboard:1:";
    QTest::newRow("json, not a scene") << QByteArray(R"({"hello": 1})") << "clipboard";
    const QByteArray negativeMass = R"({"format": "interplay.scene", "version": 1, "bodies": [
        {"name": "b", "shape": {"type": "sphere", "radius": 0.5}, "position": [0, 1, 0], "mass": -1}]})";
    QTest::newRow("negative mass") << negativeMass << "/bodies/0/mass";
    const QByteArray noBodies = R"({"format": "interplay.scene", "version": 1, "bodies": []})";
    QTest::newRow("no bodies") << noBodies << "no bodies";
}

void TestClipboard::badTextIsRefusedWithAMessage() {
    QFETCH(QByteArray, text);
    QFETCH(QString, says);
    const interplay::ParsedFragment parsed = interplay::parseFragment(text);
    QVERIFY(!parsed.fragment);
    QVERIFY2(parsed.error.contains(says), qPrintable(parsed.error));
}

void TestClipboard::offsetsPlaceBesideOrOnAPoint() {
    Scene fragment = interplay::sceneFragment(threeJointedBoxes(), {0, 1});
    // Two unit boxes, centres 2 m apart: 3 m wide, so beside is 3.1 m along +x.
    const Vec3 beside = interplay::offsetBeside(fragment);
    QCOMPARE(beside, Vec3(3.1f, 0.0f, 0.0f));

    const Vec3 point(-5.0f, 2.0f, 7.0f);
    const Vec3 onto = interplay::offsetOnto(fragment, point);
    const SceneJoint hingeBefore = fragment.joints[0];
    interplay::translateFragment(fragment, onto);
    const simcore::Aabb bounds = interplay::fragmentBounds(fragment);
    // Centred over the point in x and z, its bottom at the point's height (float sums: 1e-5 m).
    QVERIFY(glm::length(Vec3(bounds.center().x, bounds.min.y, bounds.center().z) - point) < 1e-5f);
    QCOMPARE(fragment.joints[0].joint.anchor, hingeBefore.joint.anchor + onto);  // the anchor rides along
    QCOMPARE(fragment.joints[0].joint.axis, hingeBefore.joint.axis);             // a direction does not move
    QCOMPARE(interplay::offsetBeside(Scene{}), Vec3(0.0f));                      // nothing to measure
}

void TestClipboard::mimeDataCarriesOurTypeAndPlainText() {
    const Scene fragment = interplay::sceneFragment(threeJointedBoxes(), {1});
    std::unique_ptr<QMimeData> data(interplay::fragmentMimeData(fragment));
    QVERIFY(data->hasFormat(interplay::kSceneFragmentMimeType));
    QVERIFY(data->hasText());
    QCOMPARE(data->text().toUtf8(), interplay::fragmentText(fragment));
    QCOMPARE(interplay::fragmentTextOf(*data), interplay::fragmentText(fragment));
    // Our type wins over whatever else the text says; plain text alone is read as well.
    data->setText(QStringLiteral("not a scene"));
    QCOMPARE(interplay::fragmentTextOf(*data), interplay::fragmentText(fragment));
    QMimeData plain;
    plain.setText(QStringLiteral("{}"));
    QCOMPARE(interplay::fragmentTextOf(plain), QByteArray("{}"));
}

void TestClipboard::pasteIsOneUndoEntry() {
    interplay::SceneDocument document;
    document.restoreRecovered(threeJointedBoxes(), {});
    const std::string before = simcore::serializeScene(document.scene());
    Scene fragment = interplay::sceneFragment(document.scene(), {1, 2});
    interplay::giveUniqueNames(fragment, document);
    interplay::translateFragment(fragment, interplay::offsetBeside(fragment));
    QUndoStack* stack = document.undoStack();
    const int entries = stack->count();
    stack->push(new interplay::AddFragment(&document, QStringLiteral("Paste 2 Bodies"), fragment));
    QCOMPARE(stack->count(), entries + 1);
    QCOMPARE(document.bodyCount(), 5);
    QCOMPARE(document.jointCount(), 4);
    QCOMPARE(document.selectedBodies(), (QList<int>{3, 4}));
    QVERIFY(document.selectedJoints().isEmpty());
    // The ball joint now joins the copies, not the originals.
    QCOMPARE(document.joint(3).bodyA, std::size_t(3));
    QCOMPARE(document.joint(3).bodyB, std::optional<std::size_t>(4));
    QCOMPARE(document.bodyName(3), QString("Box 4"));
    QVERIFY(errorsOf(simcore::checkScene(document.scene())).isEmpty());

    stack->undo();
    QCOMPARE(simcore::serializeScene(document.scene()), before);
    stack->redo();
    QCOMPARE(document.bodyCount(), 5);
    QCOMPARE(document.selectedBodies(), (QList<int>{3, 4}));
}

QTEST_GUILESS_MAIN(TestClipboard)
#include "test_clipboard.moc"
