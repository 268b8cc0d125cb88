#pragma once
// The rows of an Inspector form for one kind of object (bodies, joints). Each row is a
// getter/setter pair, as in Tiled's properties widget: the getter reads a value from an object or
// says the row does not apply to it (a radius for a box, limits for a ball joint), the setter
// changes a copy, and the form hands the change to its `Edit` callback, which pushes one command
// for every selected object the row applies to. With several objects selected, a number whose
// values differ shows "mixed"; a row that applies to none of them is hidden. The Inspector's own
// rows (drop-downs, the colour button) use sharedValue for the same rule.

#include "app/panels/number_field.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QString>
#include <QWidget>

#include <algorithm>
#include <functional>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace interplay {

// What `get` reads from every one of `objects`, or nothing when they differ (or there are none).
template <typename Object, typename Get>
auto sharedValue(const std::vector<const Object*>& objects, Get get)
    -> std::optional<std::decay_t<decltype(get(std::declval<const Object&>()))>> {
    std::optional<std::decay_t<decltype(get(std::declval<const Object&>()))>> shared;
    for (const Object* object : objects) {
        auto value = get(*object);
        if (!shared) shared = std::move(value);
        else if (!(value == *shared)) return std::nullopt;
    }
    return shared;
}

template <typename Object, typename Field>
class PropertyRows {
public:
    using Getter = std::function<std::optional<double>(const Object&)>;
    using Setter = std::function<void(Object&, double)>;
    using AppliesTo = std::function<bool(const Object&)>;
    using ComponentGetter = std::function<std::optional<double>(const Object&, int axis)>;
    using ComponentSetter = std::function<void(Object&, int axis, double)>;
    // Applies `change` to a copy of every selected object for which `appliesTo` holds (all of them
    // when it is empty) and pushes the result, or says why it is refused. `what` names the quantity
    // in the command's text ("Change Friction of Box 1").
    using Edit = std::function<void(Field field, const QString& what, const std::function<void(Object&)>& change,
                                    const AppliesTo& appliesTo)>;

    // Rows go into `layout`; refused input is reported through `reject`.
    PropertyRows(QFormLayout* layout, Edit edit, std::function<void(const QString&)> reject)
        : m_layout(layout), m_edit(std::move(edit)), m_reject(std::move(reject)) {}

    void addRow(const QString& label, QWidget* field, AppliesTo appliesTo) {
        m_layout->addRow(label, field);
        m_rows.push_back({field, std::move(appliesTo)});
    }

    // `what` names the edit in commands when the row's label would not read well there (units).
    NumberField* addNumber(const QString& key, const QString& quantity, double minimum, double maximum, Field field,
                           Getter get, Setter set, const QString& what = {}) {
        auto* number = makeNumber(key, quantity, what.isEmpty() ? quantity : what, minimum, maximum, field, get, set);
        addRow(quantity, number, [get](const Object& object) { return get(object).has_value(); });
        return number;
    }

    // A row of three fields for a vector; `get(object, axis)` reads a component, `set` writes one.
    void addVector(const QString& key, const QString& label, const QString& quantity, double minimum, double maximum,
                   Field field, ComponentGetter get, ComponentSetter set) {
        auto* row = new QWidget;
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(4);
        static const char* const kAxes[] = {"x", "y", "z"};
        for (int axis = 0; axis < 3; ++axis) {
            const QString axisName = QLatin1String(kAxes[axis]);
            const Getter componentGet = [get, axis](const Object& object) { return get(object, axis); };
            layout->addWidget(makeNumber(key + u'.' + axisName, QStringLiteral("%1 %2").arg(quantity, axisName), quantity,
                                         minimum, maximum, field, componentGet,
                                         [set, axis](Object& object, double value) { set(object, axis, value); }));
        }
        addRow(label, row, [get](const Object& object) { return get(object, 0).has_value(); });
    }

    NumberField* numberField(const QString& key) const {
        for (const NumberRow& row : m_numbers) {
            if (row.field->objectName() == key) return row.field;
        }
        return nullptr;
    }

    // Shows the rows that apply to any of `objects`, with their values.
    void refresh(const std::vector<const Object*>& objects) {
        for (const FormRow& row : m_rows) {
            const bool applies = std::any_of(objects.begin(), objects.end(), [&](const Object* o) { return row.appliesTo(*o); });
            m_layout->setRowVisible(row.field, applies);
        }
        for (const NumberRow& row : m_numbers) {
            std::optional<double> shown;
            bool same = true;
            for (const Object* object : objects) {
                const std::optional<double> value = row.get(*object);
                if (!value) continue;
                if (!shown) shown = value;
                else if (*value != *shown) same = false;
            }
            row.field->setValue(same ? shown : std::nullopt);
        }
    }

private:
    struct NumberRow {
        NumberField* field;
        Getter get;
    };
    struct FormRow {
        QWidget* field;
        AppliesTo appliesTo;
    };

    // `quantity` names the field in messages ("Position x"), `what` the edit in commands ("Position").
    NumberField* makeNumber(const QString& key, const QString& quantity, const QString& what, double minimum,
                            double maximum, Field field, const Getter& get, const Setter& set) {
        auto* number = new NumberField(quantity, minimum, maximum);
        number->setObjectName(key);
        m_numbers.push_back({number, get});
        QObject::connect(number, &NumberField::rejected, number, [this](const QString& message) { m_reject(message); });
        QObject::connect(number, &NumberField::committed, number, [this, field, what, get, set](double value) {
            m_edit(field, what, [&](Object& object) { set(object, value); },
                   [&](const Object& object) { return get(object).has_value(); });
        });
        return number;
    }

    QFormLayout* m_layout;
    Edit m_edit;
    std::function<void(const QString&)> m_reject;
    std::vector<NumberRow> m_numbers;
    std::vector<FormRow> m_rows;
};

}  // namespace interplay
