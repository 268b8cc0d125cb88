#include "app/panels/inspector_panel.h"

#include "app/document/body_templates.h"
#include "app/document/undo_commands.h"
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
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <type_traits>

namespace interplay {
namespace {

// Accepted ranges: the scene format's (simcore/settings_schema.h), so the editor lets in nothing a
// file would refuse on load. Each field names the schema properties it edits (its "schemaKeys"),
// which test_settings_schema checks against the schema.
using simcore::PropertyOwner;
const simcore::NumberRange& range(PropertyOwner owner, std::string_view key) {
    return simcore::propertyRange(owner, key);
}
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

// What switching a joint's option on starts from. The motor can move the editor's one-metre
// template bodies (about 1000 kg at the default density) against gravity.
constexpr float kDefaultHingeLimit = 0.25f * simcore::kPi;  // rad, either way
constexpr float kDefaultSliderLimit = 0.5f;                  // m, either way
constexpr simcore::JointMotor kDefaultMotor{1.0f, 1e4f};     // rad/s or m/s; N m or N

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

simcore::Vec3 eulerDegrees(const simcore::Quat& q) {
    return glm::degrees(glm::eulerAngles(q));
}

// Body colours are linear RGB; the colour dialog speaks sRGB.
QColor toQColor(const simcore::Vec3& linear) {
    return QColor::fromRgbF(srgbFromLinear(linear.r), srgbFromLinear(linear.g), srgbFromLinear(linear.b));
}

bool isHinge(const simcore::SceneJoint& j) {
    return j.joint.type == simcore::JointType::Hinge;
}

bool isSlider(const simcore::SceneJoint& j) {
    return j.joint.type == simcore::JointType::Slider;
}

bool isHingeOrSlider(const simcore::SceneJoint& j) {
    return isHinge(j) || isSlider(j);
}

bool isDistance(const simcore::SceneJoint& j) {
    return j.joint.type == simcore::JointType::Distance;
}

bool hasLengthRange(const simcore::SceneJoint& j) {
    return isDistance(j) && (j.joint.minLength || j.joint.maxLength);
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
      m_name(new QLineEdit), m_shapeType(new QComboBox), m_hullInfo(new QLabel), m_compoundInfo(new QLabel), m_motion(new QComboBox),
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
    m_bodyRows.addRow(tr("Hull"), m_hullInfo, [](const simcore::SceneBody& b) {
        return b.body.shape.type == simcore::ShapeType::ConvexHull;
    });
    m_compoundInfo->setObjectName(QStringLiteral("compoundChildren"));
    m_compoundInfo->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_bodyRows.addRow(tr("Children"), m_compoundInfo, [](const simcore::SceneBody& b) {
        return b.body.shape.type == simcore::ShapeType::Compound;
    });

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
                             b.body.orientation = glm::normalize(simcore::Quat(glm::radians(angles)));
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

void InspectorPanel::createJointRows() {
    const auto always = [](const simcore::SceneJoint&) { return true; };
    // An optional's value as a row value: the row applies while the option is on.
    const auto hingeLimit = [](float simcore::JointLimits::*bound) {
        return [bound](const simcore::SceneJoint& j) -> std::optional<double> {
            if (!isHinge(j) || !j.joint.limits) return std::nullopt;
            return glm::degrees((*j.joint.limits).*bound);
        };
    };
    const auto sliderLimit = [](float simcore::JointLimits::*bound) {
        return [bound](const simcore::SceneJoint& j) -> std::optional<double> {
            if (!isSlider(j) || !j.joint.limits) return std::nullopt;
            return (*j.joint.limits).*bound;
        };
    };
    const auto motorValue = [](simcore::JointType type, float simcore::JointMotor::*member) {
        return [type, member](const simcore::SceneJoint& j) -> std::optional<double> {
            if (j.joint.type != type || !j.joint.motor) return std::nullopt;
            return (*j.joint.motor).*member;
        };
    };
    const auto setMotor = [](float simcore::JointMotor::*member) {
        return [member](simcore::SceneJoint& j, double v) { (*j.joint.motor).*member = static_cast<float>(v); };
    };
    const auto springValue = [](float simcore::JointSpring::*member) {
        return [member](const simcore::SceneJoint& j) -> std::optional<double> {
            if (!isDistance(j) || !j.joint.spring) return std::nullopt;
            return (*j.joint.spring).*member;
        };
    };
    const auto setSpring = [](float simcore::JointSpring::*member) {
        return [member](simcore::SceneJoint& j, double v) { (*j.joint.spring).*member = static_cast<float>(v); };
    };
    // Hinge limits are shown in degrees; the file's range is in radians.
    struct { double min, max; } const hingeAngle{glm::degrees(range(PropertyOwner::Hinge, "limits.lower").min),
                                                 glm::degrees(range(PropertyOwner::Hinge, "limits.lower").max)};

    m_jointName->setObjectName(QStringLiteral("jointName"));
    m_jointRows.addRow(tr("Name"), m_jointName, always);
    connect(m_jointName, &QLineEdit::editingFinished, this, [this] {
        if (m_refreshing || m_document->selectedJoints().size() != 1) return;
        const QString name = m_jointName->text().trimmed();
        const int index = m_document->selectedJoints().first();
        if (name == m_document->jointName(index)) return;
        if (name.isEmpty()) {
            m_jointName->setText(m_document->jointName(index));
            showMessage(tr("A joint needs a name."));
            return;
        }
        editJoints(JointField::Name, QString(), [&](simcore::SceneJoint& j) { j.joint.name = name.toStdString(); });
    });
    m_jointType->setObjectName(QStringLiteral("jointType"));
    m_jointRows.addRow(tr("Type"), m_jointType, always);
    m_jointBodies->setObjectName(QStringLiteral("jointBodies"));
    // No word wrap: a height-for-width row in a QFormLayout with hidden rows writes out of bounds
    // in Qt 6.4 (seen under valgrind).
    m_jointRows.addRow(tr("Joins"), m_jointBodies, always);

    // Where it holds, as authored (world frame): the pose of the bodies at Reset is the rest pose.
    m_jointRows.addVector(QStringLiteral("anchor"), tr("Anchor (m)"), tr("Anchor"),
                          range(PropertyOwner::Joint, "anchor").min, range(PropertyOwner::Joint, "anchor").max,
                          JointField::Anchor,
                          [](const simcore::SceneJoint& j, int axis) -> std::optional<double> { return j.joint.anchor[axis]; },
                          [](simcore::SceneJoint& j, int axis, double v) { j.joint.anchor[axis] = static_cast<float>(v); });
    m_jointRows.addVector(QStringLiteral("anchorB"), tr("Anchor on B (m)"), tr("Anchor on B"),
                          range(PropertyOwner::Distance, "anchorB").min, range(PropertyOwner::Distance, "anchorB").max, JointField::AnchorB,
                          [](const simcore::SceneJoint& j, int axis) -> std::optional<double> {
                              if (!isDistance(j)) return std::nullopt;
                              return j.joint.anchorB[axis];
                          },
                          [](simcore::SceneJoint& j, int axis, double v) { j.joint.anchorB[axis] = static_cast<float>(v); });
    m_jointRows.addVector(QStringLiteral("axis"), tr("Axis"), tr("Axis"), range(PropertyOwner::Hinge, "axis").min,
                          range(PropertyOwner::Hinge, "axis").max, JointField::Axis,
                          [](const simcore::SceneJoint& j, int axis) -> std::optional<double> {
                              if (!isHingeOrSlider(j)) return std::nullopt;
                              return j.joint.axis[axis];
                          },
                          [](simcore::SceneJoint& j, int axis, double v) { j.joint.axis[axis] = static_cast<float>(v); });

    // Limits: hinge angles in degrees (stored in radians), slider travel in metres.
    m_limits->setObjectName(QStringLiteral("limits"));
    m_jointRows.addRow(QString(), m_limits, isHingeOrSlider);
    connect(m_limits, &QCheckBox::clicked, this, [this](bool on) {
        editJoints(JointField::Limits, tr("Limits"), [on](simcore::SceneJoint& j) {
            if (!on) {
                j.joint.limits.reset();
            } else if (!j.joint.limits) {
                const float range = isHinge(j) ? kDefaultHingeLimit : kDefaultSliderLimit;
                j.joint.limits = simcore::JointLimits{-range, range};
            }
        }, isHingeOrSlider);
    });
    m_jointRows.addNumber(QStringLiteral("hingeLower"), tr("Lower angle (°)"), hingeAngle.min, hingeAngle.max,
                          JointField::Limits, hingeLimit(&simcore::JointLimits::lower),
                          [](simcore::SceneJoint& j, double v) { j.joint.limits->lower = glm::radians(static_cast<float>(v)); },
                          tr("Lower Angle"));
    m_jointRows.addNumber(QStringLiteral("hingeUpper"), tr("Upper angle (°)"), hingeAngle.min, hingeAngle.max,
                          JointField::Limits, hingeLimit(&simcore::JointLimits::upper),
                          [](simcore::SceneJoint& j, double v) { j.joint.limits->upper = glm::radians(static_cast<float>(v)); },
                          tr("Upper Angle"));
    m_jointRows.addNumber(QStringLiteral("sliderLower"), tr("Lower limit (m)"),
                          range(PropertyOwner::Slider, "limits.lower").min, range(PropertyOwner::Slider, "limits.lower").max,
                          JointField::Limits, sliderLimit(&simcore::JointLimits::lower),
                          [](simcore::SceneJoint& j, double v) { j.joint.limits->lower = static_cast<float>(v); },
                          tr("Lower Limit"));
    m_jointRows.addNumber(QStringLiteral("sliderUpper"), tr("Upper limit (m)"),
                          range(PropertyOwner::Slider, "limits.upper").min, range(PropertyOwner::Slider, "limits.upper").max,
                          JointField::Limits, sliderLimit(&simcore::JointLimits::upper),
                          [](simcore::SceneJoint& j, double v) { j.joint.limits->upper = static_cast<float>(v); },
                          tr("Upper Limit"));

    // Motor.
    m_motor->setObjectName(QStringLiteral("motor"));
    m_jointRows.addRow(QString(), m_motor, isHingeOrSlider);
    connect(m_motor, &QCheckBox::clicked, this, [this](bool on) {
        editJoints(JointField::Motor, tr("Motor"), [on](simcore::SceneJoint& j) {
            if (!on) j.joint.motor.reset();
            else if (!j.joint.motor) j.joint.motor = kDefaultMotor;
        }, isHingeOrSlider);
    });
    m_jointRows.addNumber(QStringLiteral("hingeMotorSpeed"), tr("Motor speed (rad/s)"),
                          range(PropertyOwner::Hinge, "motor.speed").min, range(PropertyOwner::Hinge, "motor.speed").max,
                          JointField::Motor, motorValue(simcore::JointType::Hinge, &simcore::JointMotor::speed),
                          setMotor(&simcore::JointMotor::speed),
                          tr("Hinge Motor Speed"));
    m_jointRows.addNumber(QStringLiteral("hingeMaxTorque"), tr("Max torque (N m)"),
                          range(PropertyOwner::Hinge, "motor.maxTorque").min,
                          range(PropertyOwner::Hinge, "motor.maxTorque").max, JointField::Motor,
                          motorValue(simcore::JointType::Hinge, &simcore::JointMotor::maxForce),
                          setMotor(&simcore::JointMotor::maxForce),
                          tr("Hinge Motor Torque"));
    m_jointRows.addNumber(QStringLiteral("sliderMotorSpeed"), tr("Motor speed (m/s)"),
                          range(PropertyOwner::Slider, "motor.speed").min, range(PropertyOwner::Slider, "motor.speed").max,
                          JointField::Motor, motorValue(simcore::JointType::Slider, &simcore::JointMotor::speed),
                          setMotor(&simcore::JointMotor::speed),
                          tr("Slider Motor Speed"));
    m_jointRows.addNumber(QStringLiteral("sliderMaxForce"), tr("Max force (N)"),
                          range(PropertyOwner::Slider, "motor.maxForce").min,
                          range(PropertyOwner::Slider, "motor.maxForce").max, JointField::Motor,
                          motorValue(simcore::JointType::Slider, &simcore::JointMotor::maxForce),
                          setMotor(&simcore::JointMotor::maxForce),
                          tr("Slider Motor Force"));

    // Distance: a length range (off: the rest length, or unbounded with a spring) and a spring.
    m_lengths->setObjectName(QStringLiteral("lengths"));
    m_jointRows.addRow(QString(), m_lengths, isDistance);
    connect(m_lengths, &QCheckBox::clicked, this, [this](bool on) {
        editJoints(JointField::Lengths, tr("Length Range"), [on](simcore::SceneJoint& j) {
            if (!on) {
                j.joint.minLength.reset();
                j.joint.maxLength.reset();
            } else if (!hasLengthRange(j)) {
                // Start from the lengths in effect; an unbounded maximum starts a metre beyond rest.
                const simcore::DistanceLengths lengths = simcore::distanceLengths(j.joint);
                j.joint.minLength = lengths.min;
                j.joint.maxLength = std::isfinite(lengths.max) ? lengths.max : lengths.rest + 1.0f;
            }
        }, isDistance);
    });
    m_jointRows.addNumber(QStringLiteral("minLength"), tr("Min length (m)"),
                          range(PropertyOwner::Distance, "minLength").min, range(PropertyOwner::Distance, "minLength").max,
                          JointField::Lengths,
                          [](const simcore::SceneJoint& j) -> std::optional<double> {
                              if (!hasLengthRange(j)) return std::nullopt;
                              return simcore::distanceLengths(j.joint).min;
                          },
                          [](simcore::SceneJoint& j, double v) { j.joint.minLength = static_cast<float>(v); },
                          tr("Minimum Length"));
    m_jointRows.addNumber(QStringLiteral("maxLength"), tr("Max length (m)"),
                          range(PropertyOwner::Distance, "maxLength").min, range(PropertyOwner::Distance, "maxLength").max,
                          JointField::Lengths,
                          [](const simcore::SceneJoint& j) -> std::optional<double> {
                              if (!hasLengthRange(j)) return std::nullopt;
                              return simcore::distanceLengths(j.joint).max;
                          },
                          [](simcore::SceneJoint& j, double v) { j.joint.maxLength = static_cast<float>(v); },
                          tr("Maximum Length"));
    m_spring->setObjectName(QStringLiteral("spring"));
    m_jointRows.addRow(QString(), m_spring, isDistance);
    connect(m_spring, &QCheckBox::clicked, this, [this](bool on) {
        editJoints(JointField::Spring, tr("Spring"), [on](simcore::SceneJoint& j) {
            if (!on) j.joint.spring.reset();
            else if (!j.joint.spring) j.joint.spring = simcore::JointSpring{};
        }, isDistance);
    });
    m_jointRows.addNumber(QStringLiteral("springHertz"), tr("Spring frequency (Hz)"),
                          range(PropertyOwner::Distance, "spring.hertz").min,
                          range(PropertyOwner::Distance, "spring.hertz").max,
                          JointField::Spring, springValue(&simcore::JointSpring::hertz),
                          setSpring(&simcore::JointSpring::hertz),
                          tr("Spring Frequency"));
    m_jointRows.addNumber(QStringLiteral("springDampingRatio"), tr("Spring damping ratio"),
                          range(PropertyOwner::Distance, "spring.dampingRatio").min,
                          range(PropertyOwner::Distance, "spring.dampingRatio").max,
                          JointField::Spring, springValue(&simcore::JointSpring::dampingRatio),
                          setSpring(&simcore::JointSpring::dampingRatio),
                          tr("Spring Damping"));

    m_collideConnected->setObjectName(QStringLiteral("collideConnected"));
    m_jointRows.addRow(QString(), m_collideConnected, [](const simcore::SceneJoint& j) { return j.bodyB.has_value(); });
    connect(m_collideConnected, &QCheckBox::clicked, this, [this](bool on) {
        editJoints(JointField::CollideConnected, tr("Collision"),
                   [on](simcore::SceneJoint& j) { j.joint.collideConnected = on; },
                   [](const simcore::SceneJoint& j) { return j.bodyB.has_value(); });
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
    if (lead.body.shape.hull) {
        m_hullInfo->setText(tr("%1 points, %2 faces")
                                .arg(lead.body.shape.hull->sourcePoints().size())
                                .arg(lead.body.shape.hull->faces().size()));
    }
    if (lead.body.shape.compound) {
        // One line per child: its type and where it sits in the body frame.
        QStringList lines;
        for (const simcore::CompoundChild& child : lead.body.shape.compound->children()) {
            const simcore::Vec3& p = child.pose.position;
            lines << tr("%1 at (%2, %3, %4)")
                         .arg(shapeDisplayName(child.shape.type))
                         .arg(p.x, 0, 'g', 4)
                         .arg(p.y, 0, 'g', 4)
                         .arg(p.z, 0, 'g', 4);
        }
        m_compoundInfo->setText(lines.join(QLatin1Char('\n')));
    }
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
    m_ccd->setChecked(lead.body.ccd);
}

void InspectorPanel::refreshJoints() {
    const QList<int>& selection = m_document->selectedJoints();
    std::vector<const simcore::SceneJoint*> joints;
    for (int index : selection) joints.push_back(&m_document->joint(index));
    m_jointRows.refresh(joints);

    const simcore::SceneJoint& lead = *joints.front();
    const bool one = joints.size() == 1;
    m_jointName->setEnabled(one);
    m_jointName->setText(one ? m_document->jointName(selection.first()) : QString());
    const bool sameType = std::all_of(joints.begin(), joints.end(), [&](const auto* j) { return j->joint.type == lead.joint.type; });
    m_jointType->setText(sameType ? jointTypeDisplayName(lead.joint.type) : tr("mixed"));
    m_jointBodies->setText(one ? tr("%1 and %2").arg(m_document->bodyName(static_cast<int>(lead.bodyA)),
                                                     lead.bodyB ? m_document->bodyName(static_cast<int>(*lead.bodyB))
                                                                : tr("the world"))
                               : tr("%1 pairs").arg(joints.size()));
    m_limits->setChecked(lead.joint.limits.has_value());
    m_motor->setChecked(lead.joint.motor.has_value());
    m_lengths->setChecked(hasLengthRange(lead));
    m_spring->setChecked(lead.joint.spring.has_value());
    m_collideConnected->setChecked(lead.joint.collideConnected);
}

}  // namespace interplay
