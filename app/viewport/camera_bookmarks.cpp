#include "app/viewport/camera_bookmarks.h"

#include "app/document/scene_actions.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "app/viewport/viewport.h"

#include <QAction>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenu>
#include <QUndoStack>
#include <QWidget>

#include <algorithm>

namespace interplay {
namespace {

QString quoted(const simcore::CameraBookmark& bookmark) {
    return QStringLiteral("\u201c%1\u201d").arg(QString::fromStdString(bookmark.name));
}

}  // namespace

simcore::CameraBookmark bookmarkOf(const Camera& camera, const QString& name) {
    simcore::CameraBookmark bookmark;
    bookmark.name = name.toStdString();
    bookmark.target = camera.target();
    bookmark.yawDegrees = camera.yawDegrees();
    bookmark.pitchDegrees = camera.pitchDegrees();
    bookmark.distance = camera.distance();
    bookmark.orthographic = camera.isOrthographic();
    return bookmark;
}

Camera aimedAt(Camera camera, const simcore::CameraBookmark& bookmark) {
    camera.setTarget(bookmark.target);
    camera.setYawDegrees(bookmark.yawDegrees);
    camera.setPitchDegrees(bookmark.pitchDegrees);
    camera.setDistance(bookmark.distance);
    camera.setOrthographic(bookmark.orthographic);
    return camera;
}

CameraBookmarks::CameraBookmarks(SceneDocument* document, Viewport* viewport, QWidget* window)
    : QObject(window), m_document(document), m_viewport(viewport), m_window(window),
      m_menu(new QMenu(tr("Boo&kmarks"), window)), m_renameMenu(new QMenu(tr("&Rename Bookmark"), m_menu)),
      m_deleteMenu(new QMenu(tr("&Delete Bookmark"), m_menu)) {
    m_namePrompt = [this](const QString& title, const QString& name) -> std::optional<QString> {
        bool ok = false;
        const QString text = QInputDialog::getText(m_window, title, tr("Name:"), QLineEdit::Normal, name, &ok);
        return ok ? std::optional(text) : std::nullopt;
    };
    m_menu->setObjectName(QStringLiteral("bookmarksMenu"));
    m_renameMenu->setObjectName(QStringLiteral("renameBookmarkMenu"));
    m_deleteMenu->setObjectName(QStringLiteral("deleteBookmarkMenu"));
    QAction* add = createAction(this, QStringLiteral("addBookmark"), tr("&Add Bookmark…"), Qt::CTRL | Qt::Key_B,
                                tr("Keep the current view under a name, saved with the scene (Ctrl+B)"));
    connect(add, &QAction::triggered, this, &CameraBookmarks::addAsked);
    QMenu* storeMenu = new QMenu(tr("&Store View"), m_menu);
    storeMenu->setObjectName(QStringLiteral("storeBookmarkMenu"));
    for (int i = 0; i < kNumberedBookmarks; ++i) {
        QAction* store = createAction(this, QStringLiteral("storeBookmark%1").arg(i + 1), QString(),
                                      Qt::CTRL | Qt::Key(Qt::Key_1 + i), QString());
        connect(store, &QAction::triggered, this, [this, i] { this->store(i); });
        storeMenu->addAction(store);
        m_storeActions << store;
    }
    m_menu->addAction(add);
    m_menu->addMenu(storeMenu);
    m_menu->addMenu(m_renameMenu);
    m_menu->addMenu(m_deleteMenu);
    m_menu->addSeparator();
    connect(m_document, &SceneDocument::cameraBookmarksChanged, this, &CameraBookmarks::rebuildMenu);
    connect(m_document, &SceneDocument::sceneReplaced, this, &CameraBookmarks::rebuildMenu);
    rebuildMenu();
}

const std::vector<simcore::CameraBookmark>& CameraBookmarks::bookmarks() const {
    return m_document->scene().editor.cameraBookmarks;
}

bool CameraBookmarks::add(const QString& name) {
    if (bookmarks().size() >= simcore::kMaxCameraBookmarks) {
        emit rejected(tr("A scene keeps at most %1 bookmarks.").arg(simcore::kMaxCameraBookmarks));
        return false;
    }
    const simcore::CameraBookmark bookmark = bookmarkOf(m_viewport->camera(), name.trimmed());
    if (const auto problem = simcore::cameraBookmarkNameProblem(bookmark.name)) {
        emit rejected(tr("Bookmark not added: %1.").arg(QString::fromStdString(*problem)));
        return false;
    }
    std::vector<simcore::CameraBookmark> after = bookmarks();
    after.push_back(bookmark);
    push(tr("Add Bookmark %1").arg(quoted(bookmark)), std::move(after));
    return true;
}

bool CameraBookmarks::store(int index) {
    if (index == static_cast<int>(bookmarks().size())) return add(freeName());
    if (!isIndex(index)) return false;
    std::vector<simcore::CameraBookmark> after = bookmarks();
    auto& bookmark = after[static_cast<std::size_t>(index)];
    bookmark = bookmarkOf(m_viewport->camera(), QString::fromStdString(bookmark.name));
    const QString text = tr("Store View in Bookmark %1").arg(quoted(bookmark));
    push(text, std::move(after));
    return true;
}

bool CameraBookmarks::rename(int index, const QString& name) {
    if (!isIndex(index)) return false;
    const std::string newName = name.trimmed().toStdString();
    if (const auto problem = simcore::cameraBookmarkNameProblem(newName)) {
        emit rejected(tr("Bookmark not renamed: %1.").arg(QString::fromStdString(*problem)));
        return false;
    }
    std::vector<simcore::CameraBookmark> after = bookmarks();
    auto& bookmark = after[static_cast<std::size_t>(index)];
    const QString before = quoted(bookmark);
    bookmark.name = newName;
    const QString text = tr("Rename Bookmark %1 to %2").arg(before, quoted(bookmark));
    push(text, std::move(after));
    return true;
}

bool CameraBookmarks::remove(int index) {
    if (!isIndex(index)) return false;
    std::vector<simcore::CameraBookmark> after = bookmarks();
    const QString text = tr("Delete Bookmark %1").arg(quoted(after[static_cast<std::size_t>(index)]));
    after.erase(after.begin() + index);
    push(text, std::move(after));
    return true;
}

void CameraBookmarks::show(int index) {
    if (!isIndex(index)) return;
    m_viewport->setCamera(aimedAt(m_viewport->camera(), bookmarks()[static_cast<std::size_t>(index)]));
}

void CameraBookmarks::addAsked() {
    if (const auto name = m_namePrompt(tr("Add Bookmark"), freeName())) add(*name);
}

void CameraBookmarks::renameAsked(int index) {
    if (!isIndex(index)) return;
    if (const auto name = m_namePrompt(tr("Rename Bookmark"), QString::fromStdString(bookmarks()[std::size_t(index)].name)))
        rename(index, *name);
}

void CameraBookmarks::push(const QString& text, std::vector<simcore::CameraBookmark> after) {
    m_document->undoStack()->push(new ChangeCameraBookmarks(m_document, text, std::move(after)));
}

QString CameraBookmarks::freeName() const {
    for (int n = static_cast<int>(bookmarks().size()) + 1;; ++n) {
        const QString name = tr("Bookmark %1").arg(n);
        const std::string text = name.toStdString();
        if (std::none_of(bookmarks().begin(), bookmarks().end(), [&](const auto& b) { return b.name == text; }))
            return name;
    }
}

void CameraBookmarks::rebuildMenu() {
    // Deleted later, as one of them may be the action whose edit called this; unnamed now, so that
    // nothing finds them meanwhile.
    const auto retire = [](QMenu* menu, const QList<QAction*>& actions) {
        for (QAction* action : actions) {
            menu->removeAction(action);
            action->setObjectName(QString());
            action->deleteLater();
        }
    };
    retire(m_menu, m_showActions);
    retire(m_renameMenu, m_renameMenu->actions());
    retire(m_deleteMenu, m_deleteMenu->actions());
    m_showActions.clear();
    const auto& list = bookmarks();
    for (int i = 0; i < static_cast<int>(list.size()); ++i) {
        const QString name = QString::fromStdString(list[std::size_t(i)].name);
        // &1..&9 as in the recent-files menu; the first nine also have their digit as a key.
        const QString label = i < kNumberedBookmarks ? tr("&%1 %2").arg(i + 1).arg(name) : name;
        QAction* show = createAction(this, QStringLiteral("showBookmark%1").arg(i + 1), label,
                                     i < kNumberedBookmarks ? QKeySequence(Qt::Key(Qt::Key_1 + i)) : QKeySequence(),
                                     tr("Show the view kept as %1").arg(quoted(list[std::size_t(i)])));
        connect(show, &QAction::triggered, this, [this, i] { this->show(i); });
        m_menu->addAction(show);
        m_showActions << show;
        auto* rename = new QAction(label, this);
        connect(rename, &QAction::triggered, this, [this, i] { renameAsked(i); });
        m_renameMenu->addAction(rename);
        auto* remove = new QAction(label, this);
        connect(remove, &QAction::triggered, this, [this, i] { this->remove(i); });
        m_deleteMenu->addAction(remove);
    }
    for (int i = 0; i < kNumberedBookmarks; ++i) {
        m_storeActions[i]->setText(i < static_cast<int>(list.size())
                                       ? tr("&%1 %2").arg(i + 1).arg(QString::fromStdString(list[std::size_t(i)].name))
                                       : tr("&%1 (new bookmark)").arg(i + 1));
        // Past the first free number the key would store in a bookmark of another number.
        m_storeActions[i]->setEnabled(i <= static_cast<int>(list.size()));
    }
    m_renameMenu->setEnabled(!list.empty());
    m_deleteMenu->setEnabled(!list.empty());
}

}  // namespace interplay
