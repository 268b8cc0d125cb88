#pragma once
// Help → Keyboard and Mouse and Help → About Interplay. The controls list here is the one source of
// the editor's controls: the dialog shows it and README.md's controls table repeats it
// (test_editor_help checks every row appears there).

#include <QDialog>

#include <span>

namespace interplay {

struct EditorControl {
    const char* input;  // untranslated; shown through QCoreApplication::translate("EditorControls", ...)
    const char* does;
};

std::span<const EditorControl> editorControls();

// A non-modal window listing editorControls(); Escape or Close closes it.
class HelpDialog : public QDialog {
    Q_OBJECT

public:
    explicit HelpDialog(QWidget* parent = nullptr);
};

// Name, version, Qt version and the engine's description, in a QMessageBox::about.
void showAboutInterplay(QWidget* parent);

}  // namespace interplay
