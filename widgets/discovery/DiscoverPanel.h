#pragma once

#include <QWidget>
#include <string>

class QLabel;
class QPushButton;
class QTabWidget;
class QTableWidget;
class QTextBrowser;

namespace drytwin::discovery {
struct Finding;
}

namespace drytwin::widgets {

class PlotStack;
class Workbench;

/// @brief The Discover panel: what the simulation gets wrong, the ranked causes with their
/// evidence, "Extend the model" in one click, and the before/after table and plots.
class DiscoverPanel : public QWidget {
    Q_OBJECT
public:
    explicit DiscoverPanel(Workbench& workbench, QWidget* parent = nullptr);
    QTableWidget* ranking() const { return m_ranking; }
    QTableWidget* gains() const { return m_gains; }
    QPushButton* extendButton() const { return m_extend; }
    QLabel* verdict() const { return m_verdict; }
    QTextBrowser* evidence() const { return m_evidence; }
    /// The evidence sentence of a finding in the window's language, from the finding's numbers.
    static QString evidenceText(const discovery::Finding& f);
    /// Against a reference: the outputs where the line moved by another amount than the model form says.
    static QString responseSizeText(const discovery::Finding& f);
    /// @brief Per-part consistency, transfer, onset and look-alikes of a finding, worded in the GUI's
    /// language.
    static QString specificityText(const discovery::Finding& f);
    /// @brief One of discovery's notes (engine/discovery/DiscoveryNotes.h) in the GUI's language;
    /// a note of another form (a newer engine's) is shown as it is.
    static QString noteText(const std::string& note);
    PlotStack* plots() const { return m_plots; }
    /// @brief The reference period's controls and what detection found against it.
    QPushButton* referenceButton() const { return m_referenceButton; }
    QLabel* referenceLabel() const { return m_referenceLabel; }
    QLabel* detection() const { return m_detection; }
    PlotStack* monitorPlots() const { return m_monitorPlots; }
    QTableWidget* contributions() const { return m_contributions; }

private:
    void show();
    void showReference();
    /// Detection against the reference: both detectors' verdicts, the monitor's T² and SPE with
    /// their limits, and each column's contribution after the onset.
    void showDetection();

    Workbench& m_workbench;
    QLabel* m_verdict = nullptr;
    QTableWidget* m_ranking = nullptr;
    QTableWidget* m_gains = nullptr;
    QLabel* m_gainsLabel = nullptr; ///< says when nothing was extended (before = after)
    QTextBrowser* m_evidence = nullptr;
    QPushButton* m_extend = nullptr;
    PlotStack* m_plots = nullptr;
    QPushButton* m_referenceButton = nullptr;
    QLabel* m_referenceLabel = nullptr;
    QLabel* m_detection = nullptr;
    PlotStack* m_monitorPlots = nullptr;
    QTableWidget* m_contributions = nullptr;
    QTabWidget* m_views = nullptr;
};

} // namespace drytwin::widgets
