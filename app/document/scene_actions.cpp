#include "app/document/scene_actions.h"

#include "app/document/body_templates.h"
#include "app/document/scene_clipboard.h"
#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QKeySequence>
#include <QMimeData>
#include <QUndoStack>

#include <algorithm>
#include <optional>

namespace interplay {
namespace {

// The Add actions' object names, by ShapeType.
constexpr const char* kAddBodyNames[] = {"addSphere", "addBox", "addCapsule", "addCylinder", "addHull"};
static_assert(std::size(kAddBodyNames) == simcore::kShapeTypeCount);

// The Add Joint actions by object name, in menu order.
struct JointAction {
    simcore::JointType type;
    const char* objectName;
};
constexpr JointAction kJointActions[] = {
    {simcore::JointType::Ball, "addBallJoint"},         {simcore::JointType::Hinge, "addHingeJoint"},
    {simcore::JointType::Slider, "addSliderJoint"},     {simcore::JointType::Fixed, "addFixedJoint"},
    {simcore::JointType::Distance, "addDistanceJoint"},
};

}  // namespace

QAction* createAction(QObject* owner, const QString& objectName, const QString& text, const QKeySequence& shortcut,
                      const QString& statusTip) {
    auto* action = new QAction(text, owner);
    action->setObjectName(objectName);
    action->setShortcut(shortcut);
    action->setStatusTip(statusTip);
    return action;
}

SceneActions::SceneActions(SceneDocument* document, QObject* parent)
    : QObject(parent),
      m_document(document),
      m_placement([](float bodyHalfHeight) { return simcore::Vec3(0.0f, bodyHalfHeight, 0.0f); }) {
    for (int type = 0; type < simcore::kShapeTypeCount; ++type) {
        const auto shape = static_cast<simcore::ShapeType>(type);
        QAction* a =
            createAction(this, QLatin1String(kAddBodyNames[type]), tr("Add %1").arg(shapeDisplayName(shape)), {},
                         tr("Add a %1 above the point the camera looks at").arg(shapeDisplayName(shape).toLower()));
        a->setIconText(shapeDisplayName(shape));  // on a toolbar, after its "Add:" label
        connect(a, &QAction::triggered, this, [this, shape] { addBody(shape); });
        m_addBody << a;
    }
    // One action per joint type; updateJointActions enables them and says why not.
    for (const JointAction& joint : kJointActions) {
        QAction* a = createAction(this, QLatin1String(joint.objectName),
                                  tr("Add %1 Joint").arg(jointTypeDisplayName(joint.type)), {}, {});
        connect(a, &QAction::triggered, this, [this, type = joint.type] { addJoint(type); });
        m_addJoint << a;
    }
    m_duplicate = createAction(this, QStringLiteral("duplicate"), tr("Dup&licate"), Qt::CTRL | Qt::Key_D,
                               tr("Copy the selected bodies beside them"));
    connect(m_duplicate, &QAction::triggered, this, &SceneActions::duplicateSelection);
    m_delete = createAction(this, QStringLiteral("delete"), tr("&Delete"), QKeySequence::Delete,
                            tr("Delete the selected bodies (with their joints) and joints"));
    connect(m_delete, &QAction::triggered, this, &SceneActions::deleteSelection);
    m_selectAll = createAction(this, QStringLiteral("selectAll"), tr("Select &All"), QKeySequence::SelectAll,
                               tr("Select every body"));
    connect(m_selectAll, &QAction::triggered, this, &SceneActions::selectAll);
    m_selectNone = createAction(this, QStringLiteral("selectNone"), tr("Select &None"), Qt::CTRL | Qt::SHIFT | Qt::Key_A,
                                tr("Clear the selection"));
    connect(m_selectNone, &QAction::triggered, this, &SceneActions::selectNone);
    m_invertSelection = createAction(this, QStringLiteral("invertSelection"), tr("&Invert Selection"),
                                     Qt::CTRL | Qt::Key_I, tr("Select the bodies that are not selected, and only those"));
    connect(m_invertSelection, &QAction::triggered, this, &SceneActions::invertSelection);
    m_copy = createAction(this, QStringLiteral("copy"), tr("&Copy"), QKeySequence::Copy,
                          tr("Copy the selected bodies and the joints among them to the clipboard"));
    connect(m_copy, &QAction::triggered, this, &SceneActions::copySelection);
    m_cut = createAction(this, QStringLiteral("cut"), tr("Cu&t"), QKeySequence::Cut,
                         tr("Copy the selected bodies to the clipboard and delete them with their joints"));
    connect(m_cut, &QAction::triggered, this, &SceneActions::cutSelection);
    m_paste = createAction(this, QStringLiteral("paste"), tr("&Paste"), QKeySequence::Paste,
                           tr("Add the clipboard's bodies and joints at the cursor, or beside where they were copied"));
    connect(m_paste, &QAction::triggered, this, &SceneActions::paste);

    connect(m_document, &SceneDocument::selectionChanged, this, &SceneActions::updateJointActions);
    connect(m_document, &SceneDocument::bodyChanged, this, &SceneActions::updateJointActions);
    updateJointActions();
}

QAction* SceneActions::addBodyAction(simcore::ShapeType type) const { return m_addBody[static_cast<int>(type)]; }

void SceneActions::addBody(simcore::ShapeType type) {
    const simcore::Aabb bounds = simcore::localBounds(templateShape(type));
    const simcore::Vec3 position = m_placement(0.5f * (bounds.max.y - bounds.min.y));
    simcore::SceneBody body = templateBody(type, m_document->uniqueBodyName(shapeDisplayName(type)), position);
    const QString name = QString::fromStdString(body.body.name);
    m_document->undoStack()->push(
        new AddBodies(m_document, tr("Add %1").arg(name), {m_document->bodyCount()}, {std::move(body)}));
}

void SceneActions::addJoint(simcore::JointType type) {
    const QList<int>& bodies = m_document->selectedBodies();
    if (bodies.isEmpty() || bodies.size() > 2) return;
    const std::optional<std::size_t> bodyB =
        bodies.size() == 2 ? std::optional<std::size_t>(static_cast<std::size_t>(bodies[1])) : std::nullopt;
    simcore::SceneJoint joint = templateJoint(type, m_document->uniqueJointName(tr("Joint")),
                                              m_document->scene().bodies, static_cast<std::size_t>(bodies[0]), bodyB);
    // Two bodies at one point leave a distance joint no length, for instance.
    if (const QString problem = m_document->jointProblem(joint); !problem.isEmpty()) {
        emit rejected(tr("No joint added: %1").arg(problem));
        return;
    }
    m_document->undoStack()->push(new AddJoint(m_document, tr("Add %1 Joint").arg(jointTypeDisplayName(type)),
                                               m_document->jointCount(), std::move(joint)));
}

void SceneActions::updateJointActions() {
    const QList<int>& bodies = m_document->selectedBodies();
    const bool anyDynamic = std::any_of(bodies.begin(), bodies.end(), [this](int i) {
        return m_document->body(i).body.motion == simcore::MotionType::Dynamic;
    });
    QString why;  // what the selection lacks, or empty when it fits
    if (bodies.isEmpty() || bodies.size() > 2) {
        why = tr("Select two bodies to join them, or one body to hold it to the world.");
    } else if (!anyDynamic) {
        why = tr("A joint needs a dynamic body to act on; the selected bodies do not move.");
    }
    for (std::size_t i = 0; i < std::size(kJointActions); ++i) {
        QAction* a = m_addJoint[static_cast<int>(i)];
        const QString type = jointTypeDisplayName(kJointActions[i].type).toLower();
        QString tip = why;
        if (why.isEmpty() && bodies.size() == 2) {
            tip = tr("Join %1 and %2 with a %3 joint")
                      .arg(m_document->bodyName(bodies[0]), m_document->bodyName(bodies[1]), type);
        } else if (why.isEmpty()) {
            tip = tr("Hold %1 to the world with a %2 joint").arg(m_document->bodyName(bodies[0]), type);
        }
        a->setEnabled(why.isEmpty());
        a->setStatusTip(tip);
        a->setToolTip(tip);
    }
}

void SceneActions::duplicateSelection() {
    const QList<int> selection = m_document->selectedBodies();
    if (selection.isEmpty()) return;
    simcore::Scene fragment = sceneFragment(m_document->scene(), selection);
    giveUniqueNames(fragment, *m_document);
    translateFragment(fragment, offsetBeside(fragment));
    m_document->undoStack()->push(new AddFragment(
        m_document, tr("Duplicate %1").arg(bodiesLabel(*m_document, selection)), std::move(fragment)));
}

void SceneActions::copySelection() {
    const QList<int>& selection = m_document->selectedBodies();
    if (selection.isEmpty()) return;
    QGuiApplication::clipboard()->setMimeData(fragmentMimeData(sceneFragment(m_document->scene(), selection)));
}

void SceneActions::cutSelection() {
    const QList<int> selection = m_document->selectedBodies();
    if (selection.isEmpty()) return;
    copySelection();
    auto* remove = new RemoveBodies(m_document, selection);
    remove->setText(tr("Cut %1").arg(bodiesLabel(*m_document, selection)));
    m_document->undoStack()->push(remove);
}

void SceneActions::paste() {
    const QMimeData* data = QGuiApplication::clipboard()->mimeData();
    ParsedFragment parsed = parseFragment(data ? fragmentTextOf(*data) : QByteArray());
    if (!parsed.fragment) {
        emit rejected(tr("Nothing pasted: %1").arg(parsed.error));
        return;
    }
    simcore::Scene& fragment = *parsed.fragment;
    giveUniqueNames(fragment, *m_document);
    const std::optional<simcore::Vec3> point = m_pastePoint ? m_pastePoint() : std::nullopt;
    translateFragment(fragment, point ? offsetOnto(fragment, *point) : offsetBeside(fragment));
    const QString what = fragment.bodies.size() == 1 ? QString::fromStdString(fragment.bodies.front().body.name)
                                                     : tr("%n Bodies", nullptr, int(fragment.bodies.size()));
    m_document->undoStack()->push(new AddFragment(m_document, tr("Paste %1").arg(what), std::move(fragment)));
}

void SceneActions::deleteSelection() {
    if (m_document->selectedBodies().isEmpty() && m_document->selectedJoints().isEmpty()) return;
    m_document->undoStack()->push(
        new RemoveBodies(m_document, m_document->selectedBodies(), m_document->selectedJoints()));
}

void SceneActions::selectAll() {
    QList<int> all;
    for (int i = 0; i < m_document->bodyCount(); ++i) all << i;
    m_document->setSelectedBodies(all);
}

void SceneActions::selectNone() {
    m_document->setSelection({}, {});
}

void SceneActions::invertSelection() {
    QList<int> unselected;
    for (int i = 0; i < m_document->bodyCount(); ++i) {
        if (!m_document->selectedBodies().contains(i)) unselected << i;
    }
    m_document->setSelection(unselected, m_document->selectedJoints());
}

}  // namespace interplay
