#pragma once

#include <QWidget>

class QLabel;
class QPushButton;

namespace drytwin::widgets {

class Workbench;

/// @brief The model's state in one paragraph, the same on every tab that uses the learnt parts
/// (Workbench::modelStateText), with a button that retrains stale parts: one model state, shown
/// the same everywhere (issue #26).
class ModelStateBar : public QWidget {
    Q_OBJECT
public:
    explicit ModelStateBar(Workbench& workbench, QWidget* parent = nullptr);
    QLabel* text() const { return m_text; }
    QPushButton* retrainButton() const { return m_retrain; }

private:
    void refresh();

    Workbench& m_workbench;
    QLabel* m_text = nullptr;
    QPushButton* m_retrain = nullptr;
};

} // namespace drytwin::widgets
