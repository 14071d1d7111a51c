#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "control/ClosedLoop.h"
#include "data/Batch.h"
#include "hybrid/HybridModel.h"
#include "plant/Mechanisms.h"

#include <memory>
#include <string>
#include <vector>

namespace drytwin::training {

/// @brief What happened in a session, in order: the log that makes a session replayable. Times
/// are session seconds (after the warm-up); a restore sends the clock back, so times are not
/// monotonic across one.
enum class EventType { Setpoint, Controller, Fault, Freeze, Resume, Snapshot, Restore, Answer };
const char* eventTypeName(EventType t);

struct SessionEvent {
    double atS = 0;
    EventType type = EventType::Setpoint;
    double value = 0;  ///< setpoint [% wb] or fault strength (in the mechanism's unit)
    double onsetS = 0; ///< fault: when it starts to act [session s]
    std::string text;  ///< controller name, cause, or snapshot label
};

/// @brief A fault the instructor set, hidden from the trainee's view.
struct InjectedFault {
    plant::Mechanism mechanism = plant::Mechanism::HeatTransferFouling;
    double strength = 0;
    double onsetS = 0;      ///< session time from which it acts
    double injectedAtS = 0; ///< session time at which the instructor set it
};

/// @brief A cause the trainee named (a CONTRACT.md §4 name, or "no_fault").
struct TraineeAnswer {
    double atS = 0;
    std::string cause;
};

/// @brief One second of the session as the operator's screens show it (no truth, no faults).
struct LiveSample {
    double timeS = 0;
    double xOutPct = 0;     ///< measured outlet moisture [% wb]
    double setpointPct = 0; ///< the operator's setpoint [% wb]
    double hotAirSetpointC = 0;
    double hotAirC = 0;
    double feedKgH = 0;
    double xInPct = 0;
    double tOutC = 0;
    double xOutTruePct = 0; ///< the product's true moisture: for the instructor and the score only
};

/// @brief How the trainee did on one fault.
struct FaultScore {
    InjectedFault fault;
    bool found = false;
    double timeToFindS = 0;         ///< from the onset to the first right answer (found only)
    double offSpecPctWhileOpen = 0; ///< share of seconds out of the band from onset to the answer (or now)
    double points = 0;              ///< of 100
    /// Not found yet and still within the time a trainee fairly needs to react
    /// (kReactionTimeS from its onset): not scored yet, so not counted in the session's points.
    bool withinReactionTime = false;
    double reactionTimeLeftS = 0; ///< how long it stays so [s]
};

/// @brief The time from a fault's onset within which it is not scored unless found: noticing,
/// recording and diagnosing take that long (discovery names few causes on less than half an hour
/// of recording, docs/training.md), and the time bonus fades over the same half hour.
inline constexpr double kReactionTimeS = 1800;

/// @brief The session's score (docs/training.md gives the rule).
struct TrainingScore {
    std::vector<FaultScore> faults; ///< faults that have acted by now (scored or within their reaction time)
    int wrongAnswers = 0;           ///< causes named that were not acting at the time
    double offSpecPct = 0;          ///< share of session seconds with true X_out out of the band [%]
    double offSpecKg = 0;           ///< product (wet feed) that left out of the band [kg]
    double points = 0;              ///< 0..100
    std::string summary;            ///< one line in English (the GUI words its own)
};

/// @brief A snapshot's label and time (the state itself stays inside the session).
struct SnapshotInfo {
    std::string label;
    double atS = 0;
};

/// @brief A training session: the virtual plant live, driven second by second by its PI loop
/// or an MPC of the model, with an operator who moves the setpoint and switches controllers,
/// an instructor who freezes, snapshots, restores and injects faults of CONTRACT.md §4 (in the
/// plant's own forms, never the model's), and a trainee who names causes. Deterministic: the
/// same scenario (seed) and the same events give the same record, which is what makes a saved
/// session replayable. Not thread-safe: one thread drives it.
class TrainingSession {
public:
    /// @brief Starts the line of @p scenario and runs its warm-up under the PI loop; the session's
    /// clock starts after it. The scenario's length is the session's longest; its setpoint steps
    /// are the operator's to make and are ignored, its input changes and mechanisms act.
    /// @p model serves the MPC controllers (may hold only physics: then only "pbm" and "pi").
    static Expected<TrainingSession> start(const control::Scenario& scenario,
                                           std::shared_ptr<const hybrid::HybridModel> model);
    ~TrainingSession();
    TrainingSession(TrainingSession&&) noexcept;
    TrainingSession& operator=(TrainingSession&&) noexcept;

    /// @brief Runs up to @p seconds further (not while frozen, not past the end); returns how
    /// many were run. @p progress may stop it between seconds.
    std::size_t advance(std::size_t seconds, const Progress& progress = {});
    double timeS() const;
    double endS() const;
    bool finished() const;

    // The operator.
    Status setSetpoint(double pct);
    double setpointPct() const;
    Status setController(control::ControllerKind kind);
    control::ControllerKind controller() const;
    /// @brief Why the last MPC decision fell back, if it did (empty otherwise).
    const std::string& controllerNote() const;

    // The instructor.
    /// @brief A fault acting from @p onsetS (session s, not in the past) at @p strength.
    Status injectFault(plant::Mechanism mechanism, double strength, double onsetS);
    void freeze();
    void resume();
    bool frozen() const;
    Status takeSnapshot(const std::string& label);
    /// @brief Goes back to a snapshot: the line, the record, the faults and the answers as they
    /// were then. The log keeps what happened since (the session file shows the whole story).
    Status restore(const std::string& label);
    std::vector<SnapshotInfo> snapshots() const;
    const std::vector<InjectedFault>& faults() const;

    // The trainee.
    /// @brief Names a cause now: a CONTRACT.md §4 name or "no_fault".
    Status answer(const std::string& cause);
    const std::vector<TraineeAnswer>& answers() const;

    // What was recorded.
    const std::vector<SessionEvent>& events() const;
    /// @brief The session part, one entry per second.
    const std::vector<LiveSample>& trace() const;
    TrainingScore score() const;
    /// @brief The line's record, warm-up included, as a batch file would hold it.
    data::Batch recording(const std::string& batchId) const;
    const control::Scenario& scenario() const;

private:
    struct Impl;
    explicit TrainingSession(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

} // namespace drytwin::training
