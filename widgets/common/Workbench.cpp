#include "common/Workbench.h"

#include "common/ErrorText.h"
#include "common/WidgetHelpers.h"

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
}

template <class R, class Work, class Done>
JobId Workbench::start(const QString& action, Work work, Done done,
                       std::function<void(const QString&)> onFailure) {
    if (m_jobs.busy()) {
        Q_EMIT status(Workbench::tr("%1 is queued behind the running job").arg(action));
    }
    return m_jobs.submit<R>(
        action, std::function<Expected<R>(workflow::Session&, const Progress&)>(std::move(work)), this,
        std::function<void(const Expected<R>&)>([this, action, done, onFailure](const Expected<R>& r) {
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
                onFailure(message);
            }
            Q_EMIT failed(action, message, r.error().kind == ErrorKind::Cancelled);
            Q_EMIT actionFinished(action, false);
        }));
}

void Workbench::fetchModel() {
    start<hybrid::HybridModel>(
        tr("Read the model"),
        [](workflow::Session& s, const Progress&) -> Expected<hybrid::HybridModel> { return s.model(); },
        [this](const hybrid::HybridModel& m) {
            m_model = m;
            Q_EMIT modelChanged();
            // A model with learnt parts opened on loaded data: show how it does on the held-out part.
            if (m_model.hasResidualModels() && hasData() && !m_latest.evaluate) {
                evaluate();
            }
        });
}

void Workbench::openData(const QString& path, const QString& mappingPath) {
    Q_EMIT status(tr("Loading %1…").arg(path));
    workflow::OpenOptions o;
    o.dataPath = path.toStdString();
    o.mappingPath = mappingPath.toStdString();
    struct Loaded {
        workflow::OpenResult open;
        std::vector<data::SiBatch> si;
    };
    start<Loaded>(
        tr("Load %1").arg(path),
        [o](workflow::Session& s, const Progress& p) -> Expected<Loaded> {
            auto r = s.open(o, p);
            if (!r) {
                return r.error();
            }
            return Loaded{*r, s.siBatches()};
        },
        [this, path, mappingPath](const Loaded& l) {
            m_mappingPath = mappingPath;
            m_dataSet = l.open.dataSet;
            m_summary = l.open.summary;
            m_si = l.si;
            m_dataPath = path;
            m_latest = {};
            Q_EMIT status(tr("%1: %2 batches, %3 rows, %4 missing cells; the cleaning keeps %5 rows")
                              .arg(path)
                              .arg(m_summary.batches.size())
                              .arg(m_summary.rows)
                              .arg(m_summary.missing)
                              .arg(m_summary.cleaning.kept));
            Q_EMIT dataChanged();
            if (m_model.hasResidualModels()) {
                evaluate(); // the model's held-out metrics on the new data
            }
        },
        [this](const QString& message) { Q_EMIT dataLoadFailed(message); });
}

void Workbench::openModel(const QString& path) {
    workflow::OpenOptions o;
    o.modelPath = path.toStdString();
    start<workflow::OpenResult>(
        tr("Open model %1").arg(path), [o](workflow::Session& s, const Progress& p) { return s.open(o, p); },
        [this, path](const workflow::OpenResult&) {
            m_modelPath = path;
            Q_EMIT status(tr("Model %1 opened").arg(path));
            fetchModel();
        });
}

void Workbench::saveModel(const QString& path) {
    start<bool>(
        tr("Save model"),
        [p = path.toStdString()](workflow::Session& s, const Progress&) -> Expected<bool> {
            if (auto st = s.saveModel(p); !st) {
                return st.error();
            }
            return true;
        },
        [this, path](bool) {
            m_modelPath = path;
            Q_EMIT status(tr("Model saved to %1").arg(path));
        });
}

void Workbench::setParameter(properties::Param param, double value) {
    start<hybrid::HybridModel>(
        tr("Set %1").arg(fromView(properties::info(param).symbol)),
        [param, value](workflow::Session& s, const Progress&) -> Expected<hybrid::HybridModel> {
            if (auto st = s.setParameter(param, value); !st) {
                return st.error();
            }
            return s.model();
        },
        [this](const hybrid::HybridModel& m) {
            m_model = m;
            Q_EMIT modelChanged();
        });
}

void Workbench::setModel(const hybrid::HybridModel& model) {
    start<hybrid::HybridModel>(
        tr("Set the model"),
        [model](workflow::Session& s, const Progress&) -> Expected<hybrid::HybridModel> {
            s.setModel(model);
            return s.model();
        },
        [this](const hybrid::HybridModel& m) {
            m_model = m;
            Q_EMIT modelChanged();
        });
}

void Workbench::simulate() {
    start<workflow::SimulateResult>(
        tr("Simulate"), [](workflow::Session& s, const Progress& p) { return s.simulate({}, p); },
        [this](const workflow::SimulateResult& r) {
            m_latest.simulate = r;
            double x = 0;
            for (const auto& f : r.fits) {
                x += f.maeXOutPct / static_cast<double>(std::max<std::size_t>(1, r.fits.size()));
            }
            Q_EMIT status(tr("Simulated %1 batches; mean outlet-moisture MAE %2 % wb")
                              .arg(r.simulations.size())
                              .arg(x, 0, 'f', 3));
            Q_EMIT simulated();
        });
}

void Workbench::calibrate(const workflow::CalibrateOptions& options) {
    m_calibrationJob = start<workflow::CalibrateResult>(
        tr("Calibrate"),
        [options](workflow::Session& s, const Progress& p) { return s.calibrate(options, p); },
        [this](const workflow::CalibrateResult& r) {
            m_latest.calibrate = r;
            Q_EMIT status(tr("Calibration %1: loss %2 → %3")
                              .arg(QString::fromLatin1(terminationName(r.ending.termination)))
                              .arg(r.calibration.before.loss, 0, 'g', 4)
                              .arg(r.calibration.after.loss, 0, 'g', 4));
            Q_EMIT calibrated();
            fetchModel();
        });
}

void Workbench::stopKeepBest() {
    if (m_calibrationJob != 0) {
        m_jobs.stopKeepBest(m_calibrationJob);
    }
}

void Workbench::train(const workflow::TrainOptions& options) {
    start<workflow::TrainResult>(
        tr("Train"), [options](workflow::Session& s, const Progress& p) { return s.train(options, p); },
        [this](const workflow::TrainResult& r) {
            m_latest.train = r;
            Q_EMIT status(tr("Trained PGRL-CC and the baselines"));
            Q_EMIT trained();
            fetchModel();
            evaluate();
        });
}

void Workbench::evaluate() {
    start<workflow::EvaluateResult>(
        tr("Evaluate"), [](workflow::Session& s, const Progress& p) { return s.evaluate({}, p); },
        [this](const workflow::EvaluateResult& r) {
            m_latest.evaluate = r;
            Q_EMIT evaluated();
        });
}

void Workbench::discover() {
    start<workflow::DiscoverResult>(
        tr("Discover"), [](workflow::Session& s, const Progress& p) { return s.discover({}, p); },
        [this](const workflow::DiscoverResult& r) {
            m_latest.discover = r;
            Q_EMIT status(tr("Discovery: %1").arg(QString::fromStdString(r.discovery.verdict)));
            Q_EMIT discovered();
        });
}

void Workbench::runMpc(const workflow::MpcOptions& options) {
    start<workflow::MpcResult>(
        tr("What-if scenario"),
        [options](workflow::Session& s, const Progress& p) { return s.mpc(options, p); },
        [this](const workflow::MpcResult& r) {
            m_latest.mpc = r;
            Q_EMIT status(QString::fromStdString(r.ending.message));
            Q_EMIT mpcFinished();
        });
}

} // namespace drytwin::widgets

namespace drytwin::widgets {

void Workbench::ablation() {
    start<hybrid::AblationResult>(
        tr("Ablation"), [](workflow::Session& s, const Progress& p) { return s.ablation(p); },
        [this](const hybrid::AblationResult& r) {
            m_latest.ablation = r;
            Q_EMIT status(tr("Ablation: %1 variants trained and evaluated").arg(r.rows.size()));
            Q_EMIT ablationFinished();
        });
}

void Workbench::generate(const workflow::GenerateOptions& options) {
    start<workflow::GenerateResult>(
        tr("Generate"), [options](workflow::Session& s, const Progress& p) { return s.generate(options, p); },
        [this, folder = QString::fromStdString(options.outFolder)](const workflow::GenerateResult& r) {
            Q_EMIT status(tr("Wrote %1 virtual-plant batches to %2").arg(r.files.size()).arg(folder));
            openData(folder);
        });
}

} // namespace drytwin::widgets
