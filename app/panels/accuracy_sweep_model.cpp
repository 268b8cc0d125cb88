#include "app/panels/accuracy_sweep_model.h"

#include "accuracy/sweep_files.h"

#include "simcore/io/scene_io.h"
#include "simcore/world/quality_preset.h"

#include <QThread>

#include <algorithm>
#include <cmath>

namespace interplay {

namespace {

QString toQString(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString formatFigure(double value) {
    if (std::isinf(value)) return AccuracySweepModel::tr("failed");
    return QString::number(value, 'g', 3);
}

}  // namespace

// What the worker hands back to the GUI thread in one piece.
struct AccuracySweepModel::Outcome {
    std::vector<accuracy::PointResult> points;
    bool cancelled = false;
    QString error;
};

AccuracySweepModel::AccuracySweepModel(QObject* parent) : QAbstractTableModel(parent) {}

AccuracySweepModel::~AccuracySweepModel() {
    m_cancel = true;
    join();
}

accuracy::SweepSpec AccuracySweepModel::defaultSpec() {
    accuracy::SweepSpec spec;
    // The library's default time steps, as files write them; fewer of the rest.
    const accuracy::Knob timeSteps = accuracy::defaultKnobs().front();
    spec.knobs = {timeSteps,
                  {"substeps", {"1", "2", "4"}},
                  {"solver.velocityIterations", {"1", "4"}}};
    spec.seconds = 1.0;
    spec.extraPoints.push_back({});  // the scene's own settings
    for (simcore::QualityPreset preset : simcore::kQualityPresets)
        spec.extraPoints.push_back({"preset=" + std::string(simcore::qualityPresetName(preset))});
    return spec;
}

bool AccuracySweepModel::start(const simcore::Scene& scene, const accuracy::SweepSpec& spec, QString& error) {
    if (m_running) {
        error = tr("A sweep is already running.");
        return false;
    }
    if (const std::optional<std::string> problem = accuracy::checkSpec(scene, spec)) {
        error = QString::fromStdString(*problem);
        return false;
    }
    join();
    beginResetModel();
    m_scene = scene;
    m_points.clear();
    m_labels.clear();
    m_fronts = {};
    endResetModel();
    std::vector<accuracy::GridPoint> grid;
    std::vector<simcore::WorldSettings> gridSettings;
    for (accuracy::GridPoint& point : accuracy::gridPoints(spec)) {
        simcore::Scene applied = scene;
        for (const std::string& a : point.assignments) simcore::applySettingOverride(applied, a);
        if (std::find(gridSettings.begin(), gridSettings.end(), applied.settings) != gridSettings.end()) continue;
        gridSettings.push_back(applied.settings);
        grid.push_back(std::move(point));
    }
    m_gridSize = grid.size();
    m_startedAt = QDateTime::currentDateTime();
    m_cancel = false;
    m_cancelled = false;
    m_running = true;
    emit runningChanged(true);
    emit progressChanged(0, static_cast<int>(m_gridSize));

    // One core stays with the editor; the timings are then as noisy as `--jobs N` makes them.
    const int jobs = std::max(1, QThread::idealThreadCount() - 1);
    m_worker = std::thread([this, spec, grid, jobs] {
        auto outcome = std::make_shared<Outcome>();
        std::string referenceError;
        const std::optional<accuracy::Reference> reference = accuracy::runReference(m_scene, spec, referenceError, &m_cancel);
        if (reference) {
            accuracy::SweepRunOptions options;
            options.jobs = jobs;
            options.cancel = &m_cancel;
            options.timing = "in the editor, " + std::to_string(jobs) + " points at once";
            options.progress = [this](const accuracy::SweepProgress& p) {
                QMetaObject::invokeMethod(this, [this, done = int(p.done), total = int(p.total)] {
                    emit progressChanged(done, total);
                }, Qt::QueuedConnection);
            };
            outcome->points = accuracy::runSweep(m_scene, spec, grid, *reference, options);
        } else if (!m_cancel) {
            outcome->error = QString::fromStdString(referenceError);
        }
        outcome->cancelled = m_cancel;
        QMetaObject::invokeMethod(this, [this, outcome] { finish(outcome); }, Qt::QueuedConnection);
    });
    return true;
}

void AccuracySweepModel::cancel() {
    if (m_running) m_cancel = true;
}

void AccuracySweepModel::join() {
    if (m_worker.joinable()) m_worker.join();
}

void AccuracySweepModel::finish(std::shared_ptr<Outcome> outcome) {
    join();
    beginResetModel();
    m_points = std::move(outcome->points);
    m_labels = accuracy::pointLabels(m_scene, m_points);
    m_fronts = accuracy::fronts(m_points);
    endResetModel();
    m_running = false;
    m_cancelled = outcome->cancelled;
    emit runningChanged(false);
    emit sweepEnded(outcome->cancelled, outcome->error);
}

QString AccuracySweepModel::measureLabel(accuracy::Measure measure) {
    return QStringLiteral("%1 (%2)").arg(toQString(accuracy::measureTitle(measure)), toQString(accuracy::measureUnit(measure)));
}

QString AccuracySweepModel::displayAssignment(const std::string& assignment) {
    const QString text = QString::fromStdString(assignment);
    const qsizetype equals = text.indexOf(QLatin1Char('='));
    if (text.left(equals) != QStringLiteral("timeStep")) return text;
    // Steps are chosen as rates: 1/60 reads better than 0.016666668.
    bool ok = false;
    const double step = text.mid(equals + 1).toDouble(&ok);
    const double rate = ok && step > 0.0 ? 1.0 / step : 0.0;
    if (rate >= 1.0 && std::abs(rate - std::round(rate)) < 1e-3 * rate)
        return QStringLiteral("timeStep=1/%1").arg(std::llround(rate));
    return text;
}

void AccuracySweepModel::setMeasure(accuracy::Measure measure) {
    if (measure == m_measure) return;
    m_measure = measure;
    if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
}

int AccuracySweepModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_points.size());
}

int AccuracySweepModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : FirstMeasureColumn + static_cast<int>(accuracy::kMeasureCount);
}

bool AccuracySweepModel::onFront(int row, accuracy::Measure measure) const {
    const std::vector<std::size_t>& front = m_fronts[static_cast<std::size_t>(measure)];
    return std::find(front.begin(), front.end(), static_cast<std::size_t>(row)) != front.end();
}

QStringList AccuracySweepModel::labels(int row) const {
    QStringList names;
    for (const std::string& label : m_labels[static_cast<std::size_t>(row)]) names << QString::fromStdString(label);
    return names;
}

QString AccuracySweepModel::describe(int row) const {
    const accuracy::PointResult& p = point(row);
    QStringList lines;
    lines << (p.point.assignments.empty() ? tr("the scene's own settings") : data(index(row, SettingsColumn)).toString());
    if (const QStringList names = labels(row); !names.isEmpty()) lines << tr("(%1)").arg(names.join(QStringLiteral(", ")));
    lines << tr("%1 ms/step, %2 ms per simulated second").arg(formatFigure(p.msPerStep), formatFigure(p.msPerSimulatedSecond));
    for (std::size_t m = 0; m < accuracy::kMeasureCount; ++m) {
        const auto measure = static_cast<accuracy::Measure>(m);
        lines << tr("%1: %2 %3").arg(toQString(accuracy::measureTitle(measure)), formatFigure(p.measures[m]),
                                     toQString(accuracy::measureUnit(measure)));
    }
    return lines.join(QLatin1Char('\n'));
}

simcore::WorldSettings AccuracySweepModel::appliedTo(int row, const simcore::Scene& scene) const {
    simcore::Scene applied = scene;
    // The assignments passed checkSpec when the sweep started: each one parses and is in range.
    for (const std::string& assignment : point(row).point.assignments) simcore::applySettingOverride(applied, assignment);
    return applied.settings;
}

QVariant AccuracySweepModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const accuracy::PointResult& p = point(index.row());
    const double error = p.measures[static_cast<std::size_t>(m_measure)];
    switch (role) {
    case OnFrontRole: return onFront(index.row(), m_measure);
    case ErrorRole: return error;
    case CostRole: return p.msPerSimulatedSecond;
    case Qt::ToolTipRole: return describe(index.row());
    case Qt::TextAlignmentRole:
        return index.column() >= MsPerStepColumn ? QVariant(Qt::AlignRight | Qt::AlignVCenter) : QVariant();
    case Qt::DisplayRole: break;
    default: return {};
    }
    switch (index.column()) {
    case SettingsColumn: {
        QStringList assignments;
        for (const std::string& a : p.point.assignments) assignments << displayAssignment(a);
        return assignments.isEmpty() ? tr("(scene)") : assignments.join(QStringLiteral(", "));
    }
    case LabelsColumn: return labels(index.row()).join(QStringLiteral(", "));
    case MsPerStepColumn: return formatFigure(p.msPerStep);
    case MsPerSecondColumn: return formatFigure(p.msPerSimulatedSecond);
    default: return formatFigure(p.measures[static_cast<std::size_t>(index.column() - FirstMeasureColumn)]);
    }
}

QVariant AccuracySweepModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case SettingsColumn: return tr("Settings");
    case LabelsColumn: return tr("Marks");
    case MsPerStepColumn: return tr("ms/step");
    case MsPerSecondColumn: return tr("ms per sim. s");
    default: {
        const auto measure = static_cast<accuracy::Measure>(section - FirstMeasureColumn);
        return tr("%1 (%2)").arg(toQString(accuracy::measureKey(measure)), toQString(accuracy::measureUnit(measure)));
    }
    }
}

}  // namespace interplay
