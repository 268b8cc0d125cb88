#pragma once
// The document's world settings as QML properties, for the Simulation settings panel. Reads come
// from the document; every write is an undoable ChangeSettings command, checked by the engine
// first: a value it rejects (NaN, zero step, negative iterations...) pushes nothing and is reported
// through rejected(). Writes made while a control is being dragged (interacting = true) merge
// into one history entry.

#include <QObject>
#include <QStringList>
#include <QVariantList>

namespace simcore {
struct WorldSettings;
}

namespace interplay {

class SceneDocument;

class SimulationSettingsModel : public QObject {
    Q_OBJECT
    Q_PROPERTY(double gravityX READ gravityX NOTIFY changed)
    Q_PROPERTY(double gravityY READ gravityY NOTIFY changed)
    Q_PROPERTY(double gravityZ READ gravityZ NOTIFY changed)
    Q_PROPERTY(double stepRate READ stepRate WRITE setStepRate NOTIFY changed)  // steps per second (Hz)
    Q_PROPERTY(int substeps READ substeps WRITE setSubsteps NOTIFY changed)
    Q_PROPERTY(int velocityIterations READ velocityIterations WRITE setVelocityIterations NOTIFY changed)
    Q_PROPERTY(int positionIterations READ positionIterations WRITE setPositionIterations NOTIFY changed)
    Q_PROPERTY(int positionCorrection READ positionCorrection WRITE setPositionCorrection NOTIFY changed)
    Q_PROPERTY(QStringList positionCorrectionNames READ positionCorrectionNames CONSTANT)
    Q_PROPERTY(int integrator READ integrator WRITE setIntegrator NOTIFY changed)
    Q_PROPERTY(QStringList integratorNames READ integratorNames CONSTANT)
    Q_PROPERTY(double linearDamping READ linearDamping WRITE setLinearDamping NOTIFY changed)
    Q_PROPERTY(double angularDamping READ angularDamping WRITE setAngularDamping NOTIFY changed)
    Q_PROPERTY(QStringList effectNames READ effectNames CONSTANT)
    Q_PROPERTY(QVariantList effects READ effects NOTIFY changed)
    Q_PROPERTY(int preset READ preset WRITE setPreset NOTIFY changed)  // index, -1 when custom
    Q_PROPERTY(QStringList presetNames READ presetNames CONSTANT)
    Q_PROPERTY(bool interacting READ interacting WRITE setInteracting NOTIFY interactingChanged)

public:
    explicit SimulationSettingsModel(SceneDocument* document, QObject* parent = nullptr);

    double gravityX() const;
    double gravityY() const;
    double gravityZ() const;
    double stepRate() const;
    int substeps() const;
    int velocityIterations() const;
    int positionIterations() const;
    int positionCorrection() const;
    QStringList positionCorrectionNames() const;
    int integrator() const;
    QStringList integratorNames() const;
    double linearDamping() const;
    double angularDamping() const;
    QStringList effectNames() const;
    QVariantList effects() const;
    int preset() const;
    QStringList presetNames() const;
    bool interacting() const { return m_interacting; }

    Q_INVOKABLE void setGravity(double x, double y, double z);
    Q_INVOKABLE void setEffect(int effect, bool enabled);
    void setStepRate(double hertz);
    void setSubsteps(int substeps);
    void setVelocityIterations(int iterations);
    void setPositionIterations(int iterations);
    void setPositionCorrection(int method);
    void setIntegrator(int method);
    void setLinearDamping(double rate);
    void setAngularDamping(double rate);
    void setPreset(int preset);
    void setInteracting(bool interacting);

signals:
    void changed();
    void interactingChanged(bool interacting);
    void rejected(const QString& message);

private:
    const simcore::WorldSettings& settings() const;
    // Pushes the command "Change <what>" unless the engine rejects the settings.
    void push(const QString& what, const QString& key, const simcore::WorldSettings& after);

    SceneDocument* m_document;
    bool m_interacting = false;
    bool m_pushedWhileInteracting = false;
};

}  // namespace interplay
