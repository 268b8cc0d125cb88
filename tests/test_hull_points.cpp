// A convex hull's points as a table: the reader of files of points (x y z lines, CSV, an OBJ's
// vertices) and its errors, the table model and the hull it rebuilds, and the Inspector's
// Edit Points... dialog driven with real mouse and key events under Xvfb: an edited cell and an
// imported file change the body's hull as one undo entry, and points with no volume keep OK off.

#include "app/document/scene_document.h"
#include "app/main_window.h"
#include "app/panels/hull_points_dialog.h"
#include "app/panels/hull_points_model.h"
#include "app/panels/inspector_panel.h"

#include "simcore/settings_schema.h"

#include "support/editor_window.h"
#include "support/isolated_settings.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>

using interplay::HullPointsModel;
using interplay::parsePointList;

class TestHullPoints : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void cleanup();

    void readsPlainCsvAndObjPoints();
    void refusesWhatIsNotAPointNamingTheLine();
    void modelRebuildsTheHull();
    void dialogEditsTheHullAsOneUndoEntry();
    void dialogImportsAFileOfPoints();

private:
    void openHullBody();
    interplay::HullPointsDialog* openDialog();

    std::unique_ptr<interplay::MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestHullPoints::initTestCase() {
    test_support::isolateSettings("test_hull_points");
    QVERIFY(m_dir.isValid());
}

void TestHullPoints::cleanupTestCase() { test_support::removeSettings(); }

void TestHullPoints::cleanup() { test_support::closeWithoutPrompt(m_window); }

void TestHullPoints::readsPlainCsvAndObjPoints() {
    const auto plain = parsePointList("# a unit tetrahedron\n0 0 0\n1 0 0\n\n0 1 0\n0\t0  1\n");
    QVERIFY2(plain.error.isEmpty(), qPrintable(plain.error));
    QCOMPARE(plain.points.size(), std::size_t(4));
    QCOMPARE(plain.points[3], simcore::Vec3(0, 0, 1));

    const auto csv = parsePointList("1.5, -2, 3e-1\n4;5;6\n");
    QVERIFY2(csv.error.isEmpty(), qPrintable(csv.error));
    QCOMPARE(csv.points[0], simcore::Vec3(1.5f, -2.0f, 0.3f));
    QCOMPARE(csv.points[1], simcore::Vec3(4, 5, 6));

    // An OBJ's vertices (a w component ignored); faces, normals and groups are not points.
    const auto obj = parsePointList("o cube\nv 1 2 3\nv 4 5 6 1.0\nvn 0 0 1\nvt 0.5 0.5\nf 1 2 3\ng x\nv 7 8 9\n");
    QVERIFY2(obj.error.isEmpty(), qPrintable(obj.error));
    QCOMPARE(obj.points.size(), std::size_t(3));
    QCOMPARE(obj.points[1], simcore::Vec3(4, 5, 6));
}

void TestHullPoints::refusesWhatIsNotAPointNamingTheLine() {
    const auto two = parsePointList("0 0 0\n1 2\n");
    QVERIFY(two.points.empty() || !two.error.isEmpty());
    QVERIFY2(two.error.startsWith("line 2:") && two.error.contains("three numbers"), qPrintable(two.error));
    const auto word = parsePointList("0 0 0\n1 x 2\n");
    QVERIFY2(word.error.startsWith("line 2:") && word.error.contains("\"x\""), qPrintable(word.error));
    const auto infinite = parsePointList("0 0 inf\n");
    QVERIFY2(infinite.error.startsWith("line 1:"), qPrintable(infinite.error));
    const auto far = parsePointList("0 0 2e6\n");
    QVERIFY2(far.error.contains("outside the coordinate range"), qPrintable(far.error));
    QVERIFY2(parsePointList("# nothing\n\n").error.contains("no points"), "an empty file is refused");

    QString many;
    for (std::size_t i = 0; i <= simcore::limits::kMaxHullPoints; ++i) many += QStringLiteral("%1 0 0\n").arg(i);
    const auto tooMany = parsePointList(many);
    QVERIFY2(tooMany.error.contains(QString::number(simcore::limits::kMaxHullPoints)), qPrintable(tooMany.error));

    const auto missing = interplay::readPointFile(m_dir.filePath("absent.xyz"));
    QVERIFY2(missing.error.startsWith("absent.xyz:"), qPrintable(missing.error));
}

void TestHullPoints::modelRebuildsTheHull() {
    HullPointsModel model;
    model.setPoints({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    QVERIFY(model.hull().hull);
    QCOMPARE(model.hull().hull->vertices().size(), std::size_t(4));
    // Flattening the apex leaves no volume; typing it back restores the hull.
    QVERIFY(model.setData(model.index(3, 2), 0.0, Qt::EditRole));
    QVERIFY(!model.hull().hull);
    QVERIFY(!model.hull().error.empty());
    QVERIFY(model.setData(model.index(3, 2), 2.0, Qt::EditRole));
    QVERIFY(model.hull().hull);
    QVERIFY(!model.setData(model.index(0, 0), 5e6, Qt::EditRole));  // outside the scene format's range
    QVERIFY(!model.setData(model.index(0, 0), QStringLiteral("x"), Qt::EditRole));
    QCOMPARE(model.points()[0].x, 0.0f);
    // A new row copies the one above it, so the hull keeps its shape until it is edited.
    QVERIFY(model.insertRows(4, 1));
    QCOMPARE(model.points()[4], model.points()[3]);
    QCOMPARE(model.hull().hull->vertices().size(), std::size_t(4));
    QVERIFY(model.removeRows(0, 2));
    QCOMPARE(model.rowCount(), 3);
    QVERIFY(!model.hull().hull);  // three points are not a solid
}

void TestHullPoints::openHullBody() {
    m_window = std::make_unique<interplay::MainWindow>();
    m_window->openDefaultScene();
    QVERIFY(test_support::showActive(*m_window));
    m_window->action("addHull")->trigger();
    interplay::SceneDocument* document = m_window->document();
    const int hull = document->bodyCount() - 1;
    QCOMPARE(document->body(hull).body.shape.type, simcore::ShapeType::ConvexHull);
    QCOMPARE(document->selectedBodies(), QList<int>{hull});
}

interplay::HullPointsDialog* TestHullPoints::openDialog() {
    auto* button = m_window->inspector()->findChild<QPushButton*>("editHullPoints");
    if (!button || !button->isVisible() || !button->isEnabled()) return nullptr;
    QTest::mouseClick(button, Qt::LeftButton);
    auto* dialog = m_window->inspector()->findChild<interplay::HullPointsDialog*>();
    if (dialog && !QTest::qWaitForWindowExposed(dialog)) return nullptr;
    return dialog;
}

void TestHullPoints::dialogEditsTheHullAsOneUndoEntry() {
    openHullBody();
    interplay::SceneDocument* document = m_window->document();
    const int body = document->selectedBodies().first();
    const std::vector<simcore::Vec3> before = document->body(body).body.shape.hull->sourcePoints();
    const int entries = document->undoStack()->count();

    interplay::HullPointsDialog* dialog = openDialog();
    QVERIFY(dialog);
    QCOMPARE(dialog->points(), before);
    auto* table = dialog->findChild<QTableView*>("hullPoints");
    auto* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(table && ok && ok->isEnabled());

    // Type a new x for the first point, as a user would: select the cell, F2, the number, Enter.
    table->setFocus();
    table->setCurrentIndex(dialog->model()->index(0, 0));
    QTest::keyClick(table, Qt::Key_F2);
    auto* editor = table->findChild<QLineEdit*>();
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, "3.5");
    QTest::keyClick(editor, Qt::Key_Return);
    QTRY_COMPARE(dialog->points()[0].x, 3.5f);  // the delegate commits on its next event-loop turn
    QVERIFY(ok->isEnabled());
    QVERIFY2(dialog->findChild<QLabel*>("hullStatus")->text().contains("a hull of"),
             qPrintable(dialog->findChild<QLabel*>("hullStatus")->text()));
    QCOMPARE(document->body(body).body.shape.hull->sourcePoints(), before);  // nothing until OK
    test_support::saveScreenshotIfAsked(*m_window, "INTERPLAY_HULL_POINTS_SCREENSHOT");

    QTest::mouseClick(ok, Qt::LeftButton);
    QTRY_VERIFY(!m_window->inspector()->findChild<interplay::HullPointsDialog*>());
    QCOMPARE(document->body(body).body.shape.hull->sourcePoints()[0].x, 3.5f);
    QCOMPARE(document->undoStack()->count(), entries + 1);
    document->undoStack()->undo();
    QCOMPARE(document->body(body).body.shape.hull->sourcePoints(), before);
}

void TestHullPoints::dialogImportsAFileOfPoints() {
    openHullBody();
    interplay::SceneDocument* document = m_window->document();
    const int body = document->selectedBodies().first();
    const std::vector<simcore::Vec3> before = document->body(body).body.shape.hull->sourcePoints();

    interplay::HullPointsDialog* dialog = openDialog();
    QVERIFY(dialog);
    auto* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    // A flat file is read but gives no hull: OK stays off and the status says why.
    const QString flat = m_dir.filePath("flat.xyz");
    {
        QFile file(flat);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
    }
    QVERIFY(dialog->importFile(flat));
    QVERIFY(!ok->isEnabled());
    QVERIFY2(dialog->findChild<QLabel*>("hullStatus")->text().contains("no hull"),
             qPrintable(dialog->findChild<QLabel*>("hullStatus")->text()));
    // A broken file changes nothing and says which line.
    const QString broken = m_dir.filePath("broken.xyz");
    {
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0 0 0\n1 0\n");
    }
    QVERIFY(!dialog->importFile(broken));
    QCOMPARE(dialog->points().size(), std::size_t(4));
    QVERIFY2(dialog->findChild<QLabel*>("hullStatus")->text().contains("broken.xyz: line 2"),
             qPrintable(dialog->findChild<QLabel*>("hullStatus")->text()));
    // An OBJ cube's eight corners.
    const QString cube = m_dir.filePath("cube.obj");
    {
        QFile file(cube);
        QVERIFY(file.open(QIODevice::WriteOnly));
        for (int i = 0; i < 8; ++i)
            file.write(QStringLiteral("v %1 %2 %3\n").arg(i & 1 ? 0.4 : -0.4).arg(i & 2 ? 0.4 : -0.4).arg(i & 4 ? 0.4 : -0.4).toUtf8());
        file.write("f 1 2 3\n");
    }
    QVERIFY(dialog->importFile(cube));
    QVERIFY(ok->isEnabled());
    QTest::mouseClick(ok, Qt::LeftButton);
    QTRY_VERIFY(!m_window->inspector()->findChild<interplay::HullPointsDialog*>());
    const auto& hull = *document->body(body).body.shape.hull;
    QCOMPARE(hull.sourcePoints().size(), std::size_t(8));
    QCOMPARE(hull.vertices().size(), std::size_t(8));
    QCOMPARE(hull.faces().size(), std::size_t(6));  // coplanar triangles merged into squares
    document->undoStack()->undo();
    QCOMPARE(document->body(body).body.shape.hull->sourcePoints(), before);
}

QTEST_MAIN(TestHullPoints)
#include "test_hull_points.moc"
