#pragma once
// The Inspector dock: the selected bodies' properties. Each row is a getter/setter pair (as in
// Tiled's properties widget): the getter reads a value from a body (or says the row does not
// apply to it, e.g. a radius for a box), the setter changes a copy, and the edit is pushed as one
// ChangeBodies command for every selected body the row applies to. With several bodies selected a
// row whose values differ shows "mixed"; typing a value sets it on all of them.
//
// Bad input (not a number, NaN, a size <= 0, a negative mass, restitution above 1, anything the
// engine refuses) pushes nothing: the message says why, and the field shows the old value again.

#include "app/document/scene_document.h"

#include <QWidget>

#include <functional>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace interplay {

class NumberField;

class InspectorPanel : public QWidget {
    Q_OBJECT

public:
    explicit InspectorPanel(SceneDocument* document, QWidget* parent = nullptr);

    // Fields by key, e.g. "friction", "position.x", "halfExtents.y", "radius", "mass" (for tests
    // and for focusing from elsewhere).
    NumberField* numberField(const QString& key) const;
    QLineEdit* nameField() const { return m_name; }
    QComboBox* shapeTypeBox() const { return m_shapeType; }
    QComboBox* motionBox() const { return m_motion; }
    QCheckBox* ccdBox() const { return m_ccd; }
    // The last rejection message shown (empty once a valid edit went through).
    QString message() const;

signals:
    void rejected(const QString& message);

private:
    using Getter = std::function<std::optional<double>(const simcore::SceneBody&)>;
    using Setter = std::function<void(simcore::SceneBody&, double)>;
    struct NumberRow {
        NumberField* field;
        Getter get;
    };
    struct FormRow {
        QWidget* field;
        std::function<bool(const simcore::SceneBody&)> appliesTo;
    };

    NumberField* addNumber(const QString& key, const QString& quantity, double minimum, double maximum, BodyField field,
                           Getter get, Setter set);
    // A row of three fields for a vector; `component(body, axis)` reads, `setComponent` writes.
    void addVector(const QString& key, const QString& label, const QString& quantity, double minimum, double maximum,
                   BodyField field, std::function<std::optional<double>(const simcore::SceneBody&, int)> get,
                   std::function<void(simcore::SceneBody&, int, double)> set);
    void addRow(const QString& label, QWidget* field, std::function<bool(const simcore::SceneBody&)> appliesTo);

    // Applies `change` to a copy of every selected body for which `appliesTo` holds and pushes
    // the result, or shows why the engine refuses it.
    void edit(BodyField field, const QString& what, const std::function<void(simcore::SceneBody&)>& change,
              const std::function<bool(const simcore::SceneBody&)>& appliesTo = {});
    void refresh();
    void showMessage(const QString& message);
    void chooseColor();

    SceneDocument* m_document;
    QLabel* m_header;
    QLabel* m_message;
    QWidget* m_form;
    QFormLayout* m_layout;
    QLineEdit* m_name;
    QComboBox* m_shapeType;
    QLabel* m_hullInfo;
    QComboBox* m_motion;
    QComboBox* m_massMode;
    QPushButton* m_color;
    QCheckBox* m_ccd;
    std::vector<NumberRow> m_numbers;
    std::vector<FormRow> m_rows;
    bool m_refreshing = false;
};

}  // namespace interplay
