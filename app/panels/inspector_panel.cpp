#include "app/panels/inspector_panel.h"

#include "app/document/body_templates.h"
#include "app/document/undo_commands.h"
#include "app/panels/compound_children_model.h"
#include "app/panels/hull_points_dialog.h"
#include "app/panels/hull_points_model.h"
#include "app/panels/inspector_fields.h"
#include "app/panels/number_field.h"
#include "app/viewport/color_space.h"

#include "simcore/io/scene_io.h"
#include "simcore/settings_schema.h"
#include "simcore/shapes/compound_shape.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QScrollArea>
#include <QTableView>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <type_traits>

namespace interplay {

using inspector::PropertyOwner;
using inspector::range;
using inspector::showSharedCheck;

namespace {

constexpr double kMaxAngle = 360.0;  // degrees: Euler angles are how the Inspector shows an orientation


// The schema properties ("owner.key") each number field edits; a vector's x, y and z fields all
// edit theirs. The orientation's Euler angles edit no one file value (the file has a quaternion).
struct FieldSchemaKeys {
    const char* field;
    std::array<const char*, 3> keys;  // unused entries are null
};
constexpr FieldSchemaKeys kFieldSchemaKeys[] = {
    {"halfExtents", {"box.halfExtents"}},
    {"radius", {"sphere.radius", "capsule.radius", "cylinder.radius"}},
    {"halfHeight", {"capsule.halfHeight", "cylinder.halfHeight"}},
    {"mass", {"body.mass", "body.density"}},
    {"friction", {"body.friction"}},
    {"restitution", {"body.restitution"}},
    {"rollingResistance", {"body.rollingResistance"}},
    {"position", {"body.position"}},
    {"linearVelocity", {"body.linearVelocity"}},
    {"angularVelocity", {"body.angularVelocity"}},
    {"anchor", {"joint.anchor"}},
    {"anchorB", {"distance.anchorB"}},
    {"axis", {"hinge.axis", "slider.axis"}},
    {"hingeLower", {"hinge.limits.lower"}},
    {"hingeUpper", {"hinge.limits.upper"}},
    {"sliderLower", {"slider.limits.lower"}},
    {"sliderUpper", {"slider.limits.upper"}},
    {"hingeMotorSpeed", {"hinge.motor.speed"}},
    {"hingeMaxTorque", {"hinge.motor.maxTorque"}},
    {"sliderMotorSpeed", {"slider.motor.speed"}},
    {"sliderMaxForce", {"slider.motor.maxForce"}},
    {"minLength", {"distance.minLength"}},
    {"maxLength", {"distance.maxLength"}},
    {"springHertz", {"distance.spring.hertz"}},
    {"springDampingRatio", {"distance.spring.dampingRatio"}},
};


constexpr std::array<simcore::ShapeType, simcore::kShapeTypeCount> kShapeTypes{
    simcore::ShapeType::Box, simcore::ShapeType::Sphere, simcore::ShapeType::Capsule, simcore::ShapeType::Cylinder,
    simcore::ShapeType::ConvexHull};
constexpr std::array<simcore::MotionType, 3> kMotionTypes{simcore::MotionType::Dynamic, simcore::MotionType::Static,
                                                          simcore::MotionType::Kinematic};

bool isDynamic(const simcore::SceneBody& b) {
    return b.body.motion == simcore::MotionType::Dynamic;
}

bool hasRadius(const simcore::SceneBody& b) {
    const auto type = b.body.shape.type;
    return type == simcore::ShapeType::Sphere || type == simcore::ShapeType::Capsule || type == simcore::ShapeType::Cylinder;
}

bool hasHalfHeight(const simcore::SceneBody& b) {
    const auto type = b.body.shape.type;
    return type == simcore::ShapeType::Capsule || type == simcore::ShapeType::Cylinder;
}

// Body colours are linear RGB; the colour dialog speaks sRGB.
QColor toQColor(const simcore::Vec3& linear) {
    return QColor::fromRgbF(srgbFromLinear(linear.r), srgbFromLinear(linear.g), srgbFromLinear(linear.b));
}


bool isHull(const simcore::SceneBody& b) {
    return b.body.shape.type == simcore::ShapeType::ConvexHull;
}



// The mass a density gives (the shape's volume times it), or the density a mass gives; the total
// for several bodies.
QString massSummary(const std::vector<const simcore::SceneBody*>& dynamicBodies) {
    if (dynamicBodies.empty()) return {};
    const auto massOf = [](const simcore::SceneBody& b) {
        return double(b.body.mass ? *b.body.mass : simcore::massProperties(b.body.shape, b.body.density).mass);
    };
    if (dynamicBodies.size() > 1) {
        double total = 0.0;
        for (const simcore::SceneBody* b : dynamicBodies) total += massOf(*b);
        return InspectorPanel::tr("%1 kg in all").arg(total, 0, 'g', 4);
    }
    const simcore::SceneBody& body = *dynamicBodies.front();
    if (!body.body.mass) return InspectorPanel::tr("= %1 kg").arg(massOf(body), 0, 'g', 4);
    return InspectorPanel::tr("= %1 kg/m³").arg(massOf(body) / simcore::volume(body.body.shape), 0, 'g', 4);
}

QString motionLabel(simcore::MotionType motion) {
    switch (motion) {
    case simcore::MotionType::Dynamic: return InspectorPanel::tr("Dynamic");
    case simcore::MotionType::Static: return InspectorPanel::tr("Static");
    case simcore::MotionType::Kinematic: return InspectorPanel::tr("Kinematic");
    }
    return {};
}

}  // namespace

InspectorPanel::InspectorPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_header(new QLabel(this)), m_message(new QLabel(this)),
      m_bodyForm(new QWidget), m_jointForm(new QWidget),
      m_bodyRows(new QFormLayout(m_bodyForm),
                 [this](BodyField field, const QString& what, const auto& change, const auto& appliesTo) {
                     editBodies(field, what, change, appliesTo);
                 },
                 [this](const QString& message) { showMessage(message); }),
      m_jointRows(new QFormLayout(m_jointForm),
                  [this](JointField field, const QString& what, const auto& change, const auto& appliesTo) {
                      editJoints(field, what, change, appliesTo);
                  },
                  [this](const QString& message) { showMessage(message); }),
      m_name(new QLineEdit), m_shapeType(new QComboBox), m_hullInfo(new QLabel),
      m_editHullPoints(new QPushButton(tr("Edit Points…"))), m_compoundChildren(new CompoundChildrenModel(this)),
      m_compoundTable(new QTableView), m_removeChild(new QPushButton(tr("Remove"))), m_massResult(new QLabel),
      m_motion(new QComboBox),
      m_massMode(new QComboBox), m_color(new QPushButton), m_ccd(new QCheckBox(tr("Continuous collision (CCD)"))),
      m_jointName(new QLineEdit), m_jointType(new QLabel), m_jointBodies(new QLabel),
      m_limits(new QCheckBox(tr("Limits"))), m_motor(new QCheckBox(tr("Motor"))),
      m_lengths(new QCheckBox(tr("Length range"))), m_spring(new QCheckBox(tr("Spring"))),
      m_collideConnected(new QCheckBox(tr("The two bodies collide"))) {
    auto* outer = new QVBoxLayout(this);
    QFont bold = m_header->font();
    bold.setBold(true);
    m_header->setFont(bold);
    m_header->setWordWrap(true);
    m_header->setObjectName(QStringLiteral("inspectorHeader"));
    m_message->setWordWrap(true);
    m_message->setObjectName(QStringLiteral("inspectorMessage"));
    m_message->setStyleSheet(QStringLiteral("color: #b3261e;"));
    m_message->hide();
    outer->addWidget(m_header);
    auto* forms = new QWidget;
    auto* formsLayout = new QVBoxLayout(forms);
    formsLayout->setContentsMargins(0, 0, 0, 0);
    formsLayout->addWidget(m_bodyForm);
    formsLayout->addWidget(m_jointForm);
    formsLayout->addStretch(1);
    for (QWidget* form : {m_bodyForm, m_jointForm}) {
        auto* layout = static_cast<QFormLayout*>(form->layout());
        layout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        layout->setLabelAlignment(Qt::AlignRight);
    }
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // fields shrink to the dock instead
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(forms);
    outer->addWidget(scroll, 1);
    // Below the fields, so that a message appearing does not move the field being edited.
    outer->addWidget(m_message);

    createBodyRows();
    createJointRows();
    for (const auto& [field, keys] : kFieldSchemaKeys) {
        QStringList schemaKeys;
        for (const char* key : keys)
            if (key) schemaKeys << QString::fromLatin1(key);
        const QString name = QString::fromLatin1(field);
        for (const QString& part : {name, name + ".x", name + ".y", name + ".z"})
            if (NumberField* number = numberField(part)) number->setProperty("schemaKeys", schemaKeys);
    }

    // A refusal is about the fields it came from: another selection's fields are not refused.
    connect(document, &SceneDocument::selectionChanged, m_message, &QWidget::hide);
    connect(document, &SceneDocument::selectionChanged, this, &InspectorPanel::refresh);
    connect(document, &SceneDocument::sceneReplaced, this, &InspectorPanel::refresh);
    connect(document, &SceneDocument::bodyChanged, this, [this](int index) {
        // A joint's form names its bodies.
        if (m_document->selectedBodies().contains(index) || !m_document->selectedJoints().isEmpty()) refresh();
    });
    connect(document, &SceneDocument::jointChanged, this, [this](int index) {
        if (m_document->selectedJoints().contains(index)) refresh();
    });
    refresh();
}

void InspectorPanel::createBodyRows() {
    const auto always = [](const simcore::SceneBody&) { return true; };

    // Name: only for one body (several bodies never share a name on purpose).
    m_name->setObjectName(QStringLiteral("name"));
    m_bodyRows.addRow(tr("Name"), m_name, always);
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        if (m_refreshing || m_document->selectedBodies().size() != 1) return;
        const QString name = m_name->text().trimmed();
        const int index = m_document->selectedBodies().first();
        if (name == m_document->bodyName(index)) return;
        if (const QString problem = m_document->bodyNameProblem(index, name); !problem.isEmpty()) {
            m_name->setText(m_document->bodyName(index));
            showMessage(problem);
            return;
        }
        editBodies(BodyField::Name, QString(), [&](simcore::SceneBody& b) { b.body.name = name.toStdString(); });
    });

    // Shape.
    for (simcore::ShapeType type : kShapeTypes) m_shapeType->addItem(shapeDisplayName(type), static_cast<int>(type));
    m_shapeType->setObjectName(QStringLiteral("shapeType"));
    m_shapeType->setPlaceholderText(tr("mixed"));  // shown while bodies of several shapes are selected
    m_bodyRows.addRow(tr("Shape"), m_shapeType, always);
    connect(m_shapeType, &QComboBox::activated, this, [this](int row) {
        const auto type = static_cast<simcore::ShapeType>(m_shapeType->itemData(row).toInt());
        editBodies(BodyField::Shape, tr("Shape"), [type](simcore::SceneBody& b) {
            if (b.body.shape.type != type) b.body.shape = templateShape(type);
        });
    });
    m_bodyRows.addVector(QStringLiteral("halfExtents"), tr("Half extents"), tr("Half extent"), range(PropertyOwner::Box, "halfExtents").min,
                         range(PropertyOwner::Box, "halfExtents").max,
                         BodyField::Shape,
                         [](const simcore::SceneBody& b, int axis) -> std::optional<double> {
                             if (b.body.shape.type != simcore::ShapeType::Box) return std::nullopt;
                             return b.body.shape.halfExtents[axis];
                         },
                         [](simcore::SceneBody& b, int axis, double v) { b.body.shape.halfExtents[axis] = static_cast<float>(v); });
    m_bodyRows.addNumber(QStringLiteral("radius"), tr("Radius"), range(PropertyOwner::Sphere, "radius").min,
                         range(PropertyOwner::Sphere, "radius").max, BodyField::Shape,
                         [](const simcore::SceneBody& b) -> std::optional<double> {
                             if (!hasRadius(b)) return std::nullopt;
                             return b.body.shape.radius;
                         },
                         [](simcore::SceneBody& b, double v) { b.body.shape.radius = static_cast<float>(v); });
    m_bodyRows.addNumber(QStringLiteral("halfHeight"), tr("Half height"), range(PropertyOwner::Capsule, "halfHeight").min,
                         range(PropertyOwner::Capsule, "halfHeight").max, BodyField::Shape,
                         [](const simcore::SceneBody& b) -> std::optional<double> {
                             if (!hasHalfHeight(b)) return std::nullopt;
                             return b.body.shape.halfHeight;
                         },
                         [](simcore::SceneBody& b, double v) { b.body.shape.halfHeight = static_cast<float>(v); });
    // The hull's size, and its points as a table to edit or import (one body at a time).
    auto* hullRow = new QWidget;
    auto* hullLayout = new QHBoxLayout(hullRow);
    hullLayout->setContentsMargins(0, 0, 0, 0);
    m_hullInfo->setWordWrap(true);  // the row must not widen the dock
    hullLayout->addWidget(m_hullInfo, 1);
    m_editHullPoints->setObjectName(QStringLiteral("editHullPoints"));
    hullLayout->addWidget(m_editHullPoints);
    m_bodyRows.addRow(tr("Hull"), hullRow, isHull);
    connect(m_editHullPoints, &QPushButton::clicked, this, &InspectorPanel::editHullPoints);
    createCompoundRow();

    // Motion and mass.
    for (simcore::MotionType motion : kMotionTypes) m_motion->addItem(motionLabel(motion), static_cast<int>(motion));
    m_motion->setObjectName(QStringLiteral("motion"));
    m_motion->setPlaceholderText(tr("mixed"));
    m_bodyRows.addRow(tr("Motion"), m_motion, always);
    connect(m_motion, &QComboBox::activated, this, [this](int row) {
        const auto motion = static_cast<simcore::MotionType>(m_motion->itemData(row).toInt());
        editBodies(BodyField::Motion, tr("Motion"), [motion](simcore::SceneBody& b) { b.body.motion = motion; });
    });
    m_massMode->addItems({tr("Mass (kg)"), tr("Density (kg/m³)")});
    m_massMode->setObjectName(QStringLiteral("massMode"));
    m_massMode->setPlaceholderText(tr("mixed"));
    m_bodyRows.addRow(tr("Given by"), m_massMode, isDynamic);
    connect(m_massMode, &QComboBox::activated, this, [this](int row) {
        const bool byDensity = row == 1;
        // Switching keeps the body as heavy as it was; only how the file states it changes.
        editBodies(BodyField::Mass, tr("Mass"), [byDensity](simcore::SceneBody& b) {
            const float volume = simcore::volume(b.body.shape);
            if (byDensity && b.body.mass) {
                b.body.density = *b.body.mass / volume;
                b.body.mass.reset();
            } else if (!byDensity && !b.body.mass) {
                b.body.mass = b.body.density * volume;
            }
        }, isDynamic);
    });
    m_bodyRows.addNumber(QStringLiteral("mass"), tr("Mass or density"), simcore::limits::kMass.min,
                         simcore::limits::kMass.max, BodyField::Mass,
                         [](const simcore::SceneBody& b) -> std::optional<double> {
                             if (!isDynamic(b)) return std::nullopt;
                             return b.body.mass ? *b.body.mass : b.body.density;
                         },
                         [](simcore::SceneBody& b, double v) {
                             if (b.body.mass) b.body.mass = static_cast<float>(v);
                             else b.body.density = static_cast<float>(v);
                         });
    m_massResult->setObjectName(QStringLiteral("massResult"));
    m_bodyRows.addRow(QString(), m_massResult, isDynamic);

    // Material.
    m_bodyRows.addNumber(QStringLiteral("friction"), tr("Friction"), range(PropertyOwner::Body, "friction").min,
                         range(PropertyOwner::Body, "friction").max, BodyField::Friction,
                         [](const simcore::SceneBody& b) -> std::optional<double> { return b.body.friction; },
                         [](simcore::SceneBody& b, double v) { b.body.friction = static_cast<float>(v); });
    m_bodyRows.addNumber(QStringLiteral("restitution"), tr("Restitution"), range(PropertyOwner::Body, "restitution").min,
                         range(PropertyOwner::Body, "restitution").max, BodyField::Restitution,
                         [](const simcore::SceneBody& b) -> std::optional<double> { return b.body.restitution; },
                         [](simcore::SceneBody& b, double v) { b.body.restitution = static_cast<float>(v); });
    m_bodyRows.addNumber(QStringLiteral("rollingResistance"), tr("Rolling resistance"),
                         range(PropertyOwner::Body, "rollingResistance").min,
                         range(PropertyOwner::Body, "rollingResistance").max,
                         BodyField::RollingResistance,
                         [](const simcore::SceneBody& b) -> std::optional<double> { return b.body.rollingResistance; },
                         [](simcore::SceneBody& b, double v) { b.body.rollingResistance = static_cast<float>(v); },
                         tr("Rolling Resistance"));

    // Placement and motion state.
    m_bodyRows.addVector(QStringLiteral("position"), tr("Position (m)"), tr("Position"),
                         range(PropertyOwner::Body, "position").min, range(PropertyOwner::Body, "position").max,
                         BodyField::Position,
                         [](const simcore::SceneBody& b, int axis) -> std::optional<double> { return b.body.position[axis]; },
                         [](simcore::SceneBody& b, int axis, double v) { b.body.position[axis] = static_cast<float>(v); });
    m_bodyRows.addVector(QStringLiteral("orientation"), tr("Orientation (°)"), tr("Angle"), -kMaxAngle, kMaxAngle,
                         BodyField::Orientation,
                         [](const simcore::SceneBody& b, int axis) -> std::optional<double> {
                             return eulerDegrees(b.body.orientation)[axis];
                         },
                         [](simcore::SceneBody& b, int axis, double v) {
                             simcore::Vec3 angles = eulerDegrees(b.body.orientation);
                             angles[axis] = static_cast<float>(v);
                             b.body.orientation = fromEulerDegrees(angles);
                         });
    m_bodyRows.addVector(QStringLiteral("linearVelocity"), tr("Velocity (m/s)"), tr("Velocity"),
                         range(PropertyOwner::Body, "linearVelocity").min, range(PropertyOwner::Body, "linearVelocity").max,
                         BodyField::LinearVelocity,
                         [](const simcore::SceneBody& b, int axis) -> std::optional<double> { return b.body.linearVelocity[axis]; },
                         [](simcore::SceneBody& b, int axis, double v) { b.body.linearVelocity[axis] = static_cast<float>(v); });
    m_bodyRows.addVector(QStringLiteral("angularVelocity"), tr("Spin (rad/s)"), tr("Angular velocity"),
                         range(PropertyOwner::Body, "angularVelocity").min, range(PropertyOwner::Body, "angularVelocity").max, BodyField::AngularVelocity,
                         [](const simcore::SceneBody& b, int axis) -> std::optional<double> { return b.body.angularVelocity[axis]; },
                         [](simcore::SceneBody& b, int axis, double v) { b.body.angularVelocity[axis] = static_cast<float>(v); });

    // Look and collision options.
    m_color->setObjectName(QStringLiteral("color"));
    m_bodyRows.addRow(tr("Colour"), m_color, always);
    connect(m_color, &QPushButton::clicked, this, &InspectorPanel::chooseColor);
    m_ccd->setObjectName(QStringLiteral("ccd"));
    m_bodyRows.addRow(QString(), m_ccd, always);
    connect(m_ccd, &QCheckBox::clicked, this, [this](bool on) {
        editBodies(BodyField::Ccd, tr("Continuous Collision"), [on](simcore::SceneBody& b) { b.body.ccd = on; });
    });
}

NumberField* InspectorPanel::numberField(const QString& key) const {
    if (NumberField* field = m_bodyRows.numberField(key)) return field;
    return m_jointRows.numberField(key);
}

QString InspectorPanel::message() const {
    return m_message->isHidden() ? QString() : m_message->text();
}

namespace {

// The text of an edit's command: "Move Box 1", "Change Friction of 3 Bodies", "Rename Joint 2 to Door".
QString commandText(BodyField field, const QString& what, const QString& objects, const QString& newName) {
    switch (field) {
    case BodyField::Position: return InspectorPanel::tr("Move %1").arg(objects);
    case BodyField::Orientation: return InspectorPanel::tr("Rotate %1").arg(objects);
    case BodyField::Name: return InspectorPanel::tr("Rename %1 to %2").arg(objects, newName);
    default: return InspectorPanel::tr("Change %1 of %2").arg(what, objects);
    }
}

QString commandText(JointField field, const QString& what, const QString& objects, const QString& newName) {
    if (field == JointField::Name) return InspectorPanel::tr("Rename %1 to %2").arg(objects, newName);
    return InspectorPanel::tr("Change %1 of %2").arg(what, objects);
}

// The body or joint a diagnostic's path ("/bodies/3/friction") is about; `fallback` (a body, or
// a joint when !bodies) when the path names neither.
QString objectNamed(const SceneDocument& document, const std::string& path, bool bodies, int fallback) {
    for (const bool body : {true, false}) {
        const std::string prefix = body ? "/bodies/" : "/joints/";
        if (path.rfind(prefix, 0) != 0) continue;
        const int index = std::atoi(path.c_str() + prefix.size());
        return body ? document.bodyName(index) : document.jointName(index);
    }
    return bodies ? document.bodyName(fallback) : document.jointName(fallback);
}

}  // namespace

template <typename Object, typename Field>
void InspectorPanel::edit(Field field, const QString& what, const std::function<void(Object&)>& change,
                          const std::function<bool(const Object&)>& appliesTo) {
    if (m_refreshing) return;
    constexpr bool kBodies = std::is_same_v<Object, simcore::SceneBody>;
    const QList<int>& selection = kBodies ? m_document->selectedBodies() : m_document->selectedJoints();
    QList<int> indices;
    std::vector<Object> after;
    simcore::Scene candidate = m_document->scene();
    for (int index : selection) {
        const Object& object = ObjectAccess<Object>::get(*m_document, index);
        if (appliesTo && !appliesTo(object)) continue;
        Object changed = object;
        change(changed);
        if constexpr (kBodies) candidate.bodies[static_cast<std::size_t>(index)] = changed;
        else candidate.joints[static_cast<std::size_t>(index)] = changed;
        indices << index;
        after.push_back(std::move(changed));
    }
    if (indices.isEmpty()) return;
    // The loader's checks on the scene as it would be: what one field cannot see (a hull that is
    // missing, limits the wrong way round, a mass the density gives) is refused too.
    for (const simcore::Diagnostic& d : simcore::checkScene(candidate)) {
        if (d.severity != simcore::Diagnostic::Severity::Error) continue;
        showMessage(tr("%1 not changed: %2").arg(objectNamed(*m_document, d.path, kBodies, indices.value(0)),
                                                  QString::fromStdString(d.message)));
        refresh();
        return;
    }
    QString label, newName;
    if constexpr (kBodies) {
        label = bodiesLabel(*m_document, indices);
        newName = QString::fromStdString(after.front().body.name);
    } else {
        label = jointsLabel(*m_document, indices);
        newName = QString::fromStdString(after.front().joint.name);
    }
    m_message->hide();
    const QString text = commandText(field, what, label, newName);
    if constexpr (kBodies) {
        // A move or turn takes the joints riding on the bodies along.
        m_document->undoStack()->push(changeBodiesCommand(m_document, text, field, indices, std::move(after)));
    } else {
        m_document->undoStack()->push(new ChangeJoints(m_document, text, field, indices, std::move(after)));
    }
}

void InspectorPanel::editBodies(BodyField field, const QString& what, const std::function<void(simcore::SceneBody&)>& change,
                                const std::function<bool(const simcore::SceneBody&)>& appliesTo) {
    edit<simcore::SceneBody>(field, what, change, appliesTo);
}

void InspectorPanel::editJoints(JointField field, const QString& what, const std::function<void(simcore::SceneJoint&)>& change,
                                const std::function<bool(const simcore::SceneJoint&)>& appliesTo) {
    edit<simcore::SceneJoint>(field, what, change, appliesTo);
}

void InspectorPanel::showMessage(const QString& message) {
    m_message->setText(message);
    m_message->show();
    emit rejected(message);
}

void InspectorPanel::chooseColor() {
    const QList<int>& selection = m_document->selectedBodies();
    if (selection.isEmpty()) return;
    const std::optional<simcore::Vec3> current = m_document->body(selection.first()).color;
    const QColor initial = current ? toQColor(*current) : QColor(Qt::gray);
    const QColor chosen = QColorDialog::getColor(initial, this, tr("Body Colour"));
    if (!chosen.isValid()) return;
    const simcore::Vec3 linear(linearFromSrgb(static_cast<float>(chosen.redF())),
                               linearFromSrgb(static_cast<float>(chosen.greenF())),
                               linearFromSrgb(static_cast<float>(chosen.blueF())));
    editBodies(BodyField::Color, tr("Colour"), [&](simcore::SceneBody& b) { b.color = linear; });
}

void InspectorPanel::refresh() {
    m_refreshing = true;
    const QList<int>& bodies = m_document->selectedBodies();
    const QList<int>& joints = m_document->selectedJoints();
    // Bodies win a mixed selection; joints have their own form when they are all that is selected.
    const bool showJoints = bodies.isEmpty() && !joints.isEmpty();
    if (bodies.isEmpty() && joints.isEmpty()) {
        m_header->setText(tr("Nothing selected. Click a body in the viewport, or pick a body or joint in the Scene tree."));
    } else if (showJoints) {
        m_header->setText(joints.size() == 1 ? m_document->jointName(joints.first())
                                             : tr("%1 joints selected").arg(joints.size()));
    } else {
        m_header->setText(bodies.size() == 1 ? m_document->bodyName(bodies.first()) : tr("%1 bodies selected").arg(bodies.size()));
    }
    m_bodyForm->setVisible(!bodies.isEmpty());
    m_jointForm->setVisible(showJoints);
    if (!bodies.isEmpty()) refreshBodies();
    if (showJoints) refreshJoints();
    m_refreshing = false;
}

void InspectorPanel::refreshBodies() {
    const QList<int>& selection = m_document->selectedBodies();
    std::vector<const simcore::SceneBody*> bodies;
    for (int index : selection) bodies.push_back(&m_document->body(index));
    m_bodyRows.refresh(bodies);

    const simcore::SceneBody& lead = *bodies.front();
    m_name->setEnabled(bodies.size() == 1);
    m_name->setText(bodies.size() == 1 ? m_document->bodyName(selection.first()) : QString());
    // Values that differ across the selection show no choice, and the drop-down says "mixed".
    const auto showChoice = [](QComboBox* box, std::optional<int> data) { box->setCurrentIndex(data ? box->findData(*data) : -1); };
    showChoice(m_shapeType, sharedValue(bodies, [](const simcore::SceneBody& b) { return static_cast<int>(b.body.shape.type); }));
    showChoice(m_motion, sharedValue(bodies, [](const simcore::SceneBody& b) { return static_cast<int>(b.body.motion); }));
    std::vector<const simcore::SceneBody*> dynamicBodies;  // the bodies the mass row applies to
    std::copy_if(bodies.begin(), bodies.end(), std::back_inserter(dynamicBodies), [](const auto* b) { return isDynamic(*b); });
    const std::optional<bool> byMass = sharedValue(dynamicBodies, [](const simcore::SceneBody& b) { return b.body.mass.has_value(); });
    m_massMode->setCurrentIndex(byMass ? (*byMass ? 0 : 1) : -1);
    // The field takes what a scene file accepts for what it holds (docs/scene-format.md).
    const simcore::NumberRange& massRange = range(PropertyOwner::Body, lead.body.mass ? "mass" : "density");
    numberField(QStringLiteral("mass"))->setRange(massRange.min, massRange.max);
    m_massResult->setText(massSummary(dynamicBodies));
    m_editHullPoints->setEnabled(bodies.size() == 1);
    if (lead.body.shape.hull) {
        m_hullInfo->setText(tr("%1 points, %2 faces")
                                .arg(lead.body.shape.hull->sourcePoints().size())
                                .arg(lead.body.shape.hull->faces().size()));
    }
    // The children of one compound at a time: several bodies' children do not line up as rows.
    m_compoundTable->setEnabled(bodies.size() == 1);
    m_compoundChildren->setChildren(lead.body.shape.compound ? lead.body.shape.compound->children()
                                                             : std::vector<simcore::CompoundChild>{});
    const auto color = sharedValue(bodies, [](const simcore::SceneBody& b) { return b.color; });
    if (color && *color) {
        const QColor c = toQColor(**color);
        m_color->setText(c.name());
        m_color->setStyleSheet(QStringLiteral("background-color: %1; color: %2;")
                                   .arg(c.name(), c.lightnessF() > 0.55 ? QStringLiteral("black") : QStringLiteral("white")));
    } else {
        m_color->setText(color ? tr("Automatic") : tr("mixed"));
        m_color->setStyleSheet(QString());
    }
    showSharedCheck(m_ccd, sharedValue(bodies, [](const simcore::SceneBody& b) { return b.body.ccd; }));
}

void InspectorPanel::createCompoundRow() {
    const auto isCompound = [](const simcore::SceneBody& b) { return b.body.shape.type == simcore::ShapeType::Compound; };
    auto* row = new QWidget;
    auto* layout = new QVBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    m_compoundTable->setObjectName(QStringLiteral("compoundChildren"));
    m_compoundTable->setModel(m_compoundChildren);
    m_compoundTable->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                                     QAbstractItemView::AnyKeyPressed);
    m_compoundTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_compoundTable->setSelectionMode(QAbstractItemView::SingleSelection);
    m_compoundTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_compoundTable->setMinimumHeight(120);
    layout->addWidget(m_compoundTable);
    auto* buttons = new QHBoxLayout;
    auto* add = new QToolButton;
    add->setObjectName(QStringLiteral("addChild"));
    add->setText(tr("Add Child"));
    add->setPopupMode(QToolButton::InstantPopup);
    auto* types = new QMenu(add);
    for (simcore::ShapeType type : {simcore::ShapeType::Box, simcore::ShapeType::Sphere, simcore::ShapeType::Capsule,
                                    simcore::ShapeType::Cylinder})
        types->addAction(shapeDisplayName(type), this, [this, type] { m_compoundChildren->addChild(type); });
    add->setMenu(types);
    m_removeChild->setObjectName(QStringLiteral("removeChild"));
    buttons->addWidget(add);
    buttons->addWidget(m_removeChild);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_bodyRows.addRow(tr("Children"), row, isCompound);
    connect(m_removeChild, &QPushButton::clicked, this, [this] {
        const QModelIndex current = m_compoundTable->currentIndex();
        m_compoundChildren->removeChild(current.isValid() ? current.row() : m_compoundChildren->rowCount() - 1);
    });
    connect(m_compoundChildren, &CompoundChildrenModel::refused, this, &InspectorPanel::showMessage);
    // One command per accepted edit, with the model's children; checkScene may still refuse it,
    // and the refresh after either outcome puts the document's children back into the model.
    connect(m_compoundChildren, &CompoundChildrenModel::childrenEdited, this, [this, isCompound](const QString& what) {
        auto compound = std::make_shared<const simcore::CompoundShape>(m_compoundChildren->children());
        // Queued: the table's editor is still committing into the model while this signal runs.
        QMetaObject::invokeMethod(this, [this, isCompound, what, compound] {
            editBodies(BodyField::Shape, what, [&](simcore::SceneBody& b) { b.body.shape = simcore::Shape::compoundOf(compound); },
                       isCompound);
            refresh();
        }, Qt::QueuedConnection);
    });
}

void InspectorPanel::editHullPoints() {
    const QList<int>& selection = m_document->selectedBodies();
    if (selection.size() != 1 || !m_document->body(selection.first()).body.shape.hull) return;
    const int index = selection.first();
    auto* dialog = new HullPointsDialog(m_document->body(index).body.shape.hull->sourcePoints(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, index] {
        const std::shared_ptr<const simcore::ConvexHull> hull = dialog->model()->hull().hull;
        // The dialog is window-modal: the selection is still the body it was opened for.
        if (!hull || m_document->selectedBodies() != QList<int>{index}) return;
        editBodies(BodyField::Shape, tr("Hull Points"),
                   [hull](simcore::SceneBody& b) { b.body.shape = simcore::Shape::convexHull(hull); }, isHull);
    });
    dialog->open();
}

}  // namespace interplay
