#pragma once

#include "common/Workbench.h"

#include <QLabel>

namespace drytwin::widgets {

/// @brief A line under an action's button that shows, while the action waits behind another
/// job, what it waits for ("Queued — waits for “Learn the correction models”"), and is hidden
/// otherwise: a greyed-out button alone did not say whether the click was taken (issue #72 item 8).
class QueuedNote : public QLabel {
    Q_OBJECT
public:
    QueuedNote(Workbench& workbench, Action action, QWidget* parent = nullptr);

private:
    void refresh();

    Workbench& m_workbench;
    Action m_action;
};

} // namespace drytwin::widgets
