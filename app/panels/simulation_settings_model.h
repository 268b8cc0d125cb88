#pragma once
// The document's world settings for the Simulation settings panel: one row per setting of
// simcore's schema (settings_schema.h), in its order, with the schema's group, label, unit, range
// and documentation as roles, so the panel shows every setting without knowing any of them.
// setValue() is the one write: the value is checked against the schema, then the whole scene with
// it against the loader (simcore::checkScene), so the editor never holds a scene it could not
// reopen; a refused value pushes nothing and is reported through rejected() with the loader's
// message. Accepted values are undoable ChangeSettings commands; writes made while a control is
// being dragged or held (interacting = true) merge into one history entry.

#include <QAbstractListModel>
#include <QStringList>

namespace simcore {
struct SettingInfo;
struct WorldSettings;
}  // namespace simcore

namespace interplay {

class SceneDocument;

class SimulationSettingsModel : public QAbstractListModel {
    Q_OBJECT
    Q_PROPERTY(int preset READ preset WRITE setPreset NOTIFY changed)  // index, -1 when custom
    Q_PROPERTY(QStringList presetNames READ presetNames CONSTANT)
    Q_PROPERTY(bool interacting READ interacting WRITE setInteracting NOTIFY interactingChanged)

public:
    enum Role {
        KeyRole = Qt::UserRole + 1,  // "solver.contactHertz"
        GroupRole,                   // "Solver"
        FirstInGroupRole,            // true for the first row of its group: where the panel heads it
        LabelRole,                   // "Contact stiffness"
        UnitRole,                    // "Hz", empty when dimensionless
        DocRole,                     // one line
        TypeRole,                    // "bool", "int", "float", "vec3" or "choice"
        MinimumRole,                 // numbers (a vector's components); unset for bool and choice
        MaximumRole,
        RangeRole,                   // "(0, 10000] Hz", as the docs write it; empty for bool and choice
        ValueRole,                   // bool, int, double, a list of 3 doubles, or a choice's index
        ChoicesRole,                 // a choice's labels, in the order of the names files write
    };
    Q_ENUM(Role)

    explicit SimulationSettingsModel(SceneDocument* document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

    // The schema keys of the rows, in order.
    QStringList keys() const;
    QVariant value(const QString& key) const;
    // Sets the setting `key` to `value` (a vector as a list of 3 numbers, a choice as its index);
    // returns whether it was accepted. Text that is not a number arrives as NaN and is refused.
    Q_INVOKABLE bool setValue(const QString& key, const QVariant& value);

    // Replaces every setting at once (an accuracy point's knobs): one history entry "Change <what>",
    // refused like setValue() when the scene with them would not load.
    bool setSettings(const QString& what, const simcore::WorldSettings& after);

    int preset() const;
    QStringList presetNames() const;
    bool interacting() const { return m_interacting; }
    void setPreset(int preset);
    void setInteracting(bool interacting);

signals:
    void changed();
    void interactingChanged(bool interacting);
    void rejected(const QString& message);

private:
    const simcore::WorldSettings& settings() const;
    // Pushes the command "Change <what>" unless the scene with `after` would not load.
    bool push(const QString& what, const QString& key, const simcore::WorldSettings& after);
    void refuse(const QString& what, const QString& why);

    SceneDocument* m_document;
    bool m_interacting = false;
    bool m_pushedWhileInteracting = false;
};

}  // namespace interplay
