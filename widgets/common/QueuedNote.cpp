#include "common/QueuedNote.h"

namespace drytwin::widgets {

QueuedNote::QueuedNote(Workbench& workbench, Action action, QWidget* parent)
    : QLabel(parent), m_workbench(workbench), m_action(action) {
    setWordWrap(true);
    setStyleSheet(QStringLiteral("color: #5a5a5a;"));
    // Queued, started (the job ahead ended) and finished all change what it says.
    connect(&m_workbench, &Workbench::runningChanged, this, &QueuedNote::refresh);
    connect(&m_workbench.jobs(), &JobRunner::started, this, &QueuedNote::refresh);
    connect(&m_workbench.jobs(), &JobRunner::busyChanged, this, &QueuedNote::refresh);
    refresh();
}

void QueuedNote::refresh() {
    const QString text = m_workbench.queuedText(m_action);
    setText(text);
    setVisible(!text.isEmpty());
}

} // namespace drytwin::widgets
