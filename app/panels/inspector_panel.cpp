#include "app/panels/inspector_panel.h"

#include "app/document/body_templates.h"
#include "app/document/undo_commands.h"
#include "app/panels/number_field.h"
#include "app/viewport/color_space.h"

#include "simcore/world/world.h"

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

#include <cmath>
#include <exception>

namespace interplay {
namespace {

// Accepted ranges, as the scene format documents them (README "Scene format"): outside them the
// file would be refused on load, so the editor does not let them in either.
constexpr double kMinSize = 1e-4, kMaxSize = 1e5;               // m
constexpr double kMaxCoordinate = 1e6;                          // m
constexpr double kMaxSpeed = 1e4;                               // m/s and rad/s
constexpr double kMinMass = 1e-6, kMaxMass = 1e9;               // kg
constexpr double kMinDensity = 1e-3, kMaxDensity = 1e6;         // kg/m^3
constexpr double kMaxFriction = 100.0;
constexpr double kMaxAngle = 360.0;                             // degrees

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
      m_form(new QWidget), m_layout(new QFormLayout(m_form)), m_name(new QLineEdit), m_shapeType(new QComboBox),
      m_hullInfo(new QLabel), m_motion(new QComboBox), m_massMode(new QComboBox), m_color(new QPushButton),
      m_ccd(new QCheckBox(tr("Continuous collision (CCD)"))) {
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
    outer->addWidget(m_message);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // fields shrink to the dock instead
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_form);
    outer->addWidget(scroll, 1);
    m_layout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_layout->setLabelAlignment(Qt::AlignRight);

    const auto always = [](const simcore::SceneBody&) { return true; };

    // Name: only for one body (several bodies never share a name on purpose).
    m_name->setObjectName(QStringLiteral("name"));
    addRow(tr("Name"), m_name, always);
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        if (m_refreshing || m_document->selectedBodies().size() != 1) return;
        const QString name = m_name->text().trimmed();
        const int index = m_document->selectedBodies().first();
        if (name == m_document->bodyName(index)) return;
        if (name.isEmpty()) {
            m_name->setText(m_document->bodyName(index));
            showMessage(tr("A body needs a name."));
            return;
        }
        edit(BodyField::Name, QString(), [&](simcore::SceneBody& b) { b.body.name = name.toStdString(); });
    });

    // Shape.
    for (simcore::ShapeType type : kShapeTypes) m_shapeType->addItem(shapeDisplayName(type), static_cast<int>(type));
    m_shapeType->setObjectName(QStringLiteral("shapeType"));
    addRow(tr("Shape"), m_shapeType, always);
    connect(m_shapeType, &QComboBox::activated, this, [this](int row) {
        const auto type = static_cast<simcore::ShapeType>(m_shapeType->itemData(row).toInt());
        edit(BodyField::Shape, tr("Shape"), [type](simcore::SceneBody& b) {
            if (b.body.shape.type != type) b.body.shape = templateShape(type);
        });
    });
    addVector(QStringLiteral("halfExtents"), tr("Half extents"), tr("Half extent"), kMinSize, kMaxSize, BodyField::Shape,
              [](const simcore::SceneBody& b, int axis) -> std::optional<double> {
                  if (b.body.shape.type != simcore::ShapeType::Box) return std::nullopt;
                  return b.body.shape.halfExtents[axis];
              },
              [](simcore::SceneBody& b, int axis, double v) { b.body.shape.halfExtents[axis] = static_cast<float>(v); });
    addNumber(QStringLiteral("radius"), tr("Radius"), kMinSize, kMaxSize, BodyField::Shape,
              [](const simcore::SceneBody& b) -> std::optional<double> {
                  if (!hasRadius(b)) return std::nullopt;
                  return b.body.shape.radius;
              },
              [](simcore::SceneBody& b, double v) { b.body.shape.radius = static_cast<float>(v); });
    addNumber(QStringLiteral("halfHeight"), tr("Half height"), kMinSize, kMaxSize, BodyField::Shape,
              [](const simcore::SceneBody& b) -> std::optional<double> {
                  if (!hasHalfHeight(b)) return std::nullopt;
                  return b.body.shape.halfHeight;
              },
              [](simcore::SceneBody& b, double v) { b.body.shape.halfHeight = static_cast<float>(v); });
    addRow(tr("Hull"), m_hullInfo, [](const simcore::SceneBody& b) {
        return b.body.shape.type == simcore::ShapeType::ConvexHull;
    });

    // Motion and mass.
    for (simcore::MotionType motion : kMotionTypes) m_motion->addItem(motionLabel(motion), static_cast<int>(motion));
    m_motion->setObjectName(QStringLiteral("motion"));
    addRow(tr("Motion"), m_motion, always);
    connect(m_motion, &QComboBox::activated, this, [this](int row) {
        const auto motion = static_cast<simcore::MotionType>(m_motion->itemData(row).toInt());
        edit(BodyField::Motion, tr("Motion"), [motion](simcore::SceneBody& b) { b.body.motion = motion; });
    });
    m_massMode->addItems({tr("Mass (kg)"), tr("Density (kg/m³)")});
    m_massMode->setObjectName(QStringLiteral("massMode"));
    addRow(tr("Given by"), m_massMode, isDynamic);
    connect(m_massMode, &QComboBox::activated, this, [this](int row) {
        const bool byDensity = row == 1;
        // Switching keeps the body as heavy as it was; only how the file states it changes.
        edit(BodyField::Mass, tr("Mass"), [byDensity](simcore::SceneBody& b) {
            const float volume = simcore::volume(b.body.shape);
            if (byDensity && b.body.mass) {
                b.body.density = *b.body.mass / volume;
                b.body.mass.reset();
            } else if (!byDensity && !b.body.mass) {
                b.body.mass = b.body.density * volume;
            }
        }, isDynamic);
    });
    addNumber(QStringLiteral("mass"), tr("Mass or density"), kMinMass, kMaxMass, BodyField::Mass,
              [](const simcore::SceneBody& b) -> std::optional<double> {
                  if (!isDynamic(b)) return std::nullopt;
                  return b.body.mass ? *b.body.mass : b.body.density;
              },
              [](simcore::SceneBody& b, double v) {
                  if (b.body.mass) b.body.mass = static_cast<float>(v);
                  else b.body.density = static_cast<float>(v);
              });

    // Material.
    addNumber(QStringLiteral("friction"), tr("Friction"), 0.0, kMaxFriction, BodyField::Friction,
              [](const simcore::SceneBody& b) -> std::optional<double> { return b.body.friction; },
              [](simcore::SceneBody& b, double v) { b.body.friction = static_cast<float>(v); });
    addNumber(QStringLiteral("restitution"), tr("Restitution"), 0.0, 1.0, BodyField::Restitution,
              [](const simcore::SceneBody& b) -> std::optional<double> { return b.body.restitution; },
              [](simcore::SceneBody& b, double v) { b.body.restitution = static_cast<float>(v); });

    // Placement and motion state.
    addVector(QStringLiteral("position"), tr("Position (m)"), tr("Position"), -kMaxCoordinate, kMaxCoordinate,
              BodyField::Position,
              [](const simcore::SceneBody& b, int axis) -> std::optional<double> { return b.body.position[axis]; },
              [](simcore::SceneBody& b, int axis, double v) { b.body.position[axis] = static_cast<float>(v); });
    addVector(QStringLiteral("orientation"), tr("Orientation (°)"), tr("Angle"), -kMaxAngle, kMaxAngle,
              BodyField::Orientation,
              [](const simcore::SceneBody& b, int axis) -> std::optional<double> {
                  return eulerDegrees(b.body.orientation)[axis];
              },
              [](simcore::SceneBody& b, int axis, double v) {
                  simcore::Vec3 angles = eulerDegrees(b.body.orientation);
                  angles[axis] = static_cast<float>(v);
                  b.body.orientation = glm::normalize(simcore::Quat(glm::radians(angles)));
              });
    addVector(QStringLiteral("linearVelocity"), tr("Velocity (m/s)"), tr("Velocity"), -kMaxSpeed, kMaxSpeed,
              BodyField::LinearVelocity,
              [](const simcore::SceneBody& b, int axis) -> std::optional<double> { return b.body.linearVelocity[axis]; },
              [](simcore::SceneBody& b, int axis, double v) { b.body.linearVelocity[axis] = static_cast<float>(v); });
    addVector(QStringLiteral("angularVelocity"), tr("Spin (rad/s)"), tr("Angular velocity"), -kMaxSpeed, kMaxSpeed,
              BodyField::AngularVelocity,
              [](const simcore::SceneBody& b, int axis) -> std::optional<double> { return b.body.angularVelocity[axis]; },
              [](simcore::SceneBody& b, int axis, double v) { b.body.angularVelocity[axis] = static_cast<float>(v); });

    // Look and collision options.
    m_color->setObjectName(QStringLiteral("color"));
    addRow(tr("Colour"), m_color, always);
    connect(m_color, &QPushButton::clicked, this, &InspectorPanel::chooseColor);
    m_ccd->setObjectName(QStringLiteral("ccd"));
    addRow(QString(), m_ccd, always);
    connect(m_ccd, &QCheckBox::clicked, this, [this](bool on) {
        edit(BodyField::Ccd, tr("Continuous Collision"), [on](simcore::SceneBody& b) { b.body.ccd = on; });
    });

    connect(document, &SceneDocument::selectionChanged, this, &InspectorPanel::refresh);
    connect(document, &SceneDocument::sceneReplaced, this, &InspectorPanel::refresh);
    connect(document, &SceneDocument::bodyChanged, this, [this](int index) {
        if (m_document->selectedBodies().contains(index)) refresh();
    });
    refresh();
}

void InspectorPanel::addRow(const QString& label, QWidget* field, std::function<bool(const simcore::SceneBody&)> appliesTo) {
    m_layout->addRow(label, field);
    m_rows.push_back({field, std::move(appliesTo)});
}

NumberField* InspectorPanel::addNumber(const QString& key, const QString& quantity, double minimum, double maximum,
                                       BodyField field, Getter get, Setter set) {
    auto* number = new NumberField(quantity, minimum, maximum);
    number->setObjectName(key);
    m_numbers.push_back({number, get});
    addRow(quantity, number, [get](const simcore::SceneBody& b) { return get(b).has_value(); });
    connect(number, &NumberField::rejected, this, &InspectorPanel::showMessage);
    connect(number, &NumberField::committed, this, [this, field, quantity, get, set](double value) {
        edit(field, quantity, [&](simcore::SceneBody& b) { set(b, value); },
             [&](const simcore::SceneBody& b) { return get(b).has_value(); });
    });
    return number;
}

void InspectorPanel::addVector(const QString& key, const QString& label, const QString& quantity, double minimum,
                               double maximum, BodyField field,
                               std::function<std::optional<double>(const simcore::SceneBody&, int)> get,
                               std::function<void(simcore::SceneBody&, int, double)> set) {
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    static const char* const kAxes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        const QString axisQuantity = QStringLiteral("%1 %2").arg(quantity, QLatin1String(kAxes[axis]));
        const Getter componentGet = [get, axis](const simcore::SceneBody& b) { return get(b, axis); };
        auto* number = new NumberField(axisQuantity, minimum, maximum, row);
        number->setObjectName(key + u'.' + QLatin1String(kAxes[axis]));
        layout->addWidget(number);
        m_numbers.push_back({number, componentGet});
        connect(number, &NumberField::rejected, this, &InspectorPanel::showMessage);
        connect(number, &NumberField::committed, this, [this, field, quantity, componentGet, set, axis](double value) {
            edit(field, quantity, [&](simcore::SceneBody& b) { set(b, axis, value); },
                 [&](const simcore::SceneBody& b) { return componentGet(b).has_value(); });
        });
    }
    addRow(label, row, [get](const simcore::SceneBody& b) { return get(b, 0).has_value(); });
}

NumberField* InspectorPanel::numberField(const QString& key) const {
    for (const NumberRow& row : m_numbers) {
        if (row.field->objectName() == key) return row.field;
    }
    return nullptr;
}

QString InspectorPanel::message() const {
    return m_message->isHidden() ? QString() : m_message->text();
}

void InspectorPanel::edit(BodyField field, const QString& what, const std::function<void(simcore::SceneBody&)>& change,
                          const std::function<bool(const simcore::SceneBody&)>& appliesTo) {
    if (m_refreshing) return;
    QList<int> indices;
    std::vector<simcore::SceneBody> after;
    for (int index : m_document->selectedBodies()) {
        const simcore::SceneBody& body = m_document->body(index);
        if (appliesTo && !appliesTo(body)) continue;
        simcore::SceneBody changed = body;
        change(changed);
        // The engine's own checks catch what a single field cannot (e.g. a hull that is missing).
        try {
            simcore::World probe;
            probe.createBody(changed.body);
        } catch (const std::exception& e) {
            showMessage(tr("%1 not changed: %2").arg(m_document->bodyName(index), QString::fromStdString(e.what())));
            refresh();
            return;
        }
        indices << index;
        after.push_back(std::move(changed));
    }
    if (indices.isEmpty()) return;
    const QString bodies = bodiesLabel(*m_document, indices);
    QString text;
    switch (field) {
    case BodyField::Position: text = tr("Move %1").arg(bodies); break;
    case BodyField::Orientation: text = tr("Rotate %1").arg(bodies); break;
    case BodyField::Name:
        text = tr("Rename %1 to %2").arg(bodies, QString::fromStdString(after.front().body.name));
        break;
    default: text = tr("Change %1 of %2").arg(what, bodies); break;
    }
    m_message->hide();
    m_document->undoStack()->push(new ChangeBodies(m_document, text, field, indices, std::move(after)));
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
    edit(BodyField::Color, tr("Colour"), [&](simcore::SceneBody& b) { b.color = linear; });
}

void InspectorPanel::refresh() {
    m_refreshing = true;
    const QList<int>& selection = m_document->selectedBodies();
    std::vector<const simcore::SceneBody*> bodies;
    for (int index : selection) bodies.push_back(&m_document->body(index));

    if (bodies.empty()) {
        m_header->setText(tr("Nothing selected. Click a body in the viewport or pick one in the Scene tree."));
    } else if (bodies.size() == 1) {
        m_header->setText(m_document->bodyName(selection.first()));
    } else {
        m_header->setText(tr("%1 bodies selected").arg(bodies.size()));
    }
    m_form->setVisible(!bodies.empty());

    for (const FormRow& row : m_rows) {
        const bool applies = std::any_of(bodies.begin(), bodies.end(), [&](const auto* b) { return row.appliesTo(*b); });
        m_layout->setRowVisible(row.field, applies);
    }
    for (const NumberRow& row : m_numbers) {
        std::optional<double> shown;
        bool first = true, same = true;
        for (const simcore::SceneBody* b : bodies) {
            const std::optional<double> value = row.get(*b);
            if (!value) continue;
            if (first) shown = value;
            else if (*value != *shown) same = false;
            first = false;
        }
        row.field->setValue(same ? shown : std::nullopt);
    }

    if (!bodies.empty()) {
        const simcore::SceneBody& lead = *bodies.front();
        m_name->setEnabled(bodies.size() == 1);
        m_name->setText(bodies.size() == 1 ? m_document->bodyName(selection.first()) : QString());
        m_shapeType->setCurrentIndex(m_shapeType->findData(static_cast<int>(lead.body.shape.type)));
        m_motion->setCurrentIndex(m_motion->findData(static_cast<int>(lead.body.motion)));
        m_massMode->setCurrentIndex(lead.body.mass ? 0 : 1);
        // The field takes what a scene file accepts for what it holds (README "Scene format").
        if (lead.body.mass) numberField(QStringLiteral("mass"))->setRange(kMinMass, kMaxMass);
        else numberField(QStringLiteral("mass"))->setRange(kMinDensity, kMaxDensity);
        if (lead.body.shape.hull) {
            m_hullInfo->setText(tr("%1 points, %2 faces")
                                    .arg(lead.body.shape.hull->sourcePoints().size())
                                    .arg(lead.body.shape.hull->faces().size()));
        }
        if (lead.color) {
            const QColor c = toQColor(*lead.color);
            m_color->setText(c.name());
            m_color->setStyleSheet(QStringLiteral("background-color: %1; color: %2;")
                                       .arg(c.name(), c.lightnessF() > 0.55 ? QStringLiteral("black")
                                                                            : QStringLiteral("white")));
        } else {
            m_color->setText(tr("Automatic"));
            m_color->setStyleSheet(QString());
        }
        m_ccd->setChecked(lead.body.ccd);
    }
    m_refreshing = false;
}

}  // namespace interplay
