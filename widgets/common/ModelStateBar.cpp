#include "common/ModelStateBar.h"

#include "common/Workbench.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace drytwin::widgets {

ModelStateBar::ModelStateBar(Workbench& workbench, QWidget* parent)
    : QWidget(parent), m_workbench(workbench) {
    m_text = new QLabel;
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_retrain = new QPushButton(tr("Retrain the stale models"));
    m_retrain->setToolTip(tr("Learn the correction models again on the loaded data, with the settings they "
                             "were last learnt with"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_retrain, 0, Qt::AlignTop);
    setWhatsThis(
        tr("The model every tab works with: whether the physics model is calibrated or extended, and "
           "for each learnt correction model the data it was learnt on, or why it no longer fits "
           "the physics model (stale) and must be learnt again."));
    connect(m_retrain, &QPushButton::clicked, &m_workbench, &Workbench::retrain);
    connect(&m_workbench, &Workbench::modelStateChanged, this, &ModelStateBar::refresh);
    connect(&m_workbench, &Workbench::modelChanged, this, &ModelStateBar::refresh);
    connect(&m_workbench, &Workbench::dataChanged, this, &ModelStateBar::refresh);
    connect(&m_workbench.jobs(), &JobRunner::busyChanged, this, &ModelStateBar::refresh);
    // A retraining queued or started: the paragraph says so instead of "retrain it" (issue #72 item 8).
    connect(&m_workbench, &Workbench::runningChanged, this, &ModelStateBar::refresh);
    connect(&m_workbench.jobs(), &JobRunner::started, this, &ModelStateBar::refresh);
    refresh();
}

void ModelStateBar::refresh() {
    m_text->setText(m_workbench.modelStateText());
    m_retrain->setVisible(m_workbench.hasStaleParts() && !m_workbench.isRunning(Action::Train));
    m_retrain->setEnabled(m_workbench.hasData() && !m_workbench.jobs().busy());
}

} // namespace drytwin::widgets
