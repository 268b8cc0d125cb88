// interplay [SCENE] [--screenshot FILE.png] [--frames N]
// Opens SCENE (or the built-in default scene) in the editor. With --screenshot it simulates N
// frames (N fixed steps: no wall clock involved), saves what the viewport shows and exits, so
// the real rendering can be checked headlessly.

#include "app/main_window.h"
#include "app/simulation/simulation_controller.h"
#include "app/viewport/viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDeadlineTimer>
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
    parser.addOption(screenshotOption);
    parser.addOption(framesOption);
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
    const bool screenshotMode = parser.isSet(screenshotOption);

    interplay::MainWindow window;
    if (positional.isEmpty()) {
        window.openDefaultScene();
    } else {
        QString error;
        if (!window.openFile(positional.first(), &error)) {
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

    if (!screenshotMode) {
        window.show();
        return app.exec();
    }

    // Screenshot: a fixed window size and a fixed number of steps make the image reproducible.
    window.resize(1280, 800);
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
    const QImage image = viewport->grabViewport();
    if (image.isNull()) {
        printError(QStringLiteral("the viewport could not be rendered (no OpenGL context?)"));
        return kExitFailed;
    }
    const QString path = parser.value(screenshotOption);
    if (!image.save(path, "PNG")) {
        printError(QStringLiteral("could not write the screenshot to \"%1\"").arg(path));
        return kExitFailed;
    }
    return kExitOk;
}
