#include "app/help_dialog.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMessageBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace interplay {
namespace {

const EditorControl kEditorControls[] = {
    {QT_TRANSLATE_NOOP("EditorControls", "click / Ctrl- or Shift-click"),
     QT_TRANSLATE_NOOP("EditorControls", "select a joint whose anchor (every joint marks it with a small cross) or distance rod is within 8 px, as joints are drawn over the bodies — unless the body under the cursor hides that point (a joint to the world is anchored at its body's centre): then the body, and a second click on it the joint — else the body under the cursor (a ray cast through simcore) / add or remove from the selection")},
    {QT_TRANSLATE_NOOP("EditorControls", "left drag on a body"),
     QT_TRANSLATE_NOOP("EditorControls", "paused: move the selection on a horizontal plane, with the anchors of the joints riding on it; playing: pull it with a spring")},
    {QT_TRANSLATE_NOOP("EditorControls", "R held + left drag on a body (or Alt + drag, where the window manager leaves Alt alone)"),
     QT_TRANSLATE_NOOP("EditorControls", "paused: turn the selection about the vertical, with its joints' anchors and axes")},
    {QT_TRANSLATE_NOOP("EditorControls", "left drag on a gizmo handle (Ctrl: snap)"),
     QT_TRANSLATE_NOOP("EditorControls", "move along an arrow or in a plane handle's plane, or turn about a ring's axis (outer ring: the view's), the whole selection about its centre, one undo entry, also while playing; Ctrl snaps to the grid and angle steps (0.1 m and 15° unless set in Edit → Preferences), or drags freely while Snap is on; Escape or right click cancels")},
    {QT_TRANSLATE_NOOP("EditorControls", "W / E / L / Y"),
     QT_TRANSLATE_NOOP("EditorControls", "move gizmo / rotate gizmo (pressed again: none) / the gizmo on the active body's axes or the world's / snap on or off; also in the View menu and the Gizmo toolbar")},
    {QT_TRANSLATE_NOOP("EditorControls", "Ctrl+, (Edit → Preferences)"),
     QT_TRANSLATE_NOOP("EditorControls", "the gizmo's grid and angle snapping steps, applied to the next drag")},
    {QT_TRANSLATE_NOOP("EditorControls", "left drag from empty space / Shift- / Ctrl-drag"),
     QT_TRANSLATE_NOOP("EditorControls", "box select: the bodies whose centres (live while playing) the rectangle holds on screen / add them / toggle them; a click on nothing still clears the selection")},
    {QT_TRANSLATE_NOOP("EditorControls", "middle drag / Shift + middle drag / wheel"),
     QT_TRANSLATE_NOOP("EditorControls", "orbit / pan / zoom (a left drag from a joint's mark, or a Ctrl- or Shift-drag from a body, orbits too)")},
    {QT_TRANSLATE_NOOP("EditorControls", "right drag + W A S D Q E"),
     QT_TRANSLATE_NOOP("EditorControls", "fly (Shift: faster)")},
    {QT_TRANSLATE_NOOP("EditorControls", "Space, ., Ctrl+R"),
     QT_TRANSLATE_NOOP("EditorControls", "play/pause (Space opens a drop-down that has the keyboard focus instead), one step, reset to the authored scene")},
    {QT_TRANSLATE_NOOP("EditorControls", ", / drag the timeline bar"),
     QT_TRANSLATE_NOOP("EditorControls", "show the recorded frame before this one / any recorded frame, paused; . then steps through the recorded frames, and Play resumes from the frame shown, dropping the frames after it")},
    {QT_TRANSLATE_NOOP("EditorControls", "hover a body"),
     QT_TRANSLATE_NOOP("EditorControls", "a tooltip with its name and simulated speed")},
    {QT_TRANSLATE_NOOP("EditorControls", "Ctrl+Z / Ctrl+Y or Ctrl+Shift+Z"),
     QT_TRANSLATE_NOOP("EditorControls", "undo / redo, from anywhere, a field included once its value is committed (typing not yet committed is undone in the field first)")},
    {QT_TRANSLATE_NOOP("EditorControls", "Enter or Tab / Escape"),
     QT_TRANSLATE_NOOP("EditorControls", "in a number field: commit the typed value (so does clicking away) / drop it and show the scene's value (a field shows as many digits as fit; its tooltip has six)")},
    {QT_TRANSLATE_NOOP("EditorControls", "T"),
     QT_TRANSLATE_NOOP("EditorControls", "throw the chosen shape from the camera along the view (until Reset)")},
    {QT_TRANSLATE_NOOP("EditorControls", "F, Ctrl+D, Del"),
     QT_TRANSLATE_NOOP("EditorControls", "frame the selection, duplicate (with the joints among the bodies), delete (bodies with their joints, and selected joints; one undo entry)")},
    {QT_TRANSLATE_NOOP("EditorControls", "Ctrl+C / Ctrl+X / Ctrl+V"),
     QT_TRANSLATE_NOOP("EditorControls", "copy / cut / paste the selected bodies with the joints among them, as scene JSON on the system clipboard (another editor window pastes it too): pasted on the surface under the cursor when it is over the view, else beside the originals, renamed where a name is taken, one undo entry; text that is no scene is refused in the status bar")},
    {QT_TRANSLATE_NOOP("EditorControls", "Ctrl+A / Ctrl+Shift+A / Ctrl+I"),
     QT_TRANSLATE_NOOP("EditorControls", "select all / none / invert the selection of bodies (Edit menu; the Scene tree follows)")},
    {QT_TRANSLATE_NOOP("EditorControls", "Home (F with nothing selected)"),
     QT_TRANSLATE_NOOP("EditorControls", "frame all: every body's bounding sphere fills about 80 % of the view, as in a newly opened scene")},
    {QT_TRANSLATE_NOOP("EditorControls", "numpad 1 / 3 / 7 (Ctrl: the opposite way)"),
     QT_TRANSLATE_NOOP("EditorControls", "front / right / top view: look along -Z / -X / -Y (Y is up), keeping the target and distance; also in the View menu")},
    {QT_TRANSLATE_NOOP("EditorControls", "numpad 5"),
     QT_TRANSLATE_NOOP("EditorControls", "orthographic / perspective (View → Orthographic); clicks and drags pick along parallel rays")},
    {QT_TRANSLATE_NOOP("EditorControls", "Ctrl+B / 1 … 9 / Ctrl+1 … 9"),
     QT_TRANSLATE_NOOP("EditorControls", "camera bookmarks (View → Bookmarks, as in Unreal): add the view under a name / show bookmark 1 to 9 / store the view in it (a new one after the last); rename and delete them in the menu; saved with the scene, each change one undo entry")},
    {QT_TRANSLATE_NOOP("EditorControls", "F1"),
     QT_TRANSLATE_NOOP("EditorControls", "this list of controls (Help → Keyboard and Mouse)")},
};

}  // namespace

std::span<const EditorControl> editorControls() { return kEditorControls; }

HelpDialog::HelpDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("helpDialog"));
    setWindowTitle(tr("Keyboard and Mouse"));
    setModal(false);

    const std::span<const EditorControl> controls = editorControls();
    auto* table = new QTableWidget(int(controls.size()), 2, this);
    table->setObjectName(QStringLiteral("controlsTable"));
    table->setHorizontalHeaderLabels({tr("Input"), tr("Does")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setWordWrap(true);
    table->setFocusPolicy(Qt::NoFocus);  // a reference to read: no current cell to highlight
    for (int row = 0; row < int(controls.size()); ++row) {
        table->setItem(row, 0, new QTableWidgetItem(QCoreApplication::translate("EditorControls", controls[row].input)));
        table->setItem(row, 1, new QTableWidgetItem(QCoreApplication::translate("EditorControls", controls[row].does)));
    }
    table->setColumnWidth(0, 260);
    table->horizontalHeader()->setStretchLastSection(true);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(table);
    layout->addWidget(buttons);
    resize(900, 440);
    // Wrapped rows get their height once the description column has its final width.
    connect(table->horizontalHeader(), &QHeaderView::sectionResized, table, &QTableWidget::resizeRowsToContents);
}

void showAboutInterplay(QWidget* parent) {
    QMessageBox::about(parent, QCoreApplication::translate("HelpDialog", "About Interplay"),
                       QCoreApplication::translate("HelpDialog",
                                                   "<h3>Interplay %1</h3>"
                                                   "<p>A scene editor for 3D rigid-body physics.</p>"
                                                   "<p>Physics by simcore, Interplay's own rigid-body engine in plain "
                                                   "C++20 and GLM.</p>"
                                                   "<p>Built with Qt %2, running on Qt %3.</p>")
                           .arg(QStringLiteral(INTERPLAY_VERSION), QStringLiteral(QT_VERSION_STR), QString::fromLatin1(qVersion())));
}

}  // namespace interplay
