#include "app/panels/simulation_settings_model.h"

#include "app/document/scene_document.h"
#include "app/document/undo_commands.h"
#include "simcore/world/quality_preset.h"
#include "simcore/world/world.h"

#include <QUndoStack>

#include <cmath>
#include <exception>
#include <utility>

namespace interplay {

SimulationSettingsModel::SimulationSettingsModel(SceneDocument* document, QObject* parent)
    : QObject(parent), m_document(document) {
    connect(document, &SceneDocument::settingsChanged, this, &SimulationSettingsModel::changed);
    connect(document, &SceneDocument::sceneReplaced, this, &SimulationSettingsModel::changed);
}

const simcore::WorldSettings& SimulationSettingsModel::settings() const {
    return m_document->scene().settings;
}

double SimulationSettingsModel::gravityX() const { return settings().gravity.x; }
double SimulationSettingsModel::gravityY() const { return settings().gravity.y; }
double SimulationSettingsModel::gravityZ() const { return settings().gravity.z; }
double SimulationSettingsModel::stepRate() const { return 1.0 / static_cast<double>(settings().timeStep); }
int SimulationSettingsModel::substeps() const { return settings().substeps; }
int SimulationSettingsModel::velocityIterations() const { return settings().solver.velocityIterations; }
int SimulationSettingsModel::positionIterations() const { return settings().solver.positionIterations; }
int SimulationSettingsModel::positionCorrection() const { return static_cast<int>(settings().solver.positionCorrection); }
double SimulationSettingsModel::linearDamping() const { return settings().damping.linear; }
double SimulationSettingsModel::angularDamping() const { return settings().damping.angular; }
int SimulationSettingsModel::preset() const {
    const std::optional<simcore::QualityPreset> matching = simcore::matchingQualityPreset(settings());
    return matching ? static_cast<int>(*matching) : -1;  // -1: custom settings
}

QStringList SimulationSettingsModel::positionCorrectionNames() const {
    return {tr("Soft step"), tr("Baumgarte")};
}

int SimulationSettingsModel::integrator() const { return static_cast<int>(settings().integrator); }

QStringList SimulationSettingsModel::integratorNames() const {  // in simcore::Integrator's order
    return {tr("Semi-implicit Euler"), tr("Explicit Euler"), tr("Velocity Verlet")};
}

QStringList SimulationSettingsModel::effectNames() const {
    QStringList names;
    for (int i = 0; i < simcore::kEffectCount; ++i) {
        names << QString::fromLatin1(simcore::effectName(static_cast<simcore::Effect>(i)));
    }
    return names;
}

QVariantList SimulationSettingsModel::effects() const {
    QVariantList flags;
    for (bool enabled : settings().effects.enabled) flags << enabled;
    return flags;
}

QStringList SimulationSettingsModel::presetNames() const {
    QStringList names;
    for (simcore::QualityPreset preset : simcore::kQualityPresets) {
        const QString name = QString::fromLatin1(simcore::qualityPresetName(preset));
        names << name.left(1).toUpper() + name.mid(1);
    }
    return names;
}

void SimulationSettingsModel::setGravity(double x, double y, double z) {
    simcore::WorldSettings after = settings();
    after.gravity = simcore::Vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
    push(tr("Gravity"), QStringLiteral("gravity"), after);
}

void SimulationSettingsModel::setEffect(int effect, bool enabled) {
    if (effect < 0 || effect >= simcore::kEffectCount) return;
    simcore::WorldSettings after = settings();
    after.effects.enabled[static_cast<std::size_t>(effect)] = enabled;
    const QString name = QString::fromLatin1(simcore::effectName(static_cast<simcore::Effect>(effect)));
    push(enabled ? tr("Effect %1 On").arg(name) : tr("Effect %1 Off").arg(name), QStringLiteral("effects.") + name, after);
}

void SimulationSettingsModel::setStepRate(double hertz) {
    simcore::WorldSettings after = settings();
    // A zero, negative or NaN rate becomes a time step the engine rejects, with its message.
    after.timeStep = hertz > 0.0 ? static_cast<float>(1.0 / hertz) : std::nanf("");
    push(tr("Time Step"), QStringLiteral("timeStep"), after);
}

void SimulationSettingsModel::setSubsteps(int substeps) {
    simcore::WorldSettings after = settings();
    after.substeps = substeps;
    push(tr("Substeps"), QStringLiteral("substeps"), after);
}

void SimulationSettingsModel::setVelocityIterations(int iterations) {
    simcore::WorldSettings after = settings();
    after.solver.velocityIterations = iterations;
    push(tr("Velocity Iterations"), QStringLiteral("solver.velocityIterations"), after);
}

void SimulationSettingsModel::setPositionIterations(int iterations) {
    simcore::WorldSettings after = settings();
    after.solver.positionIterations = iterations;
    push(tr("Position Iterations"), QStringLiteral("solver.positionIterations"), after);
}

void SimulationSettingsModel::setPositionCorrection(int method) {
    if (method < 0 || method > static_cast<int>(simcore::PositionCorrection::Baumgarte)) return;
    simcore::WorldSettings after = settings();
    after.solver.positionCorrection = static_cast<simcore::PositionCorrection>(method);
    push(tr("Position Correction"), QStringLiteral("solver.positionCorrection"), after);
}

void SimulationSettingsModel::setIntegrator(int method) {
    if (method < 0 || method > static_cast<int>(simcore::Integrator::VelocityVerlet)) return;
    simcore::WorldSettings after = settings();
    after.integrator = static_cast<simcore::Integrator>(method);
    push(tr("Integrator"), QStringLiteral("integrator"), after);
}

void SimulationSettingsModel::setLinearDamping(double rate) {
    simcore::WorldSettings after = settings();
    after.damping.linear = static_cast<float>(rate);
    push(tr("Linear Damping"), QStringLiteral("damping.linear"), after);
}

void SimulationSettingsModel::setAngularDamping(double rate) {
    simcore::WorldSettings after = settings();
    after.damping.angular = static_cast<float>(rate);
    push(tr("Angular Damping"), QStringLiteral("damping.angular"), after);
}

void SimulationSettingsModel::setPreset(int preset) {
    if (preset < 0 || preset >= static_cast<int>(simcore::kQualityPresets.size())) return;
    simcore::WorldSettings after = settings();
    simcore::applyQualityPreset(after, simcore::kQualityPresets[static_cast<std::size_t>(preset)]);
    push(tr("Quality %1").arg(presetNames().at(preset)), QStringLiteral("preset"), after);
}

void SimulationSettingsModel::setInteracting(bool interacting) {
    if (interacting == m_interacting) return;
    m_interacting = interacting;
    m_pushedWhileInteracting = false;
    emit interactingChanged(interacting);
}

void SimulationSettingsModel::push(const QString& what, const QString& key, const simcore::WorldSettings& after) {
    try {
        simcore::World probe;
        probe.setSettings(after);  // the engine's own validation, with its message
    } catch (const std::exception& e) {
        emit rejected(tr("%1 not changed: %2").arg(what, QString::fromStdString(e.what())));
        emit changed();  // controls showing the rejected value go back to the document's
        return;
    }
    const bool mergeable = m_interacting && std::exchange(m_pushedWhileInteracting, true);
    m_document->undoStack()->push(new ChangeSettings(m_document, tr("Change %1").arg(what), key, after, mergeable));
}

}  // namespace interplay
