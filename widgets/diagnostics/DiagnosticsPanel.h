#pragma once

#include <QWidget>

class QLabel;
class QComboBox;
class QListWidget;

namespace drytwin::widgets {

class PlotStack;
class Workbench;

/// @brief The Diagnostics panel: the held-out moisture residual's ACF with its 95 % band and its
/// Welch PSD on log axes (paper Fig. 4), for any models overlaid, with Ljung-Box p-values; the
/// physics model's outlet-moisture error against an operating variable of the user's choice.
class DiagnosticsPanel : public QWidget {
    Q_OBJECT
public:
    explicit DiagnosticsPanel(Workbench& workbench, QWidget* parent = nullptr);
    PlotStack* acf() const { return m_acf; }
    PlotStack* psd() const { return m_psd; }
    QListWidget* models() const { return m_models; }
    PlotStack* scatter() const { return m_scatter; }
    PlotStack* crossCorrelation() const { return m_ccf; }

private:
    void fill();
    void redraw();
    void redrawScatter();
    void redrawCrossCorrelation();

    Workbench& m_workbench;
    QListWidget* m_models = nullptr;
    PlotStack* m_acf = nullptr;
    PlotStack* m_psd = nullptr;
    PlotStack* m_scatter = nullptr;
    PlotStack* m_ccf = nullptr;
    QComboBox* m_operating = nullptr;
    QLabel* m_tests = nullptr;
};

} // namespace drytwin::widgets
