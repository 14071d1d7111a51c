// The workflow Session driven directly, as the CLI and the GUI drive it: every action, a
// rejected load, cancel, stop-and-keep-best, failed steps, model files and the pipeline.
#include "common/AtomicFile.h"
#include "common/Units.h"
#include "io/ModelFile.h"
#include "workflow/ProjectFile.h"
#include "workflow/ResultArchive.h"
#include "workflow/Session.h"

#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace drytwin;
using properties::Param;

namespace {

/// Progress that answers @p action from the @p after-th calibration report on.
Progress stopAfter(int after, ProgressAction action, int* calls) {
    return [=](const ProgressInfo& info) {
        if (info.stage != "calibrate") {
            return ProgressAction::Continue;
        }
        return ++*calls >= after ? action : ProgressAction::Continue;
    };
}

workflow::TrainOptions quickTraining() {
    workflow::TrainOptions t;
    t.lstm.epochs = 2;
    t.lstm.hidden = 8;
    t.selection.lags = {4, 8}; // a small grid: 4 candidates with and without P⊥
    return t;
}

workflow::CalibrateOptions quickCalibration() {
    workflow::CalibrateOptions c;
    c.calibration.maxEvaluations = 60;
    c.calibration.globalEvaluations = 20;
    return c;
}

} // namespace

class TestSession : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_data; ///< a small virtual-plant data set, written once

private Q_SLOTS:
    // A report needs every step; an evaluation without PGRL-CC means Train never ran (a project's
    // results do not keep the training itself), and the paper's captions would describe the PBM.
    void aReportNamesEveryStepStillToRunTrainIncluded() {
        workflow::LatestResults latest;
        QCOMPARE(workflow::stepsMissingForReport(latest),
                 (std::vector<std::string>{"calibrate", "train", "evaluate", "ablation", "discover", "mpc"}));
        latest.calibrate.emplace();
        latest.evaluate.emplace();
        latest.evaluate->evaluation.models.resize(1);
        latest.evaluate->evaluation.models[0].name = "pbm";
        latest.ablation.emplace();
        latest.discover.emplace();
        latest.mpc.emplace();
        QCOMPARE(workflow::stepsMissingForReport(latest), (std::vector<std::string>{"train"}));
        const auto refused = workflow::reportInputs(latest, {});
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().reason.find("still to run: train") != std::string::npos);
        latest.evaluate->evaluation.models.resize(2);
        latest.evaluate->evaluation.models[1].name = "pgrl_cc";
        QVERIFY(workflow::stepsMissingForReport(latest).empty());
        QVERIFY(workflow::reportInputs(latest, {}).ok());
    }

    // A project's paths: beside the project where they exist there, else where they were saved.
    void aProjectFindsItsDataBesideItOrWhereTheyWereSaved() {
        QTemporaryDir dir;
        const std::string root = dir.path().toStdString();
        std::filesystem::create_directories(root + "/saved/data");
        std::filesystem::create_directories(root + "/moved/project");
        nlohmann::json o{{"format", "drytwin-project"},
                         {"data_path", "data"},
                         {"data_path_absolute", root + "/saved/data"},
                         {"data_fingerprint", "B01:10"}};
        o["data_sets"] = nlohmann::json::array(
            {{{"label", "x"}, {"path", "data"}, {"path_absolute", root + "/saved/data"}}});
        const std::string project = o.dump();
        std::ofstream(root + "/moved/project/p.dtproj") << project;
        auto paths = workflow::readProjectPaths(root + "/moved/project/p.dtproj");
        QVERIFY(paths.ok());
        QCOMPARE(paths->data, root + "/saved/data"); // not beside the moved project: where saved
        QCOMPARE(paths->dataFingerprint, std::string("B01:10"));
        QCOMPARE(paths->dataSets.size(), std::size_t(1));
        std::filesystem::create_directories(root + "/moved/project/data");
        paths = workflow::readProjectPaths(root + "/moved/project/p.dtproj");
        QCOMPARE(paths->data, root + "/moved/project/data"); // moved with its data: beside it
        QCOMPARE(paths->dataSets[0].batches, -1);            // a project that does not say
        // A project saved in its data's folder ("." in the file) names that folder without a
        // trailing separator, so that the folder keeps its name in the data-set list (issue #72
        // item 3: "(1 batch)"); another data set's results and batch count come back with it.
        nlohmann::json beside{{"format", "drytwin-project"}, {"data_path", "."}};
        beside["data_sets"] = nlohmann::json::array(
            {{{"label", "x"}, {"path", "."}, {"batches", 3}, {"results_path", "p.dtproj.results.1.json"}}});
        std::ofstream(root + "/saved/data/p.dtproj") << beside.dump();
        paths = workflow::readProjectPaths(root + "/saved/data/p.dtproj");
        QVERIFY(paths.ok());
        QCOMPARE(paths->data, root + "/saved/data");
        QCOMPARE(paths->dataSets[0].path, root + "/saved/data");
        QCOMPARE(paths->dataSets[0].batches, 3);
        QCOMPARE(paths->dataSets[0].results, root + "/saved/data/p.dtproj.results.1.json");
        std::ofstream(root + "/cut.dtproj") << project.substr(0, 40);
        const auto cut = workflow::readProjectPaths(root + "/cut.dtproj");
        QVERIFY(!cut.ok());
        QVERIFY2(cut.error().reason.find("damaged or cut short") != std::string::npos,
                 cut.error().reason.c_str());
    }

    // A project's data fingerprint: batches and rows, and a digest of the values, so that one
    // reading edited in place is caught; a fingerprint of an older project (no digest) still
    // compares by batches and rows.
    void aDataFingerprintSeesAValueEditedInPlace() {
        data::DataSetSummary summary;
        for (const auto& [id, rows] : {std::pair{"B01", 10}, std::pair{"B02", 12}}) {
            data::BatchSummary batch;
            batch.id = id;
            batch.rows = rows;
            summary.batches.push_back(batch);
        }
        data::ColumnSummary outlet;
        outlet.name = "X_out_pct";
        outlet.unit = "%";
        outlet.present = true;
        outlet.min = 11.0;
        outlet.max = 13.0;
        outlet.mean = 12.0;
        summary.columns.push_back(outlet);
        const std::string saved = workflow::dataFingerprint(summary);
        QVERIFY2(saved.rfind("B01:10 B02:12 values:", 0) == 0, saved.c_str());
        QVERIFY(!workflow::dataChangeSince(saved, workflow::dataFingerprint(summary)));

        summary.columns[0].mean = 12.0 + 1e-9; // one reading of 22 moved by 2e-8 % wb
        const auto edited = workflow::dataChangeSince(saved, workflow::dataFingerprint(summary));
        QVERIFY(edited && edited->valuesOnly);
        QVERIFY2(edited->describe().find("the same batches and rows (B01:10 B02:12) hold other values") !=
                     std::string::npos,
                 edited->describe().c_str());
        QVERIFY(!workflow::dataChangeSince("B01:10 B02:12", workflow::dataFingerprint(summary)));

        summary.batches.pop_back();
        const auto shorter = workflow::dataChangeSince(saved, workflow::dataFingerprint(summary));
        QVERIFY(shorter && !shorter->valuesOnly);
        QCOMPARE(shorter->describe(), std::string("batches and rows then: B01:10 B02:12; now: B01:10"));
        QVERIFY(workflow::dataChangeSince("B01:10 B02:12", workflow::dataFingerprint(summary)));
    }

    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_data = m_dir.filePath("plant");
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(5, plant::PlantKind::Lumped);
        g.plant.batches = 3;
        g.plant.samples = 1500;
        g.outFolder = m_data.toStdString();
        g.truthPath = m_dir.filePath("truth.json").toStdString();
        auto r = workflow::Session().generate(g);
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QCOMPARE(r->files.size(), std::size_t(3));
        QVERIFY(std::filesystem::exists(g.truthPath));
        QCOMPARE(r->ending.termination, Termination::Completed);
    }

    void actionsNeedData() {
        workflow::Session s;
        QVERIFY(!s.hasData());
        for (const auto& e : {s.simulate().error(), s.calibrate().error(), s.train().error(),
                              s.evaluate().error(), s.ablation().error(), s.inspect().error()}) {
            QCOMPARE(e.code, ErrorCode::NoDataLoaded);
            QCOMPARE(exitCodeFor(e.kind), 2);
        }
        QCOMPARE(s.open({}).error().code, ErrorCode::InvalidOption);
    }

    // generate never leaves a mixed data set: batch files it would not overwrite are refused, before
    // anything is written; an onset after the batches' end is refused; the truth names each onset.
    void generateRefusesStaleBatchesAndLateOnsets() {
        QTemporaryDir dir;
        workflow::GenerateOptions g;
        g.plant.batches = 3;
        g.plant.samples = 300;
        g.outFolder = dir.filePath("set").toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
        const auto b02 = std::filesystem::last_write_time(std::filesystem::path(g.outFolder) / "B02.csv");
        g.plant.batches = 1;
        g.plant.seed = 2;
        auto smaller = workflow::Session().generate(g);
        QVERIFY(!smaller.ok());
        QCOMPARE(exitCodeFor(smaller.error().kind), 2);
        QVERIFY(smaller.error().reason.find("B02.csv, B03.csv") != std::string::npos);
        QVERIFY(std::filesystem::last_write_time(std::filesystem::path(g.outFolder) / "B02.csv") == b02);
        g.plant.batches = 3; // the same files: overwritten (an interrupted run repeated)
        QVERIFY(workflow::Session().generate(g).ok());

        workflow::GenerateOptions late;
        late.plant.batches = 1;
        late.plant.samples = 300;
        late.plant.effects[plant::Mechanism::MoistureMeterOffset] = 0.8;
        late.plant.effectOnsetS[plant::Mechanism::MoistureMeterOffset] = 300;
        late.outFolder = dir.filePath("late").toStdString();
        late.truthPath = dir.filePath("late.json").toStdString();
        auto refused = workflow::Session().generate(late);
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().reason.find("after each batch's end") != std::string::npos);
        late.plant.effectOnsetS[plant::Mechanism::MoistureMeterOffset] = 120;
        QVERIFY(workflow::Session().generate(late).ok());
        std::ifstream in(late.truthPath);
        const auto truth = nlohmann::json::parse(in);
        QCOMPARE(truth.at("effect_onsets_s").at("moisture_meter_offset").get<double>(), 120.0);
    }

    // A column with no value at all is named where it is read, and an action on data that keep no
    // row says why instead of a bare "0 usable rows".
    void anEmptyColumnIsNamedAndStopsTheActionsWithItsName() {
        QTemporaryDir dir;
        const QString path = dir.filePath("B01.csv");
        {
            std::ifstream in(m_data.toStdString() + "/B01.csv");
            std::ofstream out(path.toStdString());
            std::string line;
            int xIn = -1;
            while (std::getline(in, line)) {
                if (line.rfind('#', 0) == 0) {
                    out << line << '\n';
                    continue;
                }
                std::vector<std::string> cells;
                std::stringstream ss(line);
                for (std::string c; std::getline(ss, c, ',');) {
                    cells.push_back(c);
                }
                if (xIn < 0) {
                    xIn = static_cast<int>(std::find(cells.begin(), cells.end(), "X_in_pct") - cells.begin());
                } else {
                    cells.at(static_cast<std::size_t>(xIn)) = "NaN";
                }
                for (std::size_t i = 0; i < cells.size(); ++i) {
                    out << (i ? "," : "") << cells[i];
                }
                out << '\n';
            }
        }
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = path.toStdString();
        auto opened = s.open(o);
        QVERIFY(opened.ok());
        const auto& notes = opened->summary.notes;
        QVERIFY(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
            return n.find("column 'X_in_pct' holds no value in any of its 1500 rows") != std::string::npos;
        }));
        auto cal = s.calibrate(quickCalibration());
        QVERIFY(!cal.ok());
        QCOMPARE(exitCodeFor(cal.error().kind), 3);
        QVERIFY2(cal.error().reason.find("X_in_pct") != std::string::npos, cal.error().reason.c_str());
        QVERIFY(s.inspect().ok()); // inspect still shows what was loaded
    }

    void rejectedLoadChangesNothing() {
        workflow::Session s;
        workflow::OpenOptions good;
        good.dataPath = DRYTWIN_TEST_DATA "/good/B01.csv";
        auto first = s.open(good);
        QVERIFY(first.ok());
        const auto before = s.dataSet();
        QCOMPARE(before->batches.size(), std::size_t(1));

        workflow::OpenOptions bad;
        bad.dataPath = DRYTWIN_TEST_DATA "/malformed";
        auto second = s.open(bad);
        QVERIFY(!second.ok());
        QCOMPARE(exitCodeFor(second.error().kind), 3);
        QCOMPARE(second.error().causes.size(), std::size_t(4)); // every rejected file, each with its place
        bool sawTextInNumber = false;
        for (const auto& c : second.error().causes) {
            sawTextInNumber = sawTextInNumber || (c.code == ErrorCode::TextInNumber && c.args.at(3) == "wet");
        }
        QVERIFY(sawTextInNumber);
        QCOMPARE(s.dataSet().get(), before.get()); // the same, untouched data set

        workflow::OpenOptions missingModel = good;
        missingModel.modelPath = DRYTWIN_TEST_DATA "/models/out_of_bounds.json";
        auto third = s.open(missingModel);
        QVERIFY(!third.ok());
        QCOMPARE(third.error().code, ErrorCode::ModelFileInvalid);
        QCOMPARE(s.dataSet().get(), before.get()); // a bad model file does not load the data either
    }

    // A real line is never the model: on the distributed plant with no mechanism and no drift,
    // the calibrated PBM still leaves a structured error (issue #22's bar).
    void calibratedModelLeavesStructureOnTheDistributedPlant() {
        QTemporaryDir dir;
        workflow::GenerateOptions g;
        g.plant.plant = plant::PlantKind::Distributed;
        g.plant.seed = 21;
        g.plant.batches = 4;
        g.plant.samples = 3000;
        g.outFolder = dir.filePath("null").toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = g.outFolder;
        QVERIFY(s.open(o).ok());
        auto cal = s.calibrate();
        QVERIFY2(cal.ok(), cal ? "" : cal.error().message().c_str());
        auto ev = s.evaluate();
        QVERIFY2(ev.ok(), ev ? "" : ev.error().message().c_str());
        const auto pbm = std::find_if(ev->evaluation.models.begin(), ev->evaluation.models.end(),
                                      [](const auto& m) { return m.name == "pbm"; });
        QVERIFY(pbm != ev->evaluation.models.end());
        const QString what = QString("held-out MAE X_out %1 % wb, Ljung-Box p %2")
                                 .arg(pbm->moisture.mae)
                                 .arg(pbm->moisture.ljungBoxP);
        qInfo("%s", qPrintable(what));
        QVERIFY2(pbm->moisture.mae >= 0.04, qPrintable(what));
        QVERIFY2(pbm->moisture.ljungBoxP < 1e-6, qPrintable(what));
    }

    void simulateCalibrateTrainEvaluate() {
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = m_data.toStdString();
        QVERIFY(s.open(o).ok());
        QCOMPARE(s.siBatches().size(), std::size_t(3));

        auto sim = s.simulate();
        QVERIFY(sim.ok());
        QCOMPARE(sim->simulations.size(), std::size_t(3));
        QCOMPARE(sim->fits.size(), std::size_t(3));
        for (const auto& f : sim->fits) {
            QVERIFY(std::isfinite(f.maeXOutPct) && f.maeXOutPct > 0 && f.maeXOutPct < 5);
        }
        QVERIFY(s.latest().simulate.has_value());
        // The CSV `simulate` writes: predictions beside the measured outputs (last columns), the
        // inputs without the float noise of their round trip through SI units.
        {
            const std::string csv = io::simulationCsv(s.siBatches(), sim->simulations);
            const std::string header = csv.substr(0, csv.find('\n'));
            const std::string measured = ",X_out_pct,T_out_C,X_hdt_pct,T_hdt_C";
            QVERIFY2(header.size() > measured.size() &&
                         header.compare(header.size() - measured.size(), measured.size(), measured) == 0,
                     header.c_str());
            const std::string firstRow =
                csv.substr(header.size() + 1, csv.find('\n', header.size() + 1) - header.size() - 1);
            QVERIFY2(firstRow.find("99999") == std::string::npos &&
                         firstRow.find("00000") == std::string::npos,
                     firstRow.c_str());
            const double measuredXOut = units::dryToWetPct(s.siBatches().front().xOutDb.front());
            char expected[32];
            std::snprintf(expected, sizeof expected, ",%.10g,", measuredXOut);
            QVERIFY2(firstRow.find(expected) != std::string::npos, firstRow.c_str());
        }

        const double hBefore = s.model().parameters[Param::h_HDT];
        auto cal = s.calibrate(quickCalibration());
        QVERIFY2(cal.ok(), cal ? "" : cal.error().message().c_str());
        QVERIFY(cal->calibration.after.loss < cal->calibration.before.loss);
        QVERIFY(s.model().parameters[Param::h_HDT] != hBefore);
        QCOMPARE(s.model().parameters[Param::h_HDT], cal->calibration.parameters[Param::h_HDT]);
        QVERIFY(s.model().calibration.has_value());
        QVERIFY(cal->ending.termination == Termination::Converged ||
                cal->ending.termination == Termination::BudgetExhausted);

        auto trained = s.train(quickTraining());
        QVERIFY2(trained.ok(), trained ? "" : trained.error().message().c_str());
        QVERIFY(s.model().pgrlCc && s.model().extInput && s.model().lstm);
        QVERIFY(!trained->onDefaultParameters);
        QVERIFY(trained->pgrlCc->stability().certified);
        // Settings chosen inside the training part: every candidate scored, the best one used.
        QCOMPARE(trained->selection.size(), std::size_t(4));
        QCOMPARE(std::count_if(trained->selection.begin(), trained->selection.end(),
                               [](const auto& c) { return c.chosen; }),
                 std::ptrdiff_t(1));
        for (const auto& c : trained->selection) {
            QVERIFY(std::isfinite(c.validationSkill) && c.validationSkill > 0);
            if (c.chosen) {
                QCOMPARE(trained->pgrlCc->options().residualLags, c.lags);
                QCOMPARE(trained->pgrlCc->options().orthogonalProjection, c.orthogonalProjection);
                for (const auto& other : trained->selection) {
                    QVERIFY(c.validationSkill <= other.validationSkill);
                }
            }
        }
        QCOMPARE(trained->extInput->options().residualLags, trained->pgrlCc->options().residualLags);

        auto ev = s.evaluate();
        QVERIFY2(ev.ok(), ev ? "" : ev.error().message().c_str());
        QStringList names;
        for (const auto& m : ev->evaluation.models) {
            names << QString::fromStdString(m.name);
        }
        QCOMPARE(names, QStringList({"pbm", "persistence", "pbm_residual_hold", "lstm", "ext_input_residual",
                                     "pgrl_cc"}));
        QVERIFY(ev->diagnostics.hasPgrlCcEigenvalues);
        QCOMPARE(ev->diagnostics.models.size(), std::size_t(6));
        QVERIFY(ev->diagnostics.pgrlCcAfter.spectralRadius <=
                ev->diagnostics.pgrlCcBefore.spectralRadius + 1e-12);
        // The hybrid beats the physics model alone one step ahead on this plant data.
        QVERIFY(ev->evaluation.models.back().moisture.mae < ev->evaluation.models.front().moisture.mae);
        // The horizon curve: 1 … 180 steps with the headline horizon, skill 1 for the better
        // reference at every horizon, the one-step column equal to the one-step metrics.
        const auto& e = ev->evaluation;
        QCOMPARE(e.horizons.front(), 1);
        QCOMPARE(e.horizons.back(), 180);
        QVERIFY(std::count(e.horizons.begin(), e.horizons.end(), e.multiStepHorizon) == 1);
        for (std::size_t h = 0; h < e.horizons.size(); ++h) {
            const double best =
                std::min(e.models[1].skillMoistureByHorizon[h], e.models[2].skillMoistureByHorizon[h]);
            QVERIFY(std::abs(best - 1.0) < 1e-12);
        }
        for (const auto& m : e.models) {
            QCOMPARE(m.moistureByHorizon.size(), e.horizons.size());
            QCOMPARE(m.moistureByHorizon.front().mae, m.moisture.mae);
        }
        // Persistence gets worse with the horizon; the PBM does not depend on it.
        QVERIFY(e.models[1].moistureByHorizon.back().mae > 2 * e.models[1].moistureByHorizon.front().mae);
        QCOMPARE(e.models[0].moistureByHorizon.back().mae, e.models[0].moisture.mae);
        // The free run: the PBM and both residual models, never better than seeing the outputs.
        QCOMPARE(e.freeRun.size(), std::size_t(3));
        QCOMPARE(e.freeRun[0].moisture.mae, e.models[0].moisture.mae);
        QVERIFY(e.freeRun[2].moisture.mae > e.models.back().moisture.mae);

        // Recalibrating drops the residual models, which were learnt on the old parameters.
        auto again = s.calibrate(quickCalibration());
        QVERIFY(again.ok());
        QVERIFY(again->droppedResidualModels);
        QVERIFY(!s.model().hasResidualModels());
    }

    void calibrationCancelKeepsModel() {
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = m_data.toStdString();
        QVERIFY(s.open(o).ok());
        const auto before = s.model().parameters;
        int calls = 0;
        auto r = s.calibrate(quickCalibration(), stopAfter(5, ProgressAction::Stop, &calls));
        QVERIFY(!r.ok());
        QCOMPARE(r.error().code, ErrorCode::Cancelled);
        QCOMPARE(exitCodeFor(r.error().kind), 130);
        QCOMPARE(s.model().parameters[Param::h_HDT], before[Param::h_HDT]);
        QCOMPARE(s.model().parameters[Param::k_HDT], before[Param::k_HDT]);
        QVERIFY(!s.model().calibration.has_value());
    }

    void calibrationStopKeepsBest() {
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = m_data.toStdString();
        QVERIFY(s.open(o).ok());
        int calls = 0;
        auto r = s.calibrate(quickCalibration(), stopAfter(12, ProgressAction::StopKeepBest, &calls));
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QCOMPARE(r->ending.termination, Termination::StoppedKeptBest);
        const auto& history = r->calibration.history;
        QVERIFY(history.size() >= 12 && history.size() < 40); // stopped early, not at the budget of 60
        // The parameters returned are the best found so far: the best evaluation, or the start
        // when none beat it.
        const auto best = std::min_element(history.begin(), history.end(),
                                           [](const auto& a, const auto& b) { return a.loss < b.loss; });
        const bool improved = best->loss < r->calibration.before.loss;
        QCOMPARE(s.model().parameters[Param::h_HDT],
                 improved ? best->values[0] : r->startParameters[Param::h_HDT]);
        QCOMPARE(s.model().parameters[Param::k_HDT],
                 improved ? best->values[1] : r->startParameters[Param::k_HDT]);
        // The fit after is recomputed with sensitivities (for the intervals), whose error control
        // differs slightly from the plain runs of the search.
        const double bestLoss = std::min(best->loss, r->calibration.before.loss);
        QVERIFY(std::abs(r->calibration.after.loss - bestLoss) < 1e-3 * bestLoss);
    }

    void failedStepsSayWhy() {
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = m_data.toStdString();
        QVERIFY(s.open(o).ok());
        // An impossible parameter is refused and changes nothing.
        const double h = s.model().parameters[Param::h_HDT];
        const auto st = s.setParameter(Param::h_HDT, -5);
        QVERIFY(!st.ok());
        QCOMPARE(st.error().code, ErrorCode::ParameterOutOfRange);
        QCOMPARE(s.model().parameters[Param::h_HDT], h);
        // A mechanism extension in the model is simulated, not ignored: a meter offset of
        // 0.5 % wb moves every predicted outlet moisture by that much.
        auto base = s.simulate();
        QVERIFY(base.ok());
        QVERIFY(s.setParameter(Param::X_meter_offset, 0.5).ok());
        auto shifted = s.simulate();
        QVERIFY(shifted.ok());
        const double x0 = units::dryToWetPct(base->simulations[0].xOutDb[100]);
        const double x1 = units::dryToWetPct(shifted->simulations[0].xOutDb[100]);
        QVERIFY(std::abs(x1 - x0 - 0.5) < 1e-9);
        // Options are validated before any work.
        workflow::EvaluateOptions bad;
        bad.evaluation.horizonSteps = 0;
        QCOMPARE(s.evaluate(bad).error().code, ErrorCode::InvalidOption);
        workflow::CalibrateOptions noRows = quickCalibration();
        noRows.subsetStride = 0;
        QVERIFY(!s.calibrate(noRows).ok());
    }

    void modelFilesRoundTripAndReadVersion1() {
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = m_data.toStdString();
        QVERIFY(s.open(o).ok());
        QVERIFY(s.calibrate(quickCalibration()).ok());
        QVERIFY(s.train(quickTraining()).ok());
        auto model = s.model();
        model.mechanisms["moisture_meter_offset"] = {0.0, "% wb", -0.1, 0.1};
        s.setModel(model);
        const std::string path = m_dir.filePath("model-v2.json").toStdString();
        QVERIFY(s.saveModel(path).ok());

        auto back = io::readModelFile(path);
        QVERIFY2(back.ok(), back ? "" : back.error().message().c_str());
        QCOMPARE(back->parameters[Param::h_HDT], s.model().parameters[Param::h_HDT]);
        QVERIFY(back->pgrlCc && back->extInput && back->lstm);
        QCOMPARE(back->pgrlCc->a(), s.model().pgrlCc->a());
        QCOMPARE(back->mechanisms.at("moisture_meter_offset").ci95High, 0.1);
        QCOMPARE(io::formatModelFile(*back), io::formatModelFile(s.model()));

        // The same model as version 1 wrote it: learnt models at the top level, plus a key of
        // another tool that must survive a round trip.
        auto j = nlohmann::json::parse(*readWholeFile(path));
        j["format_version"] = 1;
        for (const auto& [key, value] : j["residual_models"].items()) {
            j[key] = value;
        }
        j.erase("residual_models");
        j.erase("mechanisms");
        j["site_notes"] = {{"line", 2}};
        auto v1 = io::parseModelFile(j.dump(), "v1.json");
        QVERIFY2(v1.ok(), v1 ? "" : v1.error().message().c_str());
        QVERIFY(v1->pgrlCc && v1->lstm);
        QCOMPARE(v1->pgrlCc->a(), s.model().pgrlCc->a());
        const auto rewritten = nlohmann::json::parse(io::formatModelFile(*v1));
        QCOMPARE(rewritten["format_version"].get<int>(), io::kModelFormatVersion);
        QCOMPARE(rewritten["site_notes"]["line"].get<int>(), 2);
        QVERIFY(rewritten.contains("residual_models"));

        // Unknown intervals (NaN, written as null) read back; a wrongly typed key is an error, not a crash.
        auto withNan = s.model();
        withNan.calibration->estimates[0].ci95Low = std::nan("");
        auto nanBack = io::parseModelFile(io::formatModelFile(withNan), "nan.json");
        QVERIFY2(nanBack.ok(), nanBack ? "" : nanBack.error().message().c_str());
        QVERIFY(std::isnan(nanBack->calibration->estimates[0].ci95Low));
        auto wrongType = nlohmann::json::parse(io::formatModelFile(withNan));
        wrongType["calibration"]["loss_after"] = "small";
        auto typed = io::parseModelFile(wrongType.dump(), "typed.json");
        QVERIFY(!typed.ok());
        QCOMPARE(typed.error().code, ErrorCode::ModelFileInvalid);

        // A newer version than this DryTwin reads is refused with the key named.
        j["format_version"] = io::kModelFormatVersion + 1;
        auto newer = io::parseModelFile(j.dump(), "newer.json");
        QVERIFY(!newer.ok());
        QVERIFY(QString::fromStdString(newer.error().message()).contains("format_version"));
    }

    void discoverExtendsACopyOfTheModel() {
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = m_data.toStdString();
        QVERIFY(s.open(o).ok());
        QVERIFY(s.calibrate(quickCalibration()).ok());
        const auto before = s.model().parameters;
        auto r = s.discover();
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        // The session's model is untouched until the user takes the extended one.
        QCOMPARE(s.model().parameters[Param::h_HDT], before[Param::h_HDT]);
        QVERIFY(s.latest().discover.has_value());
        const auto& ext = r->extendedModel;
        for (const auto& f : r->discovery.findings) {
            QCOMPARE(ext.parameters[f.parameter], f.value);
            QCOMPARE(ext.mechanisms.at(f.cause).ci95High, f.ci95High);
        }
        QCOMPARE(ext.parameters[Param::k_HDT], r->discovery.parameters[Param::k_HDT]);
        QVERIFY(r->hasHybrid && ext.pgrlCc); // the residual model is retrained on the extended model
        QVERIFY(std::isfinite(r->hybridMaeMoistureAfter));
        // The references PGRL-CC must beat are scored on the same held-out rows: the last
        // measurement held does not depend on the model, so it is evaluate()'s persistence.
        auto ev = s.evaluate();
        QVERIFY2(ev.ok(), ev ? "" : ev.error().message().c_str());
        const auto persistence = std::find_if(ev->evaluation.models.begin(), ev->evaluation.models.end(),
                                              [](const auto& m) { return m.name == "persistence"; });
        QVERIFY(persistence != ev->evaluation.models.end());
        const auto& ref = r->references;
        QCOMPARE(ref.persistenceMoisture, persistence->moisture.mae);
        QCOMPARE(ref.persistenceTemperature, persistence->temperature.mae);
        for (double mae : {ref.pbmHoldMoistureBefore, ref.pbmHoldMoistureAfter, ref.pbmHoldTemperatureBefore,
                           ref.pbmHoldTemperatureAfter}) {
            QVERIFY(std::isfinite(mae) && mae > 0);
        }
        // The JSON says whether the model offered for forecasting beats the better of the two.
        const auto j = nlohmann::json::parse(io::discoveryJson(
            r->discovery, r->hasHybrid, r->hybridMaeMoistureBefore, r->hybridMaeMoistureAfter,
            r->hybridMaeTemperatureBefore, r->hybridMaeTemperatureAfter, r->keptStartingModel, ref));
        const double offeredX = r->keptStartingModel ? r->hybridMaeMoistureBefore : r->hybridMaeMoistureAfter;
        QCOMPARE(j["hybrid"]["references"]["persistence"]["mae_moisture"].get<double>(),
                 ref.persistenceMoisture);
        QCOMPARE(j["hybrid"]["beats_references"]["moisture"].get<bool>(),
                 offeredX < std::min(ref.persistenceMoisture, r->keptStartingModel
                                                                  ? ref.pbmHoldMoistureBefore
                                                                  : ref.pbmHoldMoistureAfter));
        // Extended model files keep the mechanisms with their intervals.
        const std::string path = m_dir.filePath("extended.json").toStdString();
        QVERIFY(io::writeModelFile(ext, path).ok());
        auto back = io::readModelFile(path);
        QVERIFY(back.ok());
        for (const auto& f : r->discovery.findings) {
            QCOMPARE(back->parameters[f.parameter], f.value);
            QCOMPARE(back->mechanisms.at(f.cause).ci95Low, f.ci95Low);
        }
        s.setModel(ext); // "extend the model"
        QCOMPARE(s.model().parameters[Param::k_HDT], ext.parameters[Param::k_HDT]);
    }

    void pipelineWritesEveryStage() {
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = m_data.toStdString();
        QVERIFY(s.open(o).ok());
        workflow::PipelineOptions p;
        p.outFolder = m_dir.filePath("report").toStdString();
        p.calibrate = quickCalibration();
        p.train = quickTraining();
        // A one-minute closed loop instead of the bundled 1,000 steps (that one is benchmarked).
        const std::string scenario = m_dir.filePath("short-scenario.json").toStdString();
        std::ofstream(scenario) << R"({"name": "short", "length_s": 60, "warmup_s": 150, "seed": 2,
                                       "setpoint_steps": [{"at_s": 10, "to_pct": 12.6}]})";
        p.mpc.scenarioPath = scenario;
        auto r = s.pipeline(p);
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QStringList stages;
        for (const auto& st : r->stages) {
            stages << QString::fromStdString(st.name);
            for (const auto& f : st.files) {
                QVERIFY2(std::filesystem::exists(f), f.c_str());
            }
        }
        QCOMPARE(stages, QStringList({"inspect", "calibrate", "train", "evaluate", "ablation", "discover",
                                      "mpc", "report"}));
        // Table 3's seven rows and four more: the other energy balance, Eq. 27 literally, the pull,
        // the paper's level form (the trivial predictors not nested).
        QCOMPARE(r->ablation.rows.size(), std::size_t(11));
        for (const auto& row : r->ablation.rows) {
            QVERIFY(std::isfinite(row.maeMoisture) && std::isfinite(row.regimeMaeMoisture) &&
                    std::isfinite(row.maeMoistureMultiStep));
            // Further ahead is not easier. On these three short batches with white measurement
            // noise the velocity form's one-step forecast starts from the last measurement, noise
            // included, and sits at the noise floor with the 30-step one (0.0586 and 0.0577 % wb
            // for the paper's energy balance): a tie within 5 % passes, a 30-step forecast
            // clearly better than the one-step one does not.
            QVERIFY2(row.maeMoistureMultiStep > 0.95 * row.maeMoisture,
                     (row.variant + ": " + std::to_string(row.maeMoisture) + " one step, " +
                      std::to_string(row.maeMoistureMultiStep) + " multi-step")
                         .c_str());
        }
        // Physics variants refit h_HDT, k_HDT; learning variants keep the model's.
        QVERIFY(r->ablation.rows[1].recalibrated && !r->ablation.rows[5].recalibrated);
        QCOMPARE(r->ablation.rows[5].hHdt, s.model().parameters[Param::h_HDT]);
        // The files hold the session's own numbers.
        auto saved = io::readModelFile(p.outFolder + "/model.json");
        QVERIFY(saved.ok());
        QCOMPARE(saved->parameters[Param::k_HDT], s.model().parameters[Param::k_HDT]);
        const auto ev = nlohmann::json::parse(*readWholeFile(p.outFolder + "/evaluate.json"));
        QCOMPARE(ev["models"]["pgrl_cc"]["moisture"]["mae"].get<double>(),
                 r->evaluate.evaluation.models.back().moisture.mae);
        // The report shows the horizon curve and says where PGRL-CC loses to a reference, if anywhere.
        const auto report = readWholeFile(p.outFolder + "/report.md");
        QVERIFY(report.ok());
        QVERIFY(report->find("Skill for moisture by horizon") != std::string::npos);
        QVERIFY(report->find("reference predictors in moisture at") != std::string::npos);
        QVERIFY(report->find("Eq. 30 side by side") != std::string::npos);
        QVERIFY(report->find("extrapolation") != std::string::npos);
        // The closed loop: mpc.json holds the run's numbers and the report its Table 2.
        const auto mpc = nlohmann::json::parse(*readWholeFile(p.outFolder + "/mpc.json"));
        QCOMPARE(mpc["steps"].get<int>(), 60);
        QCOMPARE(mpc["controllers"]["pbm"]["iae"].get<double>(),
                 r->mpc.closedLoop.runs.front().metrics.iaePctS);
        QVERIFY(mpc["controllers"].contains("pi") && mpc["controllers"].contains("pgrl_cc"));
        QVERIFY(report->find("Closed-loop MPC (paper Table 2)") != std::string::npos);
        // Discovery's section puts PGRL-CC beside the two references, with the numbers of discover.json.
        const auto disc = nlohmann::json::parse(*readWholeFile(p.outFolder + "/discover.json"));
        const double persistenceX = disc["hybrid"]["references"]["persistence"]["mae_moisture"].get<double>();
        QVERIFY(persistenceX > 0);
        char row[96];
        std::snprintf(row, sizeof row, "| the last measurement held | %.4g | ", persistenceX);
        QVERIFY2(report->find(row) != std::string::npos, row);

        // A project keeps these results (issue #26): the archive reads back into the same structs,
        // NaN included, and writes the same text again.
        const std::string archived = workflow::latestResultsJson(s.latest());
        auto back = workflow::parseLatestResults(archived, "p.drytwin.results.json");
        QVERIFY2(back.ok(), back ? "" : back.error().message().c_str());
        QCOMPARE(workflow::latestResultsJson(*back), archived);
        QCOMPARE(back->discover->discovery.findings.size(), r->discover.discovery.findings.size());
        QCOMPARE(back->discover->discovery.verdict, r->discover.discovery.verdict);
        QCOMPARE(back->discover->extendedModel.parameters[Param::k_HDT],
                 r->discover.extendedModel.parameters[Param::k_HDT]);
        QCOMPARE(back->discover->extendedModel.pgrlCc != nullptr,
                 r->discover.extendedModel.pgrlCc != nullptr);
        QCOMPARE(back->discover->references.persistenceMoisture, r->discover.references.persistenceMoisture);
        QCOMPARE(back->discover->references.pbmHoldTemperatureAfter,
                 r->discover.references.pbmHoldTemperatureAfter);
        QCOMPARE(back->evaluate->evaluation.models.back().moisture.mae,
                 r->evaluate.evaluation.models.back().moisture.mae);
        QCOMPARE(back->mpc->closedLoop.runs.front().xOutTruePct, r->mpc.closedLoop.runs.front().xOutTruePct);
        QCOMPARE(back->mpc->closedLoop.scenario.setpointSteps.size(), std::size_t(1));
        QCOMPARE(back->calibrate->calibration.estimates.size(), r->calibrate.calibration.estimates.size());
        QCOMPARE(back->ablation->rows.size(), std::size_t(11));
        QVERIFY(!back->simulate && !back->train); // re-run on opening / in the model file
        auto damaged =
            workflow::parseLatestResults(archived.substr(0, archived.size() / 2), "p.results.json");
        QVERIFY(!damaged.ok() && damaged.error().place == "p.results.json");
        auto foreign = workflow::parseLatestResults(R"({"format": "something else"})", "x.json");
        QVERIFY(!foreign.ok() &&
                foreign.error().reason.find("not a DryTwin results file") != std::string::npos);

        // A cancelled pipeline keeps the model it started with, and the folder's finished report
        // as it was: nothing of the cancelled run is moved in, its staging folder is gone.
        const std::filesystem::path folder(p.outFolder);
        QVERIFY(!std::filesystem::exists(folder / ".drytwin-pipeline-partial"));
        const auto reportTime = std::filesystem::last_write_time(folder / "report.md");
        const auto inspectTime = std::filesystem::last_write_time(folder / "inspect.json");
        workflow::Session c;
        QVERIFY(c.open(o).ok());
        int calls = 0;
        auto cancelled = c.pipeline(p, stopAfter(3, ProgressAction::Stop, &calls));
        QVERIFY(!cancelled.ok());
        QCOMPARE(cancelled.error().kind, ErrorKind::Cancelled);
        QVERIFY(!c.model().calibration.has_value());
        QVERIFY(std::filesystem::last_write_time(folder / "report.md") == reportTime);
        QVERIFY(std::filesystem::last_write_time(folder / "inspect.json") ==
                inspectTime); // written before the stop
        QVERIFY(!std::filesystem::exists(folder / ".drytwin-pipeline-partial"));
    }
};

QTEST_APPLESS_MAIN(TestSession)
#include "TestSession.moc"
