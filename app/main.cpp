// interplay [SCENE] [--screenshot FILE.png | --window-screenshot FILE.png] [--frames N]
//           [--select NAME]... [--debug-draw aabbs,contacts,normals] [--show-settings]
// Opens SCENE (or the built-in default scene) in the editor. With --screenshot it simulates N
// frames (N fixed steps: no wall clock involved), saves what the viewport shows and exits, so
// the real rendering can be checked headlessly; --window-screenshot saves the whole editor with
// its docks instead. In both modes --select selects the named bodies or joints first (outlined, shown in the Inspector),
// --debug-draw turns overlays on, --show-settings brings the Simulation panel to the front.

#include "app/document/document_manager.h"
#include "app/document/scene_document.h"
#include "app/main_window.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/debug_draw_options.h"
#include "app/viewport/viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDeadlineTimer>
#include <QDockWidget>
#include <QImage>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QWindow>

#include <cstdio>

namespace {

// Exit codes, as for interplay-run where they overlap.
constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;       // the screenshot could not be rendered or written
constexpr int kExitBadArguments = 2;
constexpr int kExitBadScene = 3;

void printError(const QString& message) {
    std::fprintf(stderr, "interplay: %s\n", qPrintable(message));
}

}  // namespace

int main(int argc, char* argv[]) {
    // Before any window exists (mandatory on some platforms for a core profile).
    QSurfaceFormat::setDefaultFormat(interplay::Viewport::requiredSurfaceFormat());

    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Interplay"));
    QApplication::setOrganizationName(QStringLiteral("Interplay"));
    QApplication::setApplicationVersion(QStringLiteral("0.1.0"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Interplay: a scene editor for 3D rigid-body physics."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("scene"),
                                 QStringLiteral("Scene file to open (v1 or thesis format). Default: the built-in scene."),
                                 QStringLiteral("[SCENE]"));
    const QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"), QStringLiteral("Simulate, save the viewport to <file> (PNG) and exit."),
        QStringLiteral("file"));
    const QCommandLineOption framesOption(QStringLiteral("frames"),
                                          QStringLiteral("Time steps to simulate before the screenshot (default 60)."),
                                          QStringLiteral("n"), QStringLiteral("60"));
    const QCommandLineOption windowScreenshotOption(
        QStringLiteral("window-screenshot"),
        QStringLiteral("Like --screenshot, but save the whole editor window with its panels."), QStringLiteral("file"));
    const QCommandLineOption selectOption(QStringLiteral("select"),
                                          QStringLiteral("Select the body or joint named <name> (repeatable)."),
                                          QStringLiteral("name"));
    parser.addOption(screenshotOption);
    parser.addOption(windowScreenshotOption);
    parser.addOption(framesOption);
    const QCommandLineOption debugDrawOption(QStringLiteral("debug-draw"),
                                             QStringLiteral("Overlays to draw: any of aabbs, contacts, normals."),
                                             QStringLiteral("list"));
    const QCommandLineOption showSettingsOption(QStringLiteral("show-settings"),
                                                QStringLiteral("Bring the Simulation settings panel to the front."));
    parser.addOption(selectOption);
    parser.addOption(debugDrawOption);
    parser.addOption(showSettingsOption);
    parser.process(app);  // exits on --help, --version and unknown options

    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1) {
        printError(QStringLiteral("expected at most one scene file, got %1").arg(positional.size()));
        return kExitBadArguments;
    }
    bool framesOk = false;
    const int frames = parser.value(framesOption).toInt(&framesOk);
    if (!framesOk || frames < 0) {
        printError(QStringLiteral("--frames needs a whole number >= 0, got \"%1\"").arg(parser.value(framesOption)));
        return kExitBadArguments;
    }
    const bool windowShot = parser.isSet(windowScreenshotOption);
    const bool screenshotMode = parser.isSet(screenshotOption) || windowShot;

    interplay::MainWindow window;
    // A recovered scene wins over the command line: it holds work the user has not saved.
    if (!screenshotMode && window.documentManager()->offerRecovery()) {
        window.show();
        return app.exec();
    }
    if (positional.isEmpty()) {
        window.openDefaultScene();
    } else {
        QString error;
        if (!window.documentManager()->openFile(positional.first(), &error)) {
            if (screenshotMode) {
                printError(error);
                return kExitBadScene;
            }
            QMessageBox box(QMessageBox::Warning, QStringLiteral("Interplay"),
                            QStringLiteral("The scene \"%1\" could not be opened; showing the default scene.")
                                .arg(positional.first()),
                            QMessageBox::Ok);
            box.setInformativeText(error);
            box.exec();
            window.openDefaultScene();
        }
    }

    // View options from the command line apply to the window and to screenshots alike.
    QList<int> bodies, joints;
    for (const QString& name : parser.values(selectOption)) {
        const qsizetype before = bodies.size() + joints.size();
        for (int i = 0; i < window.document()->bodyCount(); ++i) {
            if (window.document()->bodyName(i) == name) bodies << i;
        }
        for (int i = 0; i < window.document()->jointCount(); ++i) {
            if (window.document()->jointName(i) == name) joints << i;
        }
        if (bodies.size() + joints.size() == before) {
            printError(QStringLiteral("--select: no body or joint is named \"%1\"").arg(name));
        }
    }
    window.document()->setSelection(bodies, joints);
    const QStringList overlays = parser.value(debugDrawOption).split(u',', Qt::SkipEmptyParts);
    for (const QString& overlay : overlays) {
        const char* property = overlay == QLatin1String("aabbs")      ? "aabbs"
                               : overlay == QLatin1String("contacts") ? "contactPoints"
                               : overlay == QLatin1String("normals")  ? "contactNormals"
                                                                      : nullptr;
        if (!property) {
            printError(QStringLiteral("--debug-draw takes aabbs, contacts and normals, not \"%1\"").arg(overlay));
            return kExitBadArguments;
        }
        window.debugDrawOptions()->setProperty(property, true);
    }
    if (parser.isSet(showSettingsOption)) window.findChild<QDockWidget*>(QStringLiteral("settingsDock"))->raise();

    if (!screenshotMode) {
        window.show();
        return app.exec();
    }

    // Screenshot: a fixed window size and layout (not the user's saved one) and a fixed number of
    // steps make the image reproducible.
    if (windowShot) {
        window.resize(1600, 1000);
        window.arrangeDefaultLayout();
    } else {
        for (QDockWidget* dock : window.findChildren<QDockWidget*>()) dock->hide();
        window.resize(1280, 800);
    }
    window.show();
    // Waiting only decides when to render, never what: the simulation does not run on a timer here.
    const QDeadlineTimer deadline(10000);
    while (!(window.windowHandle() && window.windowHandle()->isExposed()) && !deadline.hasExpired()) {
        QApplication::processEvents(QEventLoop::AllEvents, 50);
    }
    QApplication::processEvents();

    interplay::Viewport* viewport = window.viewport();
    // A first frame aims the camera at the scene as authored, before it moves.
    viewport->grabViewport();
    window.simulation()->stepFrames(frames);
    QApplication::processEvents();  // let the panels show the state after the steps
    const QImage image = windowShot ? window.grab().toImage() : viewport->grabViewport();
    if (image.isNull()) {
        printError(QStringLiteral("the viewport could not be rendered (no OpenGL context?)"));
        return kExitFailed;
    }
    const QString path = parser.value(windowShot ? windowScreenshotOption : screenshotOption);
    if (!image.save(path, "PNG")) {
        printError(QStringLiteral("could not write the screenshot to \"%1\"").arg(path));
        return kExitFailed;
    }
    return kExitOk;
}
