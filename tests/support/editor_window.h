#pragma once
// The editor suites' window: shown at one size and active, so that key events reach it, and
// closed without the unsaved-changes prompt.

#include "app/document/scene_document.h"
#include "app/main_window.h"

#include <QScreen>
#include <QTest>
#include <QUndoStack>

#include <memory>

namespace test_support {

// False if the window was never exposed or never became active.
[[nodiscard]] inline bool showActive(interplay::MainWindow& window) {
    window.resize(1400, 900);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return false;
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

inline void closeWithoutPrompt(std::unique_ptr<interplay::MainWindow>& window) {
    if (window) {
        window->document()->undoStack()->setClean();
        window->close();
    }
    window.reset();
}

// Saves what the screen shows over the window as the PNG file `path`, dialogs in front of it
// included: how the README's screenshots are made.
inline void saveScreenshot(const QWidget& window, const QString& path) {
    QTest::qWait(200);  // the window repaints what the last event changed
    const QRect frame = window.frameGeometry();
    QVERIFY2(window.screen()->grabWindow(0, frame.x(), frame.y(), frame.width(), frame.height()).save(path),
             qPrintable(path));
}

// saveScreenshot where the environment variable `variable` names the file.
inline void saveScreenshotIfAsked(const QWidget& window, const char* variable) {
    if (const QString path = qEnvironmentVariable(variable); !path.isEmpty()) saveScreenshot(window, path);
}

}  // namespace test_support
