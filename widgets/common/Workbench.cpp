#include "common/Workbench.h"

#include "common/DisplayNames.h"
#include "common/ErrorText.h"
#include "common/WidgetHelpers.h"

#include <QAbstractButton>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>

namespace drytwin::widgets {

Workbench::Workbench(QObject* parent) : QObject(parent) {
    connect(&m_jobs, &JobRunner::progress, this,
            [this](JobId id, const QString& stage, double fraction, const QString& detail) {
                if (id == m_calibrationJob && stage == QLatin1String("calibrate")) {
                    static const QRegularExpression loss(QStringLiteral("loss ([-+0-9.eE]+)"));
                    const auto m = loss.match(detail);
                    if (m.hasMatch()) {
                        Q_EMIT calibrationProgress(fraction, m.captured(1).toDouble());
                    }
                }
            });
    connect(&m_jobs, &JobRunner::finished, this, [this](JobId id, JobStatus) { m_jobActions.erase(id); });
}

bool Workbench::isRunning(Action action) const {
    const auto it = m_running.find(action);
    return it != m_running.end() && it->second > 0;
}

void Workbench::bindButton(QAbstractButton* button, Action action) {
    const auto update = [this, button = QPointer<QAbstractButton>(button), action] {
        if (button) {
            button->setEnabled(!isRunning(action));
        }
    };
    connect(this, &Workbench::runningChanged, button, update);
    update();
}

Action Workbench::actionOf(JobId id) const {
    const auto it = m_jobActions.find(id);
    return it == m_jobActions.end() ? Action::Other : it->second;
}

QString progressStageOf(Action action) {
    switch (action) {
    case Action::Load:
        return QStringLiteral("load");
    case Action::Simulate:
        return QStringLiteral("simulate");
    case Action::Calibrate:
        return QStringLiteral("calibrate");
    case Action::Train:
        return QStringLiteral("train");
    case Action::Evaluate:
        return QStringLiteral("evaluate");
    case Action::Discover:
        return QStringLiteral("discover");
    case Action::Mpc:
        return QStringLiteral("mpc");
    case Action::Ablation:
        return QStringLiteral("ablation");
    case Action::Generate:
        return QStringLiteral("generate");
    case Action::Other:
        break;
    }
    return {};
}

template <class R, class Work, class Done>
JobId Workbench::start(Action kind, const QString& action, Work work, Done done,
                       std::function<void(const QString&, const Error&)> onFailure) {
    if (m_jobs.busy()) {
        Q_EMIT queued(Workbench::tr("%1 is queued behind the running job").arg(action));
    }
    ++m_running[kind];
    Q_EMIT runningChanged();
    const JobId id = m_jobs.submit<R>(
        action, std::function<Expected<R>(workflow::Session&, const Progress&)>(std::move(work)), this,
        std::function<void(const Expected<R>&)>([this, kind, action, done, onFailure](const Expected<R>& r) {
            --m_running[kind];
            Q_EMIT runningChanged();
            if (r) {
                done(*r);
                Q_EMIT actionFinished(action, true);
                return;
            }
            const QString message = r.error().kind == ErrorKind::Cancelled
                                        ? Workbench::tr("%1 was cancelled; nothing changed.").arg(action)
                                        : Workbench::tr("%1 failed: %2").arg(action, errorText(r.error()));
            Q_EMIT status(message);
            if (onFailure) {
                onFailure(message, r.error());
            }
            Q_EMIT failed(action, message, r.error().kind == ErrorKind::Cancelled);
            Q_EMIT actionFinished(action, false);
        }));
    m_jobActions[id] = kind; // read by the progress bar; the job reports only once this returned
    return id;
}

QString dataSetLabelText(const QString& name, int batches) {
    return batches == 1 ? Workbench::tr("%1 (1 batch)").arg(name)
                        : Workbench::tr("%1 (%2 batches)").arg(name).arg(batches);
}

QString LearntPart::learntOnText() const {
    return learntOnBatches >= 0 ? dataSetLabelText(learntOnName, learntOnBatches) : learntOn;
}

QString Workbench::dataSetLabel() const {
    if (!m_dataSet) {
        return {};
    }
    return dataSetLabelText(QFileInfo(m_dataPath).fileName(), static_cast<int>(m_summary.batches.size()));
}

void Workbench::retrain() {
    train(m_lastTrainOptions.value_or(workflow::TrainOptions{}));
}

void Workbench::fetchModel(const QString& why, const QString& learntOn, bool fromFile,
                           const std::optional<std::array<LearntPart, 3>>& parts) {
    start<hybrid::HybridModel>(
        Action::Other, tr("Read the model"),
        [](workflow::Session& s, const Progress&) -> Expected<hybrid::HybridModel> { return s.model(); },
        [this, why, learntOn, fromFile, parts](const hybrid::HybridModel& m) {
            takeModel(m, why, learntOn, fromFile);
            if (parts) {
                restoreLearntParts(*parts);
            }
            // A model with learnt parts opened on loaded data: show how it does on the held-out part.
            if (m_model.hasResidualModels() && hasData() && !m_latest.evaluate) {
                evaluate();
            }
        });
}

void Workbench::openData(const QString& givenPath, const QString& mappingPath) {
    // One spelling per data set ("demo/" and "demo" are the same folder): the list, the stash of
    // each one's results and a project's paths all key on it.
    const QString path = QDir::cleanPath(givenPath);
    Q_EMIT status(tr("Loading %1…").arg(path));
    workflow::OpenOptions o;
    o.dataPath = path.toStdString();
    o.mappingPath = mappingPath.toStdString();
    struct Loaded {
        workflow::OpenResult open;
        std::vector<data::SiBatch> si;
    };
    start<Loaded>(
        Action::Load, tr("Load %1").arg(path),
        [o](workflow::Session& s, const Progress& p) -> Expected<Loaded> {
            auto r = s.open(o, p);
            if (!r) {
                return r.error();
            }
            return Loaded{*r, s.siBatches()};
        },
        [this, path, mappingPath](const Loaded& l) {
            if (!m_dataPath.isEmpty()) {
                m_stash[m_dataPath] = {m_latest, m_modelRevision}; // kept for switching back
            }
            m_mappingPath = mappingPath;
            rememberFolder(path); // the next file dialog starts where the data are
            m_dataSet = l.open.dataSet;
            m_summary = l.open.summary;
            m_si = l.si;
            m_dataPath = path;
            m_latest = {};
            m_calibrationStart.reset();
            bool restored = false;
            if (const auto it = m_stash.find(path);
                it != m_stash.end() && it->second.modelRevision == m_modelRevision) {
                m_latest = it->second.results;
                m_latest.simulate.reset(); // simulated again below, by whoever shows it
                restored = true;
            }
            const QString label = dataSetLabel();
            auto entry = std::find_if(m_dataSets.begin(), m_dataSets.end(),
                                      [&](const DataSetEntry& e) { return e.path == path; });
            const DataSetEntry loaded{path, mappingPath, label, static_cast<int>(m_summary.batches.size())};
            if (entry == m_dataSets.end()) {
                m_dataSets.push_back(loaded);
            } else {
                *entry = loaded;
            }
            Q_EMIT dataSetsChanged();
            Q_EMIT status(tr("%1: %2 batches, %3 rows, %4 missing cells; the cleaning keeps %5 rows")
                              .arg(path)
                              .arg(m_summary.batches.size())
                              .arg(m_summary.rows)
                              .arg(m_summary.missing)
                              .arg(m_summary.cleaning.kept));
            Q_EMIT dataChanged();
            if (restored) {
                Q_EMIT resultsRestored();
            } else if (m_model.hasResidualModels()) {
                evaluate(); // the model's held-out metrics on the new data
            }
        },
        [this, path, mappingPath](const QString& message, const Error& e) {
            const bool mappable =
                mappingPath.isEmpty() && QFileInfo(path).isFile() &&
                (e.code == ErrorCode::MissingColumn || e.code == ErrorCode::DataFileFormat ||
                 e.code == ErrorCode::TextInNumber || e.code == ErrorCode::TimeNotIncreasing);
            Q_EMIT dataLoadFailed(message, path, mappable);
        });
}

void Workbench::openModel(const QString& path, const std::optional<std::array<LearntPart, 3>>& parts) {
    workflow::OpenOptions o;
    o.modelPath = path.toStdString();
    start<workflow::OpenResult>(
        Action::Other, tr("Open model %1").arg(path),
        [o](workflow::Session& s, const Progress& p) { return s.open(o, p); },
        [this, path, parts](const workflow::OpenResult&) {
            m_modelPath = path;
            Q_EMIT status(tr("Model %1 opened").arg(path));
            fetchModel({}, tr("model file %1").arg(QFileInfo(path).fileName()), true, parts);
        });
}

void Workbench::saveModel(const QString& path, const QString& doneMessage) {
    start<bool>(
        Action::Other, tr("Save model"),
        [p = path.toStdString()](workflow::Session& s, const Progress&) -> Expected<bool> {
            if (auto st = s.saveModel(p); !st) {
                return st.error();
            }
            return true;
        },
        [this, path, doneMessage](bool) {
            m_modelPath = path;
            Q_EMIT status(doneMessage.isEmpty() ? tr("Model saved to %1").arg(path) : doneMessage);
        });
}

void Workbench::setParameter(properties::Param param, double value) {
    start<hybrid::HybridModel>(
        Action::Other, tr("Set %1").arg(fromView(properties::info(param).symbol)),
        [param, value](workflow::Session& s, const Progress&) -> Expected<hybrid::HybridModel> {
            if (auto st = s.setParameter(param, value); !st) {
                return st.error();
            }
            return s.model();
        },
        [this](const hybrid::HybridModel& m) {
            m_model = m;
            ++m_modelRevision;
            Q_EMIT modelChanged();
            Q_EMIT modelEdited();
        });
}

void Workbench::setModel(const hybrid::HybridModel& model, const QString& why, bool retrainAfter) {
    start<hybrid::HybridModel>(
        Action::Other, tr("Set the model"),
        [model](workflow::Session& s, const Progress&) -> Expected<hybrid::HybridModel> {
            s.setModel(model);
            return s.model();
        },
        [this, why, retrainAfter](const hybrid::HybridModel& m) {
            // The parts the new model brings (discovery retrains PGRL-CC on the extended model) were
            // learnt on the loaded data.
            takeModel(m, why, why.isEmpty() ? QString() : dataSetLabel());
            Q_EMIT modelEdited();
            if (retrainAfter && hasStaleParts()) {
                retrain();
            }
        });
}

void Workbench::simulate() {
    start<workflow::SimulateResult>(
        Action::Simulate, tr("Simulate"),
        [](workflow::Session& s, const Progress& p) { return s.simulate({}, p); },
        [this](const workflow::SimulateResult& r) {
            m_latest.simulate = r;
            // Over every kept row, as the Calibrate tab's summary gives it for all rows: the mean
            // of the batches' MAEs (0.216) sat beside the calibration rows' (0.163) unexplained.
            const QString mae = tr("outlet-moisture MAE %1 % wb over all %2 kept rows")
                                    .arg(r.maeXOutPctAllKeptRows(), 0, 'f', 3)
                                    .arg(r.keptRows());
            Q_EMIT status(r.simulations.size() == 1
                              ? tr("Simulated 1 batch; %1").arg(mae)
                              : tr("Simulated %1 batches; %2").arg(r.simulations.size()).arg(mae));
            Q_EMIT simulated();
        });
}

void Workbench::simulateCalibrationStart() {
    if (!m_latest.calibrate || !hasData()) {
        return;
    }
    workflow::SimulateOptions o;
    o.parameters = m_latest.calibrate->startParameters;
    start<workflow::SimulateResult>(
        Action::Simulate, tr("Simulate"),
        [o](workflow::Session& s, const Progress& p) { return s.simulate(o, p); },
        [this, forPath = m_dataPath](const workflow::SimulateResult& r) {
            if (forPath != m_dataPath) {
                return; // another data set was loaded meanwhile: this run belongs to none shown
            }
            m_calibrationStart = r;
            Q_EMIT calibrationStartSimulated();
        });
}

void Workbench::calibrate(const workflow::CalibrateOptions& options, bool retrainAfter) {
    m_calibrationJob = start<workflow::CalibrateResult>(
        Action::Calibrate, tr("Calibrate"),
        [options](workflow::Session& s, const Progress& p) { return s.calibrate(options, p); },
        [this, retrainAfter](const workflow::CalibrateResult& r) {
            m_latest.calibrate = r;
            m_calibrationStart.reset();
            Q_EMIT status(tr("Calibration: %1; loss %2 → %3")
                              .arg(terminationText(r.ending.termination))
                              .arg(r.calibration.before.loss, 0, 'g', 4)
                              .arg(r.calibration.after.loss, 0, 'g', 4));
            if (r.droppedResidualModels) {
                // The held-out metrics were of the learnt models the calibration dropped.
                m_latest.evaluate.reset();
                Q_EMIT evaluated();
            }
            Q_EMIT calibrated();
            fetchModel(QString::fromLatin1(staleReason::kCalibrated));
            if (retrainAfter && r.droppedResidualModels) {
                retrain(); // queued behind the model's refresh
            }
        });
}

void Workbench::stopKeepBest() {
    if (m_calibrationJob != 0) {
        m_jobs.stopKeepBest(m_calibrationJob);
    }
}

void Workbench::train(const workflow::TrainOptions& options) {
    m_lastTrainOptions = options;
    start<workflow::TrainResult>(
        Action::Train, tr("Learn the correction models"),
        [options](workflow::Session& s, const Progress& p) { return s.train(options, p); },
        [this](const workflow::TrainResult& r) {
            m_latest.train = r;
            Q_EMIT status(tr("Learnt the correction models (PGRL-CC) and the two comparison models"));
            Q_EMIT trained();
            // The learnt parts are in the result: the tabs say "learnt" now, not after a model
            // read queued behind whatever else waits (issue #43 item 11).
            hybrid::HybridModel m = m_model;
            m.pgrlCc = r.pgrlCc;
            m.extInput = r.extInput;
            m.lstm = r.lstm;
            takeModel(m, {}, dataSetLabel());
            evaluate();
        });
}

void Workbench::evaluate() {
    start<workflow::EvaluateResult>(
        Action::Evaluate, tr("Evaluate"),
        [](workflow::Session& s, const Progress& p) { return s.evaluate({}, p); },
        [this](const workflow::EvaluateResult& r) {
            m_latest.evaluate = r;
            Q_EMIT evaluated();
        });
}

void Workbench::setReferencePath(const QString& path) {
    if (path == m_referencePath) {
        return;
    }
    m_referencePath = path;
    Q_EMIT referenceChanged();
}

void Workbench::discover() {
    workflow::DiscoverOptions options;
    options.referencePath = m_referencePath.toStdString();
    // The reference is read with the loaded data's column mapping: the same historian, the same tags.
    options.referenceMappingPath = m_mappingPath.toStdString();
    start<workflow::DiscoverResult>(
        Action::Discover, m_referencePath.isEmpty() ? tr("Discover") : tr("Discover against the reference"),
        [options](workflow::Session& s, const Progress& p) { return s.discover(options, p); },
        [this](const workflow::DiscoverResult& r) {
            m_latest.discover = r;
            // The verdict in words, with the first cause (its group's name where it names one).
            QString first;
            if (!r.discovery.findings.empty()) {
                const auto& f = r.discovery.findings.front();
                first = f.group.empty() ? causeDisplayName(f.cause) : groupDisplayName(f.group);
                if (r.discovery.findings.size() > 1) { // the others are not hidden behind the first
                    first += tr(" (and %1 more)").arg(r.discovery.findings.size() - 1);
                }
            }
            Q_EMIT status(tr("Discovery: %1").arg(verdictDisplayText(r.discovery.verdict, first)));
            Q_EMIT discovered();
        });
}

void Workbench::runMpc(const workflow::MpcOptions& options) {
    start<workflow::MpcResult>(
        Action::Mpc, tr("What-if scenario"),
        [options](workflow::Session& s, const Progress& p) { return s.mpc(options, p); },
        [this](const workflow::MpcResult& r) {
            m_latest.mpc = r;
            Q_EMIT status(mpcEndingText(r.closedLoop));
            Q_EMIT mpcFinished();
        });
}

} // namespace drytwin::widgets

namespace drytwin::widgets {

void Workbench::ablation() {
    start<hybrid::AblationResult>(
        Action::Ablation, tr("Ablation"),
        [](workflow::Session& s, const Progress& p) { return s.ablation(p); },
        [this](const hybrid::AblationResult& r) {
            m_latest.ablation = r;
            Q_EMIT status(tr("Ablation: %1 variants trained and evaluated").arg(r.rows.size()));
            Q_EMIT ablationFinished();
        });
}

void Workbench::generate(const workflow::GenerateOptions& options) {
    start<workflow::GenerateResult>(
        Action::Generate, tr("Generate"),
        [options](workflow::Session& s, const Progress& p) { return s.generate(options, p); },
        [this, folder = QString::fromStdString(options.outFolder)](const workflow::GenerateResult& r) {
            Q_EMIT status(tr("Wrote %1 virtual-plant batches to %2").arg(r.files.size()).arg(folder));
            openData(folder);
        });
}

} // namespace drytwin::widgets
