#pragma once

#include "common/JobRunner.h"
#include "workflow/Session.h"

#include <QObject>
#include <QString>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class QAbstractButton;
class QWidget;

namespace drytwin::widgets {

/// @brief Why learnt parts went stale: English keys, kept as they are in LearntPart::staleBecause and
/// in projects, and worded in the user's language by staleReasonText() when shown (a project saved
/// in one language reads back in the other without English left in the sentence).
namespace staleReason {
inline constexpr const char* kCalibrated =
    QT_TRANSLATE_NOOP("StaleReason", "the physics model was calibrated after it was learnt");
inline constexpr const char* kExtended =
    QT_TRANSLATE_NOOP("StaleReason", "the model was extended by discovery");
} // namespace staleReason

/// @brief A stale reason (a staleReason key, or text kept from before they were keys) in the
/// user's language.
QString staleReasonText(const QString& reason);

/// @brief How a learnt part of the model stands: not learnt, learnt on the present physics model,
/// or learnt on a physics model that has since changed (calibrated, extended) and dropped with it.
enum class PartState { Absent, Current, Stale };

/// @brief One learnt part of the model (PGRL-CC, the external-input residual, the LSTM) as every
/// tab shows it: whether it exists, what data it was learnt on, and why it is stale.
struct LearntPart {
    control::ControllerKind kind = control::ControllerKind::PgrlCc;
    PartState state = PartState::Absent;
    QString learntOn; ///< the data set's label, or "model file x.json", as worded when learnt
    /// Learnt on a data set: its folder or file name and batch count, worded when shown
    /// (learntOnText()), so that a project saved in English reads back in Chinese; -1: not a data set.
    QString learntOnName;
    int learntOnBatches = -1;
    QString staleBecause; ///< the action that made it stale: a staleReason key (staleReasonText() words it)

    /// @brief What it was learnt on, in the user's language.
    QString learntOnText() const;

    static LearntPart absent(control::ControllerKind kind) {
        LearntPart part;
        part.kind = kind;
        return part;
    }
};

/// @brief The actions a button starts, for Workbench::isRunning() (a running action's button is
/// disabled: a second click would queue a duplicate run).
enum class Action { Other, Load, Simulate, Calibrate, Train, Evaluate, Discover, Mpc, Ablation, Generate };

/// @brief The engine's progress stage key an action reports as its own ("evaluate" for Evaluate;
/// the stages inside it, such as "simulate", are its parts); empty for Action::Other.
QString progressStageOf(Action action);

/// @brief A data set opened in this window: the loaded one and those opened beside it (a training
/// recording to diagnose), any of which can be switched back to.
struct DataSetEntry {
    QString path;
    QString mappingPath;
    QString label;    ///< as worded when it was opened (kept for a project that gives no count)
    int batches = -1; ///< its batch count (-1: unknown)

    /// @brief Its name and batch count in the user's language ("shift.csv (2 batches)").
    QString labelText() const;
};

/// @brief A data set's name and batch count as the tabs say it: "demo (10 batches)".
QString dataSetLabelText(const QString& name, int batches);

/// @brief What to do with learnt parts an action is about to make stale.
enum class AfterInvalidation { Ask, Retrain, KeepStale };

/// @brief The GUI's side of the workflow Session: starts every action as a job on the engine
/// thread (JobRunner) and keeps, on the GUI thread, copies of what the panels show (data set,
/// model, latest results). Panels ask it for actions and listen to its signals; none of them
/// touches the Session or computes anything (ARCHITECTURE.md rules 4 and 5). A second request
/// while one runs is queued behind it (the status bar says so).
class Workbench : public QObject {
    Q_OBJECT
public:
    explicit Workbench(QObject* parent = nullptr);

    JobRunner& jobs() { return m_jobs; }
    /// @brief True while an action of this kind is queued or running.
    bool isRunning(Action action) const;
    /// @brief The action a queued or running job was started for (Action::Other when unknown).
    Action actionOf(JobId id) const;
    /// @brief Keeps @p button disabled while its action is queued or running.
    void bindButton(QAbstractButton* button, Action action);
    bool hasData() const { return m_dataSet != nullptr; }
    std::shared_ptr<const data::DataSet> dataSet() const { return m_dataSet; }
    const std::vector<data::SiBatch>& siBatches() const { return m_si; }
    const data::DataSetSummary& summary() const { return m_summary; }
    const hybrid::HybridModel& model() const { return m_model; }
    const workflow::LatestResults& latest() const { return m_latest; }
    QString dataPath() const { return m_dataPath; }
    QString modelPath() const { return m_modelPath; }
    QString mappingPath() const { return m_mappingPath; }
    /// @brief The reference period discovery compares the data with (a batch file or folder
    /// when the line ran as it should; empty: the data are judged alone). A project keeps it.
    QString referencePath() const { return m_referencePath; }
    void setReferencePath(const QString& path);
    /// @brief Offers @p referencePath as the reference period for the data set at @p dataPath (a
    /// training recording's commissioning runs): Discover's reference menu names it first.
    void suggestReference(const QString& dataPath, const QString& referencePath);
    /// @brief The reference offered for the data set at @p dataPath (default: the loaded one); "" for none.
    QString suggestedReference(const QString& dataPath = {}) const;
    /// @brief The loaded data set in a few words ("plant: 10 batches"), for "learnt on" and
    /// "results of" lines; empty without data.
    QString dataSetLabel() const;

    /// @brief The data sets opened in this window, in the order they were first opened.
    const std::vector<DataSetEntry>& dataSets() const { return m_dataSets; }
    /// @brief The index of the loaded one in dataSets() (-1: none).
    int currentDataSet() const;
    /// @brief Loads the data set @p index again; its results come back when the model has not
    /// changed since they were computed.
    void switchDataSet(int index);
    /// @brief Puts back the data sets a project had open beside the loaded one (those whose file or
    /// folder still exists), so that they can be switched to again; the loaded one is opened with
    /// openData().
    void restoreDataSets(const std::vector<DataSetEntry>& entries);

    /// @brief The learnt parts, PGRL-CC first, as every tab shows them.
    const std::array<LearntPart, 3>& learntParts() const { return m_parts; }
    const LearntPart& learntPart(control::ControllerKind kind) const;
    /// @brief True when the model holds a usable (current) prediction model of this kind; the
    /// physics model and the PI loop always exist.
    bool hasController(control::ControllerKind kind) const;
    bool hasStaleParts() const;
    /// @brief One paragraph on the model's state: calibrated or not, extended by which causes,
    /// each learnt part with the data it was learnt on or why it is stale.
    QString modelStateText() const;
    /// @brief Asks before an action that makes learnt parts stale (calibrate, extend the model):
    /// nothing when there are none; otherwise a dialog (or the policy set below). Returns
    /// std::nullopt when the user cancels, true to retrain them afterwards, false to keep them
    /// marked stale.
    /// @p newModel: the model the action will put in place (extend), whose missing parts are the
    /// ones that go stale; none: every learnt part (calibrate).
    std::optional<bool> confirmInvalidation(QWidget* parent, const QString& action,
                                            const hybrid::HybridModel* newModel = nullptr);
    /// @brief The question confirmInvalidation() asks: what @p newModel adds (causes, refitted
    /// parameters, learnt parts it brings) and which learnt parts go stale.
    QString invalidationQuestion(const QString& action, const hybrid::HybridModel* newModel = nullptr) const;
    /// @brief Answers confirmInvalidation() without a dialog (tests, scripted runs).
    void setInvalidationPolicy(AfterInvalidation policy) { m_invalidationPolicy = policy; }
    /// @brief Retrains the learnt parts with the settings they were last trained with (the
    /// defaults when none): "retrain on request".
    void retrain();

    /// @brief Loads data; @p mappingPath: a column mapping file (empty: the contract's names).
    void openData(const QString& path, const QString& mappingPath = {});
    /// @p parts: the learnt parts' states a project saved with this model, put back once it is read.
    void openModel(const QString& path, const std::optional<std::array<LearntPart, 3>>& parts = std::nullopt);
    /// @p doneMessage: the status line when it is written (default "Model saved to …").
    void saveModel(const QString& path, const QString& doneMessage = {});
    /// @brief Shows results read back from a project (panels redraw from them, nothing re-runs).
    /// @p otherDataSets: the results of the other data sets the project had open, by path; they
    /// come back when one is switched to, as long as the model is the project's.
    void restoreResults(const workflow::LatestResults& results,
                        const std::map<QString, workflow::LatestResults>& otherDataSets = {});
    /// @brief The results of the data sets other than the loaded one that still belong to the
    /// present model (a project keeps them beside its own), by path.
    std::map<QString, workflow::LatestResults> otherDataSetResults() const;
    /// @brief For a button whose action is queued behind another job: "Queued — waits for …";
    /// empty when the action is not waiting (not asked for, or running now).
    QString queuedText(Action action) const;
    /// @brief True while an action of this kind is running now (not merely queued).
    bool isRunningNow(Action action) const;
    /// @brief Puts back the learnt parts' states a project saved (after its model is open).
    void restoreLearntParts(const std::array<LearntPart, 3>& parts);
    /// @brief Sets a physics parameter (checked against its bounds on the engine thread).
    void setParameter(properties::Param param, double value);
    /// @brief Replaces the session's model (undo, "extend the model").
    /// @p why: the action, when it replaces the physics the learnt parts sat on (learnt parts the
    /// new model lacks become stale for it); @p retrainAfter: retrain them when it is done.
    void setModel(const hybrid::HybridModel& model, const QString& why = {}, bool retrainAfter = false);
    void simulate();
    /// @brief Simulates the data with the physics parameters the latest calibration started from
    /// (calibrationStart() then holds it; latest().simulate is left alone), for the calibration's
    /// before/after plot, also after a project is reopened. Nothing without a calibration.
    void simulateCalibrationStart();
    /// @brief The simulation with the parameters before the latest calibration (empty until
    /// simulateCalibrationStart() has run for it).
    const std::optional<workflow::SimulateResult>& calibrationStart() const { return m_calibrationStart; }
    /// @brief Calibrates; learnt parts become stale (the session drops them), and are retrained
    /// when it is done if @p retrainAfter.
    void calibrate(const workflow::CalibrateOptions& options, bool retrainAfter = false);
    /// @brief Asks a running calibration to stop and keep its best parameters so far.
    void stopKeepBest();
    void train(const workflow::TrainOptions& options);
    void evaluate();
    void discover();
    void runMpc(const workflow::MpcOptions& options);
    /// @brief The ablation table (paper Table 3) on the session's model.
    void ablation();
    /// @brief Writes virtual-plant batches into a folder and opens them.
    void generate(const workflow::GenerateOptions& options);
    /// @brief Cancels everything queued or running.
    void cancelAll() { m_jobs.cancelAll(); }

Q_SIGNALS:
    void dataChanged();
    void modelChanged();
    /// @brief Results were put back from a project, or the views must be redrawn from the
    /// Workbench's state (every panel shows what latest() holds).
    void resultsRestored();
    /// @brief The list of opened data sets changed.
    void dataSetsChanged();
    /// @brief The learnt parts' states changed (learnt, dropped, opened from a file).
    void modelStateChanged();
    /// @brief The user changed the model (a parameter edited, the model extended or replaced):
    /// a project saved before no longer holds it.
    void modelEdited();
    void simulated();
    /// @brief calibrationStart() is ready.
    void calibrationStartSimulated();
    void calibrated();
    /// @brief A calibration progress report: evaluations so far and the best loss.
    void calibrationProgress(double fraction, double bestLoss);
    void trained();
    void evaluated();
    void discovered();
    /// @brief The reference period was set or cleared.
    void referenceChanged();
    void mpcFinished();
    void ablationFinished();
    /// @brief An action failed or was cancelled; @p message is worded for the user.
    void failed(const QString& action, const QString& message, bool cancelled);
    /// @brief Loading data failed; what was loaded before is unchanged.
    /// @p mappingMayHelp: a single file whose columns were not recognised (a historian export,
    /// foreign names): the column mapping would load it.
    void dataLoadFailed(const QString& message, const QString& path = {}, bool mappingMayHelp = false);
    /// @brief A line for the status bar.
    void status(const QString& text);
    /// @brief A line for the status bar while jobs run ("X is queued …"), gone when they are done.
    void queued(const QString& text);
    /// @brief An action was queued or finished (isRunning() changed).
    void runningChanged();
    /// @brief An action finished (successfully or not), for scripts and tests.
    void actionFinished(const QString& action, bool ok);

private:
    template <class R, class Work, class Done>
    JobId start(Action kind, const QString& action, Work work, Done done,
                std::function<void(const QString&, const Error&)> onFailure = {});
    /// Refreshes the GUI copy of the model after an action that may change it; @p why names
    /// the action, for the parts it drops ("the physics model was calibrated").
    void fetchModel(const QString& why = {}, const QString& learntOn = {}, bool fromFile = false,
                    const std::optional<std::array<LearntPart, 3>>& parts = std::nullopt);
    /// Takes @p model as the GUI copy and updates the learnt parts: a part the model holds and did
    /// not before, or any it holds when @p learntOn is given, is current (learnt on @p learntOn);
    /// one it no longer holds is stale for @p why (absent when no why, or @p fromFile).
    void takeModel(const hybrid::HybridModel& model, const QString& why, const QString& learntOn,
                   bool fromFile = false);

    JobRunner m_jobs;
    std::shared_ptr<const data::DataSet> m_dataSet;
    std::vector<data::SiBatch> m_si;
    data::DataSetSummary m_summary;
    hybrid::HybridModel m_model;
    workflow::LatestResults m_latest;
    QString m_dataPath, m_modelPath, m_mappingPath, m_referencePath;
    JobId m_calibrationJob = 0;
    std::map<Action, int> m_running;      ///< queued or running jobs per action
    std::map<JobId, Action> m_jobActions; ///< the action of each queued or running job
    std::optional<workflow::SimulateResult> m_calibrationStart;
    std::array<LearntPart, 3> m_parts{LearntPart::absent(control::ControllerKind::PgrlCc),
                                      LearntPart::absent(control::ControllerKind::ExtInputResidual),
                                      LearntPart::absent(control::ControllerKind::Lstm)};
    AfterInvalidation m_invalidationPolicy = AfterInvalidation::Ask;
    std::optional<workflow::TrainOptions> m_lastTrainOptions;
    std::vector<DataSetEntry> m_dataSets;
    /// The results each data set had when another was loaded, with the model revision they were
    /// computed with (restored only for the same revision).
    struct StashedResults {
        workflow::LatestResults results;
        int modelRevision = 0;
    };
    std::map<QString, StashedResults> m_stash;
    std::map<QString, QString> m_suggestedReferences; ///< by data set path
    /// A project's other data sets' results were put in the stash before its model file was read:
    /// the model that reading brings is the one they were made with.
    bool m_stashAwaitsProjectModel = false;
    int m_modelRevision = 0; ///< counts changes of the model
};

} // namespace drytwin::widgets
