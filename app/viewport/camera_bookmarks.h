#pragma once
// Camera bookmarks: named views kept in the scene file's editor state (simcore::CameraBookmark),
// in the View → Bookmarks menu. Keys as in Unreal's editor, whose bookmarks these are modelled on:
// 1 to 9 show bookmark 1 to 9, Ctrl+1 to Ctrl+9 store the view in it (a new bookmark where there is
// none yet); Ctrl+B adds one under a name asked for. Adding, storing, renaming and deleting are
// document edits (one undo entry each, the document modified); showing a bookmark only moves the
// camera.

#include "app/viewport/camera.h"

#include "simcore/io/scene.h"

#include <QList>
#include <QObject>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QAction;
class QMenu;
class QWidget;

namespace interplay {

class SceneDocument;
class Viewport;

// The view `camera` shows, as a bookmark called `name`; and a camera aimed as `bookmark` says,
// with the rest of `camera` (its field of view) kept.
simcore::CameraBookmark bookmarkOf(const Camera& camera, const QString& name);
Camera aimedAt(Camera camera, const simcore::CameraBookmark& bookmark);

class CameraBookmarks : public QObject {
    Q_OBJECT

public:
    static constexpr int kNumberedBookmarks = 9;  // the ones with keys

    // Asks for a bookmark's name, offering `name`; nothing when cancelled. A QInputDialog by
    // default; tests replace it.
    using NamePrompt = std::function<std::optional<QString>(const QString& title, const QString& name)>;

    // The menu's actions act in `window` (their shortcuts, the dialogs' parent).
    CameraBookmarks(SceneDocument* document, Viewport* viewport, QWidget* window);

    QMenu* menu() const { return m_menu; }
    void setNamePrompt(NamePrompt prompt) { m_namePrompt = std::move(prompt); }

    const std::vector<simcore::CameraBookmark>& bookmarks() const;
    // Each an undoable edit; false (with `rejected`) for a bad name or index, or a full list.
    bool add(const QString& name);
    bool store(int index);  // the view into bookmark `index`, or a new one when index == count
    bool rename(int index, const QString& name);
    bool remove(int index);
    void show(int index);

signals:
    void rejected(const QString& message);

private:
    void addAsked();
    void renameAsked(int index);
    void rebuildMenu();
    void push(const QString& text, std::vector<simcore::CameraBookmark> after);
    bool isIndex(int index) const { return index >= 0 && index < static_cast<int>(bookmarks().size()); }
    // "Bookmark 3": the first such name no bookmark has.
    QString freeName() const;

    SceneDocument* m_document;
    Viewport* m_viewport;
    QWidget* m_window;
    QMenu* m_menu;
    QMenu* m_renameMenu;
    QMenu* m_deleteMenu;
    QList<QAction*> m_storeActions;  // Ctrl+1..9, fixed; their texts follow the bookmarks
    QList<QAction*> m_showActions;   // one per bookmark, rebuilt
    NamePrompt m_namePrompt;
};

}  // namespace interplay
