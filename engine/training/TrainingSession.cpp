#include "training/TrainingSession.h"

#include "common/Units.h"
#include "plant/PlantExport.h"
#include "plant/PlantLine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drytwin::training {

using control::ControllerKind;

namespace {

/// A cause that "found" a fault needs a right answer within this time for the full time bonus
/// to fade to zero (docs/training.md): half an hour of a shift, the reaction time.
constexpr double kTimeBonusFadeS = kReactionTimeS;
constexpr double kFoundPoints = 60;
constexpr double kTimePoints = 25;
constexpr double kBandPoints = 15;
constexpr double kWrongAnswerPenalty = 10;

std::string mechanismName(plant::Mechanism m) {
    return std::string(plant::info(m).name);
}

} // namespace

const char* eventTypeName(EventType t) {
    switch (t) {
    case EventType::Setpoint:
        return "setpoint";
    case EventType::Controller:
        return "controller";
    case EventType::Fault:
        return "fault";
    case EventType::Freeze:
        return "freeze";
    case EventType::Resume:
        return "resume";
    case EventType::Snapshot:
        return "snapshot";
    case EventType::Restore:
        return "restore";
    case EventType::Answer:
        return "answer";
    }
    return "setpoint";
}

/// Everything that a restore brings back. The line draws its noise from `random`, which lives
/// on the heap so that the pointer the line keeps survives moves of the state.
struct LineState {
    std::unique_ptr<plant::PlantRandom> random;
    std::unique_ptr<control::ControlledLine> line;
    double setpointPct = 13;
    ControllerKind controller = ControllerKind::Pi;
    std::vector<LiveSample> trace;
    std::vector<InjectedFault> faults;
    std::vector<TraineeAnswer> answers;

    LineState copy() const {
        LineState c;
        c.random = std::make_unique<plant::PlantRandom>(*random);
        c.line = std::make_unique<control::ControlledLine>(line->clone(*c.random));
        c.setpointPct = setpointPct;
        c.controller = controller;
        c.trace = trace;
        c.faults = faults;
        c.answers = answers;
        return c;
    }
};

struct TrainingSession::Impl {
    control::Scenario scenario;
    std::shared_ptr<const hybrid::HybridModel> model;
    LineState state;
    std::vector<std::pair<SnapshotInfo, LineState>> snapshots;
    std::vector<SessionEvent> events;
    std::unique_ptr<control::MpcController> mpc; ///< for state.controller; rebuilt after a switch or restore
    std::string controllerNote;
    bool frozen = false;
    std::size_t warm = 0;
    std::size_t total = 0;

    double now() const { return static_cast<double>(state.line->sample()) - static_cast<double>(warm); }

    void log(EventType type, double value = 0, double onsetS = 0, std::string text = {}) {
        events.push_back({now(), type, value, onsetS, std::move(text)});
    }

    Status buildMpc(ControllerKind kind) {
        std::string missing;
        auto forecaster = control::forecasterFor(kind, *model, missing);
        if (!forecaster) {
            return Error{ErrorKind::BadInput, std::string("controller ") + control::controllerName(kind),
                         missing};
        }
        auto mpcNew = std::make_unique<control::MpcController>(std::move(forecaster), control::MpcSettings{},
                                                               model->parameters[properties::Param::tau_act]);
        if (mpcNew->historyNeeded() > warm) {
            return Error{ErrorKind::BadInput, std::string("controller ") + control::controllerName(kind),
                         "needs " + std::to_string(mpcNew->historyNeeded()) +
                             " s of history; the scenario's warm-up is shorter"};
        }
        mpc = std::move(mpcNew);
        return Status{};
    }

    /// One second of the line under the controller in charge.
    void step() {
        auto& st = state;
        const bool warmingUp = st.line->warmingUp();
        const control::ControlledLine::Second second =
            st.line->step(st.controller == ControllerKind::Pi ? nullptr : mpc.get(), st.setpointPct);
        if (second.decision) {
            controllerNote = second.decision->fallback ? second.decision->fallbackReason : std::string();
        }
        if (warmingUp) {
            return;
        }
        const auto& rec = st.line->line().record();
        LiveSample live;
        live.timeS = now() - 1; // the second just run
        live.xOutPct = second.sample.xOutPct;
        live.setpointPct = st.setpointPct;
        live.hotAirSetpointC = units::kelvinToCelsius(second.setpointK);
        live.hotAirC = units::kelvinToCelsius(second.hotAirK);
        live.tOutC = units::kelvinToCelsius(second.sample.tOutK);
        live.xOutTruePct = second.sample.xOutTruePct;
        live.feedKgH = units::kgPerSToKgPerHour(rec.feedKgPerS.back());
        live.xInPct = units::dryToWetPct(rec.xInDb.back());
        st.trace.push_back(live);
    }
};

TrainingSession::TrainingSession(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
TrainingSession::~TrainingSession() = default;
TrainingSession::TrainingSession(TrainingSession&&) noexcept = default;
TrainingSession& TrainingSession::operator=(TrainingSession&&) noexcept = default;

Expected<TrainingSession> TrainingSession::start(const control::Scenario& scenario,
                                                 std::shared_ptr<const hybrid::HybridModel> model) {
    if (auto st = scenario.validate(); !st) {
        return st.error();
    }
    if (!model) {
        return Error{ErrorKind::BadInput, "training session", "no model (the MPC controllers need one)"};
    }
    const plant::PlantOptions plantOptions = control::scenarioPlantOptions(scenario);
    if (auto st = plantOptions.validate(); !st) {
        return st.error();
    }
    auto im = std::make_unique<Impl>();
    im->scenario = scenario;
    im->model = std::move(model);
    im->warm = static_cast<std::size_t>(scenario.warmupS);
    im->total = im->warm + static_cast<std::size_t>(scenario.lengthS);
    auto& st = im->state;
    st.random = std::make_unique<plant::PlantRandom>(scenario.seed + 1);
    st.line = std::make_unique<control::ControlledLine>(scenario, plantOptions, *st.random);
    st.setpointPct = scenario.setpointPct;
    for (std::size_t k = 0; k < im->warm; ++k) {
        im->step();
    }
    return TrainingSession(std::move(im));
}

std::size_t TrainingSession::advance(std::size_t seconds, const Progress& progress) {
    auto& im = *m_impl;
    std::size_t done = 0;
    while (done < seconds && !im.frozen && !finished()) {
        im.step();
        ++done;
        if (done % 50 == 0 && reportProgress(progress, "training", static_cast<double>(done) / seconds,
                                             "second " + std::to_string(static_cast<long>(im.now())))) {
            break;
        }
    }
    return done;
}

double TrainingSession::timeS() const {
    return m_impl->now();
}
double TrainingSession::endS() const {
    return m_impl->scenario.lengthS;
}
bool TrainingSession::finished() const {
    // The line's disturbances end one sample after the scenario; its last sample stays unused.
    return m_impl->state.line->sample() >= m_impl->total;
}

Status TrainingSession::setSetpoint(double pct) {
    if (!std::isfinite(pct) || pct < 8 || pct > 20) {
        return Error{ErrorKind::BadInput, "setpoint", "must be within 8 … 20 % wb"};
    }
    m_impl->state.setpointPct = pct;
    m_impl->log(EventType::Setpoint, pct);
    return Status{};
}
double TrainingSession::setpointPct() const {
    return m_impl->state.setpointPct;
}

Status TrainingSession::setController(ControllerKind kind) {
    auto& im = *m_impl;
    if (kind != ControllerKind::Pi) {
        if (auto st = im.buildMpc(kind); !st) {
            return st;
        }
    } else {
        im.mpc.reset();
    }
    im.state.controller = kind;
    im.controllerNote.clear();
    im.log(EventType::Controller, 0, 0, control::controllerName(kind));
    return Status{};
}
ControllerKind TrainingSession::controller() const {
    return m_impl->state.controller;
}
const std::string& TrainingSession::controllerNote() const {
    return m_impl->controllerNote;
}

Status TrainingSession::injectFault(plant::Mechanism mechanism, double strength, double onsetS) {
    auto& im = *m_impl;
    if (!std::isfinite(onsetS) || onsetS < im.now()) {
        return Error{ErrorKind::BadInput, mechanismName(mechanism),
                     "the onset must not lie before the session's current time"};
    }
    if (onsetS > endS()) {
        return Error{ErrorKind::BadInput, mechanismName(mechanism), "the onset lies after the session's end"};
    }
    if (auto st = im.state.line->line().setEffect(mechanism, strength, static_cast<double>(im.warm) + onsetS);
        !st) {
        return st;
    }
    auto& faults = im.state.faults;
    // Re-scheduling a fault that has not acted yet replaces it.
    faults.erase(std::remove_if(faults.begin(), faults.end(),
                                [&](const InjectedFault& f) { return f.mechanism == mechanism; }),
                 faults.end());
    faults.push_back({mechanism, strength, onsetS, im.now()});
    im.log(EventType::Fault, strength, onsetS, mechanismName(mechanism));
    return Status{};
}

void TrainingSession::freeze() {
    if (!m_impl->frozen) {
        m_impl->frozen = true;
        m_impl->log(EventType::Freeze);
    }
}
void TrainingSession::resume() {
    if (m_impl->frozen) {
        m_impl->frozen = false;
        m_impl->log(EventType::Resume);
    }
}
bool TrainingSession::frozen() const {
    return m_impl->frozen;
}

Status TrainingSession::takeSnapshot(const std::string& label) {
    auto& im = *m_impl;
    if (label.empty()) {
        return Error{ErrorKind::BadInput, "snapshot", "needs a label"};
    }
    for (const auto& s : im.snapshots) {
        if (s.first.label == label) {
            return Error{ErrorKind::BadInput, "snapshot " + label, "a snapshot of that name exists"};
        }
    }
    im.snapshots.emplace_back(SnapshotInfo{label, im.now()}, im.state.copy());
    im.log(EventType::Snapshot, 0, 0, label);
    return Status{};
}

Status TrainingSession::restore(const std::string& label) {
    auto& im = *m_impl;
    for (const auto& s : im.snapshots) {
        if (s.first.label == label) {
            im.log(EventType::Restore, 0, 0, label); // at the time the instructor went back from
            im.state = s.second.copy();
            im.mpc.reset();
            if (im.state.controller != ControllerKind::Pi) {
                if (auto st = im.buildMpc(im.state.controller); !st) {
                    return st;
                }
            }
            im.controllerNote.clear();
            return Status{};
        }
    }
    return Error{ErrorKind::BadInput, "snapshot " + label, "no snapshot of that name"};
}

std::vector<SnapshotInfo> TrainingSession::snapshots() const {
    std::vector<SnapshotInfo> out;
    for (const auto& s : m_impl->snapshots) {
        out.push_back(s.first);
    }
    return out;
}

const std::vector<InjectedFault>& TrainingSession::faults() const {
    return m_impl->state.faults;
}

Status TrainingSession::answer(const std::string& cause) {
    if (cause != "no_fault" && !plant::mechanismByName(cause)) {
        return Error{ErrorKind::BadInput, "answer",
                     "'" + cause + "' is neither a CONTRACT.md §4 cause nor no_fault"};
    }
    m_impl->state.answers.push_back({m_impl->now(), cause});
    m_impl->log(EventType::Answer, 0, 0, cause);
    return Status{};
}
const std::vector<TraineeAnswer>& TrainingSession::answers() const {
    return m_impl->state.answers;
}
const std::vector<SessionEvent>& TrainingSession::events() const {
    return m_impl->events;
}
const std::vector<LiveSample>& TrainingSession::trace() const {
    return m_impl->state.trace;
}
const control::Scenario& TrainingSession::scenario() const {
    return m_impl->scenario;
}

TrainingScore TrainingSession::score() const {
    const auto& im = *m_impl;
    const auto& trace = im.state.trace;
    const double band = im.scenario.bandPct;
    const double now = im.now();
    const auto outOfBand = [&](const LiveSample& s) {
        return std::abs(s.xOutTruePct - s.setpointPct) > band;
    };
    TrainingScore sc;
    std::size_t outside = 0;
    for (const auto& s : trace) {
        if (outOfBand(s)) {
            ++outside;
            sc.offSpecKg += s.feedKgH / 3600.0; // one second of product
        }
    }
    sc.offSpecPct =
        trace.empty() ? 0 : 100.0 * static_cast<double>(outside) / static_cast<double>(trace.size());
    // A fault counts once it has acted; an answer is right when it names a fault acting then.
    const auto actingAt = [&](const std::string& cause, double t) {
        return std::any_of(im.state.faults.begin(), im.state.faults.end(), [&](const InjectedFault& f) {
            return mechanismName(f.mechanism) == cause && f.onsetS <= t;
        });
    };
    const bool anyActing = std::any_of(im.state.faults.begin(), im.state.faults.end(),
                                       [&](const InjectedFault& f) { return f.onsetS <= now; });
    for (const auto& a : im.state.answers) {
        const bool faultActing = std::any_of(im.state.faults.begin(), im.state.faults.end(),
                                             [&](const InjectedFault& f) { return f.onsetS <= a.atS; });
        const bool right = a.cause == "no_fault" ? !faultActing : actingAt(a.cause, a.atS);
        if (!right) {
            ++sc.wrongAnswers;
        }
    }
    double sum = 0;
    std::size_t scored = 0;
    for (const auto& f : im.state.faults) {
        if (f.onsetS > now) {
            continue;
        }
        FaultScore fs;
        fs.fault = f;
        double closedAt = now;
        for (const auto& a : im.state.answers) {
            if (a.cause == mechanismName(f.mechanism) && a.atS >= f.onsetS) {
                fs.found = true;
                fs.timeToFindS = a.atS - f.onsetS;
                closedAt = a.atS;
                break;
            }
        }
        std::size_t open = 0, openOutside = 0;
        for (const auto& s : trace) {
            if (s.timeS >= f.onsetS && s.timeS <= closedAt) {
                ++open;
                openOutside += outOfBand(s) ? 1 : 0;
            }
        }
        fs.offSpecPctWhileOpen =
            open > 0 ? 100.0 * static_cast<double>(openOutside) / static_cast<double>(open) : 0;
        if (fs.found) {
            fs.points = kFoundPoints + kTimePoints * std::max(0.0, 1.0 - fs.timeToFindS / kTimeBonusFadeS);
        }
        fs.points += kBandPoints * (1.0 - fs.offSpecPctWhileOpen / 100.0);
        // Unanswered and younger than the reaction time: nobody could have acted yet, so it does
        // not count until it is found or that time has passed (the score fell to 15 the moment a
        // fault was injected: issue #72 item 9).
        fs.withinReactionTime = !fs.found && now - f.onsetS < kReactionTimeS;
        fs.reactionTimeLeftS = fs.withinReactionTime ? kReactionTimeS - (now - f.onsetS) : 0;
        if (!fs.withinReactionTime) {
            sum += fs.points;
            ++scored;
        }
        sc.faults.push_back(fs);
    }
    const double base = scored == 0 ? 100.0 : sum / static_cast<double>(scored);
    sc.points = std::clamp(base - kWrongAnswerPenalty * sc.wrongAnswers, 0.0, 100.0);
    std::ostringstream os;
    os.setf(std::ios::fixed);
    os.precision(0);
    os << sc.points << " points: ";
    if (!anyActing) {
        os << "no fault has acted yet";
    } else {
        int found = 0;
        for (const auto& f : sc.faults) {
            found += f.found ? 1 : 0;
        }
        os << found << " of " << sc.faults.size() << " faults found";
        const auto waiting = std::count_if(sc.faults.begin(), sc.faults.end(),
                                           [](const FaultScore& x) { return x.withinReactionTime; });
        if (waiting > 0) {
            os << " (" << waiting << " within the time to react, not scored yet)";
        }
    }
    os.precision(1);
    os << ", " << sc.wrongAnswers << " wrong answer(s), " << sc.offSpecPct
       << " % of the time out of the band (" << sc.offSpecKg << " kg)";
    sc.summary = os.str();
    return sc;
}

data::Batch TrainingSession::recording(const std::string& batchId) const {
    plant::PlantBatch pb = m_impl->state.line->line().record();
    pb.id = batchId;
    // The line's time axis is reserved for its full length; the record ends at the last applied second.
    pb.timeS.resize(pb.tHotSpK.size());
    pb.xOutDb.resize(pb.tHotSpK.size());
    pb.tOutK.resize(pb.tHotSpK.size());
    pb.xHdtDb.resize(pb.tHotSpK.size());
    pb.tHdtK.resize(pb.tHotSpK.size());
    return plant::toBatch(pb, m_impl->scenario.seed);
}

} // namespace drytwin::training
