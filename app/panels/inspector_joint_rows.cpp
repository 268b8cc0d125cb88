// The Inspector's joint form: its rows (type, bodies, anchors and axis, limits, motor, length
// range, spring, collision) and how it shows the selected joints.

#include "app/panels/inspector_fields.h"
#include "app/panels/inspector_panel.h"

#include "app/document/body_templates.h"
#include "app/document/scene_document.h"

#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>

#include <algorithm>
#include <iterator>
#include <vector>

namespace interplay {

using inspector::PropertyOwner;
using inspector::range;
using inspector::showSharedCheck;

namespace {

// What switching a joint's option on starts from. The motor can move the editor's one-metre
// template bodies (about 1000 kg at the default density) against gravity.
constexpr float kDefaultHingeLimit = 0.25f * simcore::kPi;  // rad, either way
constexpr float kDefaultSliderLimit = 0.5f;                  // m, either way
constexpr simcore::JointMotor kDefaultMotor{1.0f, 1e4f};     // rad/s or m/s; N m or N

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

}  // namespace

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
    // Each box over the joints it applies to (its row is shown when it applies to any).
    const auto showOption = [&joints](QCheckBox* box, const auto& appliesTo, const auto& isOn) {
        std::vector<const simcore::SceneJoint*> applicable;
        std::copy_if(joints.begin(), joints.end(), std::back_inserter(applicable), [&](const auto* j) { return appliesTo(*j); });
        showSharedCheck(box, sharedValue(applicable, isOn));
    };
    showOption(m_limits, isHingeOrSlider, [](const simcore::SceneJoint& j) { return j.joint.limits.has_value(); });
    showOption(m_motor, isHingeOrSlider, [](const simcore::SceneJoint& j) { return j.joint.motor.has_value(); });
    showOption(m_lengths, isDistance, [](const simcore::SceneJoint& j) { return hasLengthRange(j); });
    showOption(m_spring, isDistance, [](const simcore::SceneJoint& j) { return j.joint.spring.has_value(); });
    showOption(m_collideConnected, [](const simcore::SceneJoint& j) { return j.bodyB.has_value(); },
               [](const simcore::SceneJoint& j) { return j.joint.collideConnected; });
}

}  // namespace interplay
