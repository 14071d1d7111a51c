// The learnt parts of the model (PGRL-CC, the input-only correction, the LSTM) as every tab shows
// them: which exist, what they were learnt on, which went stale and why, and the question asked
// before an action makes them stale. Split from Workbench.cpp, which holds the actions.

#include "common/DisplayNames.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <algorithm>
#include <utility>

namespace drytwin::widgets {

const LearntPart& Workbench::learntPart(control::ControllerKind kind) const {
    for (const auto& p : m_parts) {
        if (p.kind == kind) {
            return p;
        }
    }
    static const LearntPart none{};
    return none;
}

bool Workbench::hasController(control::ControllerKind kind) const {
    if (kind == control::ControllerKind::Pbm || kind == control::ControllerKind::Pi) {
        return true;
    }
    return learntPart(kind).state == PartState::Current;
}

bool Workbench::hasStaleParts() const {
    return std::any_of(m_parts.begin(), m_parts.end(),
                       [](const LearntPart& p) { return p.state == PartState::Stale; });
}

namespace {
bool modelHoldsPart(const hybrid::HybridModel& m, control::ControllerKind k) {
    switch (k) {
    case control::ControllerKind::PgrlCc:
        return m.pgrlCc != nullptr;
    case control::ControllerKind::ExtInputResidual:
        return m.extInput != nullptr;
    case control::ControllerKind::Lstm:
        return m.lstm != nullptr;
    default:
        return false;
    }
}
} // namespace

void Workbench::takeModel(const hybrid::HybridModel& model, const QString& why, const QString& learntOn,
                          bool fromFile) {
    for (auto& p : m_parts) {
        const bool before = modelHoldsPart(m_model, p.kind);
        const bool after = modelHoldsPart(model, p.kind);
        if (after && (!before || !learntOn.isEmpty())) {
            p.state = PartState::Current;
            p.learntOn = learntOn;
            // Learnt on the loaded data set: kept as name and count, worded when shown.
            const bool onData = m_dataSet && !learntOn.isEmpty() && learntOn == dataSetLabel();
            p.learntOnName = onData ? QFileInfo(m_dataPath).fileName() : QString();
            p.learntOnBatches = onData ? static_cast<int>(m_summary.batches.size()) : -1;
            p.staleBecause.clear();
        } else if (!after && fromFile) {
            p = LearntPart::absent(p.kind); // a model file opened: what it lacks was never learnt for it
        } else if (!after && before) {
            p.state = why.isEmpty() ? PartState::Absent : PartState::Stale;
            p.staleBecause = why;
        }
    }
    m_model = model;
    ++m_modelRevision;
    // A project's other data sets were stashed before its model file was read (the data come
    // first): their results were made with the model this reading brings, not with the one before.
    if (fromFile && std::exchange(m_stashAwaitsProjectModel, false)) {
        for (auto& entry : m_stash) {
            if (entry.second.modelRevision == m_modelRevision - 1) {
                entry.second.modelRevision = m_modelRevision;
            }
        }
    }
    Q_EMIT modelChanged();
    Q_EMIT modelStateChanged();
}

std::optional<bool> Workbench::confirmInvalidation(QWidget* parent, const QString& action,
                                                   const hybrid::HybridModel* newModel) {
    QStringList current;
    for (const auto& p : m_parts) {
        if (p.state == PartState::Current && !(newModel && modelHoldsPart(*newModel, p.kind))) {
            current << controllerDisplayName(p.kind);
        }
    }
    if (current.isEmpty()) {
        return false;
    }
    if (m_invalidationPolicy != AfterInvalidation::Ask || qEnvironmentVariableIsSet("DRYTWIN_NO_MODAL")) {
        return m_invalidationPolicy == AfterInvalidation::Retrain;
    }
    QMessageBox box(QMessageBox::Question, action, invalidationQuestion(action, newModel),
                    QMessageBox::NoButton, parent);
    auto* retrain = box.addButton(tr("%1, then retrain them").arg(action), QMessageBox::AcceptRole);
    auto* keep = box.addButton(tr("%1 only (retrain later)").arg(action), QMessageBox::DestructiveRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(retrain);
    box.exec();
    if (box.clickedButton() == retrain) {
        return true;
    }
    if (box.clickedButton() == keep) {
        return false;
    }
    return std::nullopt;
}

QString Workbench::invalidationQuestion(const QString& action, const hybrid::HybridModel* newModel) const {
    QStringList stale;
    for (const auto& p : m_parts) {
        if (p.state == PartState::Current && !(newModel && modelHoldsPart(*newModel, p.kind))) {
            stale << controllerDisplayName(p.kind);
        }
    }
    const QString staleText =
        tr("Learnt on the present physics model, these no longer match it and are set aside as stale: %1.")
            .arg(stale.join(tr(", ")));
    if (!newModel) {
        return tr("%1 changes the physics model. ").arg(action) + staleText;
    }
    // What the new model brings, first (issue #72 item 11: the Extend dialog named only the part it
    // makes stale): the causes it adds, the parameters refitted with them, the learnt parts it holds.
    QStringList added;
    for (const auto& [name, mechanism] : newModel->mechanisms) {
        if (!m_model.mechanisms.count(name)) {
            added << causeDisplayName(name);
        }
    }
    QStringList refitted;
    for (const auto& info : properties::parameterTable()) {
        if (newModel->parameters[info.id] != m_model.parameters[info.id] && !info.fixed &&
            std::string(info.source).rfind("extension ", 0) != 0) {
            refitted << fromView(info.symbol);
        }
    }
    QStringList brought;
    for (const auto& p : m_parts) {
        if (modelHoldsPart(*newModel, p.kind)) {
            brought << controllerDisplayName(p.kind);
        }
    }
    QString text = added.isEmpty()
                       ? tr("%1 replaces the physics model.").arg(action)
                       : tr("%1 adds to the physics model: %2.").arg(action, added.join(tr(", ")));
    if (!refitted.isEmpty()) {
        text += QLatin1Char(' ') + tr("Refitted with it: %1.").arg(refitted.join(tr(", ")));
    }
    if (!brought.isEmpty()) {
        text += QLatin1Char(' ') +
                tr("Learnt on the new model and brought with it: %1.").arg(brought.join(tr(", ")));
    }
    return text + QLatin1Char(' ') + staleText;
}

QString staleReasonText(const QString& reason) {
    return QCoreApplication::translate("StaleReason", reason.toUtf8().constData());
}

QString Workbench::modelStateText() const {
    QStringList lines;
    if (m_model.calibration) {
        QStringList symbols;
        for (const auto& e : m_model.calibration->estimates) {
            symbols << QString::fromStdString(e.symbol);
        }
        lines << tr("Physics model calibrated (%1 fitted to data).").arg(symbols.join(QStringLiteral(", ")));
    } else {
        lines << tr("Physics model with its default parameters (not calibrated).");
    }
    if (!m_model.mechanisms.empty()) {
        QStringList causes;
        for (const auto& [name, value] : m_model.mechanisms) {
            causes << causeDisplayName(name);
        }
        lines << tr("Extended by discovery with: %1.").arg(causes.join(QStringLiteral(", ")));
    }
    for (const auto& p : m_parts) {
        const QString name = controllerDisplayName(p.kind);
        switch (p.state) {
        case PartState::Absent:
            lines << tr("%1: not learnt yet.").arg(name);
            break;
        case PartState::Current:
            lines << (p.learntOnText().isEmpty() ? tr("%1: learnt.").arg(name)
                                                 : tr("%1: learnt on %2.").arg(name, p.learntOnText()));
            break;
        case PartState::Stale:
            // While a retraining is under way the advice to retrain would be wrong (issue #72 item 8).
            if (isRunningNow(Action::Train)) {
                lines << tr("%1: stale, since %2; being learnt again now.")
                             .arg(name, staleReasonText(p.staleBecause));
            } else if (isRunning(Action::Train)) {
                lines << tr("%1: stale, since %2; learning it again is queued behind “%3”.")
                             .arg(name, staleReasonText(p.staleBecause), m_jobs.jobName(m_jobs.headJob()));
            } else {
                lines << tr("%1: stale, since %2; retrain it to use it.")
                             .arg(name, staleReasonText(p.staleBecause));
            }
            break;
        }
    }
    return lines.join(QLatin1Char(' '));
}

void Workbench::restoreLearntParts(const std::array<LearntPart, 3>& parts) {
    for (std::size_t i = 0; i < m_parts.size(); ++i) {
        // Only what the open model agrees with: a part saved as current must be in the model.
        const bool holds = modelHoldsPart(m_model, m_parts[i].kind);
        if (parts[i].kind == m_parts[i].kind && (parts[i].state == PartState::Current) == holds) {
            m_parts[i] = parts[i];
        }
    }
    Q_EMIT modelStateChanged();
}

} // namespace drytwin::widgets
