#include "app/panels/accuracy_panel.h"

#include "app/document/scene_document.h"
#include "app/panels/accuracy_plot.h"
#include "app/panels/accuracy_sweep_model.h"
#include "app/panels/simulation_settings_model.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

namespace interplay {

AccuracyPanel::AccuracyPanel(SceneDocument* document, SimulationSettingsModel* settings, QWidget* parent)
    : QWidget(parent),
      m_document(document),
      m_settings(settings),
      m_model(new AccuracySweepModel(this)),
      m_spec(AccuracySweepModel::defaultSpec()),
      m_explore(new QPushButton(tr("Explore accuracy"))),
      m_cancel(new QPushButton(tr("Cancel"))),
      m_progress(new QProgressBar),
      m_seconds(new QDoubleSpinBox),
      m_measure(new QComboBox),
      m_status(new QLabel),
      m_plot(new AccuracyPlot(m_model)),
      m_table(new QTableView),
      m_details(new QLabel),
      m_apply(new QPushButton(tr("Apply"))) {
    setObjectName(QStringLiteral("accuracyPanel"));
    m_explore->setObjectName(QStringLiteral("exploreButton"));
    m_explore->setToolTip(tr("Sweep the scene as it is now over a grid of settings, against a converged reference run"));
    m_cancel->setObjectName(QStringLiteral("cancelButton"));
    m_progress->setObjectName(QStringLiteral("sweepProgress"));
    m_progress->setFormat(tr("%v of %m points"));
    m_seconds->setObjectName(QStringLiteral("secondsField"));
    m_seconds->setRange(0.05, 30.0);
    m_seconds->setDecimals(2);
    m_seconds->setSingleStep(0.5);
    m_seconds->setSuffix(tr(" s"));
    m_seconds->setValue(m_spec.seconds);
    m_seconds->setToolTip(tr("Simulated time per run: longer runs show more drift and take longer"));
    m_measure->setObjectName(QStringLiteral("measureChoice"));
    for (std::size_t m = 0; m < accuracy::kMeasureCount; ++m) {
        m_measure->addItem(AccuracySweepModel::measureLabel(static_cast<accuracy::Measure>(m)));
    }
    m_status->setObjectName(QStringLiteral("sweepStatus"));
    m_status->setWordWrap(true);
    m_table->setObjectName(QStringLiteral("pointsTable"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setWordWrap(false);
    m_table->setTextElideMode(Qt::ElideMiddle);
    m_details->setObjectName(QStringLiteral("pointDetails"));
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_apply->setObjectName(QStringLiteral("applyButton"));
    m_apply->setToolTip(tr("Make the chosen point's settings the scene's (one undoable edit)"));

    auto* controls = new QHBoxLayout;
    controls->addWidget(m_explore);
    controls->addWidget(m_cancel);
    controls->addWidget(m_progress, 1);
    controls->addWidget(new QLabel(tr("Run for")));
    controls->addWidget(m_seconds);
    controls->addWidget(new QLabel(tr("Error:")));
    controls->addWidget(m_measure);
    auto* side = new QWidget;
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(m_details, 1);
    sideLayout->addWidget(m_apply);
    auto* split = new QSplitter(Qt::Horizontal);
    split->addWidget(m_plot);
    split->addWidget(m_table);
    split->addWidget(side);
    split->setStretchFactor(0, 4);
    split->setStretchFactor(1, 3);
    split->setStretchFactor(2, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(m_status);
    layout->addWidget(split, 1);

    connect(m_explore, &QPushButton::clicked, this, &AccuracyPanel::explore);
    connect(m_cancel, &QPushButton::clicked, this, &AccuracyPanel::cancel);
    connect(m_apply, &QPushButton::clicked, this, &AccuracyPanel::applyChosen);
    connect(m_measure, &QComboBox::currentIndexChanged, this,
            [this](int index) { m_model->setMeasure(static_cast<accuracy::Measure>(index)); });
    connect(m_plot, &AccuracyPlot::rowClicked, this, &AccuracyPanel::choose);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) { choose(current.isValid() ? current.row() : -1); });
    connect(m_model, &AccuracySweepModel::progressChanged, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
        if (done == 0) m_status->setText(tr("Running the reference (a converged run)…"));
        else m_status->setText(tr("Sweeping the scene as it was at %1; editing it now does not change this sweep.")
                                   .arg(m_model->startedAt().toString(QStringLiteral("HH:mm:ss"))));
    });
    connect(m_model, &AccuracySweepModel::sweepEnded, this, &AccuracyPanel::sweepEnded);
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] { choose(-1); });
    updateControls();
}

void AccuracyPanel::setSpec(const accuracy::SweepSpec& spec) {
    m_spec = spec;
    m_seconds->setValue(spec.seconds);
}

void AccuracyPanel::explore() {
    m_spec.seconds = m_seconds->value();
    QString error;
    if (!m_model->start(m_document->scene(), m_spec, error)) m_status->setText(tr("Not started: %1").arg(error));
    updateControls();
}

void AccuracyPanel::cancel() {
    m_model->cancel();
    m_status->setText(tr("Cancelling…"));
    m_cancel->setEnabled(false);
}

void AccuracyPanel::sweepEnded(bool cancelled, const QString& error) {
    const QString when = m_model->startedAt().toString(QStringLiteral("HH:mm:ss"));
    if (!error.isEmpty()) m_status->setText(tr("The sweep failed: %1").arg(error));
    else if (cancelled)
        m_status->setText(tr("Cancelled: %1 of %2 points done, kept below (the scene as it was at %3).")
                              .arg(m_model->rowCount()).arg(m_model->gridSize()).arg(when));
    else
        m_status->setText(tr("%1 points for the scene as it was at %2. Hover a point for its figures, click it to choose it.")
                              .arg(m_model->rowCount()).arg(when));
    updateControls();
}

void AccuracyPanel::choose(int row) {
    if (row >= m_model->rowCount()) row = -1;
    m_chosenRow = row;
    m_plot->setChosenRow(row);
    if (row >= 0 && m_table->currentIndex().row() != row) m_table->selectRow(row);
    m_details->setText(row >= 0 ? m_model->describe(row) : tr("No point chosen."));
    updateControls();
}

void AccuracyPanel::applyChosen() {
    if (m_chosenRow < 0) return;
    const simcore::WorldSettings after = m_model->appliedTo(m_chosenRow, m_document->scene());
    m_settings->setSettings(tr("settings to an accuracy point"), after);
}

void AccuracyPanel::updateControls() {
    const bool running = m_model->isRunning();
    m_explore->setEnabled(!running);
    m_cancel->setEnabled(running);
    m_seconds->setEnabled(!running);
    m_progress->setVisible(running);
    m_apply->setEnabled(m_chosenRow >= 0);
}

}  // namespace interplay
