#pragma once
// The editor suites' window: shown at one size and active, so that key events reach it, and
// closed without the unsaved-changes prompt.

#include "app/document/scene_document.h"
#include "app/main_window.h"

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

}  // namespace test_support
