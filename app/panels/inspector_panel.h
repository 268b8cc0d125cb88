#pragma once
// The Inspector dock: the selected bodies' properties or, when only joints are selected, the
// selected joints'. Each form is a set of PropertyRows (getter/setter pairs, as in Tiled's
// properties widget), and an edit is pushed as one ChangeBodies or ChangeJoints command for every
// selected object the row applies to. With several objects selected a row whose values differ
// shows "mixed"; typing a value sets it on all of them.
//
// Bad input (not a number, NaN, a size <= 0, a negative mass, restitution above 1, a negative
// rolling resistance, a zero axis, limits the wrong way round, anything the engine refuses)
// pushes nothing: the message says why, and the field shows the old value again.

#include "app/document/scene_document.h"
#include "app/panels/property_rows.h"

#include <QWidget>

#include <functional>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;

namespace interplay {

class CompoundChildrenModel;
class NumberField;

class InspectorPanel : public QWidget {
    Q_OBJECT

public:
    explicit InspectorPanel(SceneDocument* document, QWidget* parent = nullptr);

    // Fields by key (for tests and for focusing from elsewhere). Bodies: "friction", "position.x",
    // "halfExtents.y", "radius", "mass", ... Joints: "anchor.x", "anchorB.x", "axis.x",
    // "hingeLower", "hingeUpper" (degrees), "sliderLower", "sliderUpper", "hingeMotorSpeed",
    // "hingeMaxTorque", "sliderMotorSpeed", "sliderMaxForce", "minLength", "maxLength",
    // "springHertz", "springDampingRatio".
    NumberField* numberField(const QString& key) const;
    QLineEdit* nameField() const { return m_name; }
    QComboBox* shapeTypeBox() const { return m_shapeType; }
    QComboBox* motionBox() const { return m_motion; }
    QCheckBox* ccdBox() const { return m_ccd; }
    QLineEdit* jointNameField() const { return m_jointName; }
    QCheckBox* limitsBox() const { return m_limits; }
    QCheckBox* motorBox() const { return m_motor; }
    QCheckBox* lengthsBox() const { return m_lengths; }
    QCheckBox* springBox() const { return m_spring; }
    QCheckBox* collideConnectedBox() const { return m_collideConnected; }
    // The last rejection message shown (empty once a valid edit went through).
    QString message() const;

signals:
    void rejected(const QString& message);

private:
    using BodyRows = PropertyRows<simcore::SceneBody, BodyField>;
    using JointRows = PropertyRows<simcore::SceneJoint, JointField>;

    void createBodyRows();
    void createJointRows();
    // Applies `change` to a copy of every selected body (joint) for which `appliesTo` holds and
    // pushes the result, or shows why the engine refuses it.
    template <typename Object, typename Field>
    void edit(Field field, const QString& what, const std::function<void(Object&)>& change,
              const std::function<bool(const Object&)>& appliesTo);
    void editBodies(BodyField field, const QString& what, const std::function<void(simcore::SceneBody&)>& change,
                    const std::function<bool(const simcore::SceneBody&)>& appliesTo = {});
    void editJoints(JointField field, const QString& what, const std::function<void(simcore::SceneJoint&)>& change,
                    const std::function<bool(const simcore::SceneJoint&)>& appliesTo = {});
    void refresh();
    void refreshBodies();
    void refreshJoints();
    void showMessage(const QString& message);
    void chooseColor();
    void editHullPoints();
    void createCompoundRow();

    SceneDocument* m_document;
    QLabel* m_header;
    QLabel* m_message;
    QWidget* m_bodyForm;
    QWidget* m_jointForm;
    BodyRows m_bodyRows;
    JointRows m_jointRows;

    QLineEdit* m_name;
    QComboBox* m_shapeType;
    QLabel* m_hullInfo;
    QPushButton* m_editHullPoints;
    CompoundChildrenModel* m_compoundChildren;  // the lead body's children, edited in a table
    QTableView* m_compoundTable;
    QPushButton* m_removeChild;
    QLabel* m_massResult;    // what the given mass or density comes to
    QComboBox* m_motion;
    QComboBox* m_massMode;
    QPushButton* m_color;
    QCheckBox* m_ccd;

    QLineEdit* m_jointName;
    QLabel* m_jointType;
    QLabel* m_jointBodies;
    QCheckBox* m_limits;
    QCheckBox* m_motor;
    QCheckBox* m_lengths;
    QCheckBox* m_spring;
    QCheckBox* m_collideConnected;

    bool m_refreshing = false;
};

}  // namespace interplay
