// File → Import Geometry and dropped mesh files, in the real window under Xvfb: a dropped OBJ opens
// the preview dialog (counts and bounds in metres after the scale typed into it), and OK adds one
// body as one undo entry - a mesh kept as a file reference, a mesh stored in the scene, or a dynamic
// convex hull; a hostile file shows the importer's message with OK off, and Cancel changes nothing;
// other files are not taken. With INTERPLAY_SCREENSHOT_DIR set it saves the dialog's picture there.

#include "app/document/scene_document.h"
#include "app/main_window.h"
#include "app/panels/import_geometry_dialog.h"
#include "simcore/shapes/convex_hull.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QUrl>

#include <memory>

using interplay::ImportGeometryDialog;

namespace {

// A box of half extents (1, 2, 3) as six quads, outward counter-clockwise.
const char* kBoxObj = "v -1 -2 -3\nv 1 -2 -3\nv 1 2 -3\nv -1 2 -3\nv -1 -2 3\nv 1 -2 3\nv 1 2 3\nv -1 2 3\n"
                      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

}  // namespace

class TestEditorImport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test_support::isolateSettings("test_editor_import"); }
    void cleanupTestCase() { test_support::removeSettings(); }
    void init();
    void cleanup() { test_support::closeWithoutPrompt(m_window); }
    void droppedObjBecomesAFileReferencedMesh();
    void meshInSceneAndHull();
    void hostileFileChangesNothing();
    void otherFilesAreNotTaken();

private:
    // Drags `path` over the window and drops it, as a file manager does; whether it was taken.
    bool drop(const QString& path);
    ImportGeometryDialog* dialog() const { return m_window->findChild<ImportGeometryDialog*>(); }
    void typeInto(QDoubleSpinBox* box, const QString& text);
    void choose(QComboBox* box, int row);

    std::unique_ptr<interplay::MainWindow> m_window;
    QTemporaryDir m_dir;
    QString m_box;
};

void TestEditorImport::init() {
    QVERIFY(m_dir.isValid());
    m_box = m_dir.filePath("box.obj");
    QFile file(m_box);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(kBoxObj);
    file.close();
    m_window = std::make_unique<interplay::MainWindow>();
    QVERIFY(test_support::showActive(*m_window));
    QVERIFY(m_window->findChild<QAction*>("importGeometry"));  // File → Import Geometry…
}

bool TestEditorImport::drop(const QString& path) {
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(path)});
    const QPoint at = m_window->rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(m_window.get(), &enter);
    if (!enter.isAccepted()) return false;
    QDropEvent dropped(QPointF(at), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(m_window.get(), &dropped);
    return dropped.isAccepted();
}

void TestEditorImport::typeInto(QDoubleSpinBox* box, const QString& text) {
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Tab);
}

void TestEditorImport::choose(QComboBox* box, int row) {
    box->setFocus();
    while (box->currentIndex() < row) QTest::keyClick(box, Qt::Key_Down);
    while (box->currentIndex() > row) QTest::keyClick(box, Qt::Key_Up);
}

void TestEditorImport::droppedObjBecomesAFileReferencedMesh() {
    interplay::SceneDocument* document = m_window->document();
    const QString scene = m_dir.filePath("scene.json");
    QVERIFY(document->save(scene));  // so the reference is made relative to the scene's folder
    const int bodies = document->bodyCount();
    const int entries = document->undoStack()->count();
    QVERIFY(drop(m_box));
    QTRY_VERIFY(dialog() && dialog()->isVisible());
    auto* preview = dialog()->findChild<QLabel*>("importPreview");
    QVERIFY(preview);
    QVERIFY2(preview->text().startsWith("12 triangles, 8 vertices; 2 × 4 × 6 m"), qPrintable(preview->text()));
    typeInto(dialog()->findChild<QDoubleSpinBox*>("scaleX"), "2.5");
    QVERIFY2(preview->text().contains("5 × 4 × 6 m, from (-2.5, -2, -3) to (2.5, 2, 3)"), qPrintable(preview->text()));
    choose(dialog()->findChild<QComboBox*>("upAxis"), 1);  // the file is z-up: its z becomes y
    QVERIFY2(preview->text().contains("5 × 6 × 4 m"), qPrintable(preview->text()));
    choose(dialog()->findChild<QComboBox*>("importKind"), 1);  // a static mesh referring to the file
    if (const QByteArray dir = qgetenv("INTERPLAY_SCREENSHOT_DIR"); !dir.isEmpty())
        QVERIFY(dialog()->grab().save(QString::fromLocal8Bit(dir) + "/import_geometry_dialog.png"));
    QPushButton* ok = dialog()->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    QTest::mouseClick(ok, Qt::LeftButton);

    QTRY_COMPARE(document->bodyCount(), bodies + 1);
    QCOMPARE(document->undoStack()->count(), entries + 1);  // one entry
    QCOMPARE(document->undoStack()->undoText(), QString("Import box.obj"));
    const simcore::SceneBody& body = document->body(bodies);
    QCOMPARE(QString::fromStdString(body.body.name), QString("box 1"));  // uniqueBodyName numbers from 1
    QVERIFY(body.body.motion == simcore::MotionType::Static);
    QVERIFY(body.body.shape.type == simcore::ShapeType::Mesh && body.body.shape.mesh);
    QCOMPARE(body.body.shape.mesh->triangleCount(), std::size_t(12));
    QVERIFY(glm::length(body.body.shape.mesh->bounds().max - simcore::Vec3(2.5f, 3.0f, 2.0f)) < 1e-5f);
    QVERIFY(body.meshFile);
    QCOMPARE(QString::fromStdString(body.meshFile->resolvedPath.string()), QFileInfo(m_box).absoluteFilePath());
    QVERIFY(body.meshFile->scale == simcore::Vec3(2.5f, 1.0f, 1.0f));
    QVERIFY(body.meshFile->upAxis == simcore::UpAxis::Z);
    QCOMPARE(document->selectedBodies(), QList<int>{bodies});

    // Saved, the scene refers to the file, also from another folder; undo takes the body away again.
    QCOMPARE(body.meshFile->file, std::string("box.obj"));
    QVERIFY(QDir(m_dir.path()).mkpath("elsewhere"));
    QVERIFY(document->save(m_dir.filePath("elsewhere/scene.json")));
    QFile saved(m_dir.filePath("elsewhere/scene.json"));
    QVERIFY(saved.open(QIODevice::ReadOnly));
    const QByteArray text = saved.readAll();
    QVERIFY2(text.contains(R"("file": "../box.obj")") && text.contains(R"("upAxis": "z")"), text.constData());
    document->undoStack()->undo();
    QCOMPARE(document->bodyCount(), bodies);
}

void TestEditorImport::meshInSceneAndHull() {
    interplay::SceneDocument* document = m_window->document();
    const int bodies = document->bodyCount();
    QVERIFY(drop(m_box));
    QTRY_VERIFY(dialog() && dialog()->isVisible());
    QTest::mouseClick(dialog()->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
    QTRY_COMPARE(document->bodyCount(), bodies + 1);
    QVERIFY(!document->body(bodies).meshFile);  // stored in the scene: the default choice
    QCOMPARE(document->body(bodies).body.shape.mesh->triangleCount(), std::size_t(12));
    QTRY_VERIFY(!dialog());  // closed and deleted

    QVERIFY(drop(m_box));
    QTRY_VERIFY(dialog() && dialog()->isVisible());
    choose(dialog()->findChild<QComboBox*>("importKind"), 2);
    QVERIFY2(dialog()->findChild<QLabel*>("importKindNote")->text().contains("8 corners"),
             qPrintable(dialog()->findChild<QLabel*>("importKindNote")->text()));
    QTest::mouseClick(dialog()->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
    QTRY_COMPARE(document->bodyCount(), bodies + 2);
    const simcore::SceneBody& hull = document->body(bodies + 1);
    QVERIFY(hull.body.motion == simcore::MotionType::Dynamic);
    QVERIFY(hull.body.shape.type == simcore::ShapeType::ConvexHull);
    QCOMPARE(hull.body.shape.hull->vertices().size(), std::size_t(8));
    QCOMPARE(QString::fromStdString(hull.body.name), QString("box 2"));
}

void TestEditorImport::hostileFileChangesNothing() {
    interplay::SceneDocument* document = m_window->document();
    const int bodies = document->bodyCount();
    const int entries = document->undoStack()->count();
    QVERIFY(drop(INTERPLAY_SOURCE_DIR "/tests/data/meshes/hostile/truncated.glb"));
    QTRY_VERIFY(dialog() && dialog()->isVisible());
    const QString message = dialog()->findChild<QLabel*>("importPreview")->text();
    QVERIFY2(message.contains("truncated.glb: is a binary glTF whose header says 628 bytes, but it has 100"), qPrintable(message));
    QVERIFY(!dialog()->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled());
    QTest::mouseClick(dialog()->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Cancel), Qt::LeftButton);
    QTRY_VERIFY(!dialog());
    QCOMPARE(document->bodyCount(), bodies);
    QCOMPARE(document->undoStack()->count(), entries);
}

void TestEditorImport::otherFilesAreNotTaken() {
    QFile text(m_dir.filePath("notes.txt"));
    QVERIFY(text.open(QIODevice::WriteOnly));
    text.write("not geometry");
    text.close();
    QVERIFY(!drop(text.fileName()));
    QVERIFY(!dialog());
}

QTEST_MAIN(TestEditorImport)
#include "test_editor_import.moc"
