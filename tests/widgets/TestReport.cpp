// The pipeline's HTML/PDF report: built from the run's result structs with the GUI's plot code,
// and its numbers are the ones in the JSON files written beside it.
#include "report/ReportWriter.h"
#include "workflow/Session.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace drytwin;

class TestReport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void reportMatchesTheJsonFiles() {
        QTemporaryDir dir;
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(6, plant::PlantKind::Lumped);
        g.plant.batches = 2;
        g.plant.samples = 1500;
        g.outFolder = dir.filePath("plant").toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
        workflow::Session s;
        workflow::OpenOptions o;
        o.dataPath = g.outFolder;
        QVERIFY(s.open(o).ok());
        workflow::PipelineOptions p;
        p.outFolder = dir.filePath("out").toStdString();
        p.calibrate.calibration.maxEvaluations = 60;
        p.calibrate.calibration.globalEvaluations = 20;
        p.train.lstm.epochs = 2;
        p.train.lstm.hidden = 8;
        p.train.selection.lags = {4, 8};
        const std::string scenario = dir.filePath("s.json").toStdString();
        std::ofstream(scenario) << R"({"name": "r", "length_s": 60, "warmup_s": 150, "seed": 3})";
        p.mpc.scenarioPath = scenario;
        auto r = s.pipeline(p);
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        widgets::ReportContext context;
        context.command = QStringLiteral("drytwin pipeline --data plant --out out");
        for (const auto& b : s.dataSet()->batches) {
            context.dataFiles.push_back(b.sourcePath);
        }
        auto files = widgets::writeHtmlPdfReport(*r, s.siBatches(), context, dir.filePath("out"));
        QVERIFY2(files.ok(), files ? "" : files.error().message().c_str());
        QCOMPARE(files->size(), 2);
        QFile html(files->at(0));
        QVERIFY(html.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(html.readAll());
        QCOMPARE(text.count(QStringLiteral("<svg")), 9); // every figure inline
        // The residual's ACF on its own linear lag axis, the PSD on a logarithmic frequency axis:
        // two figures (one stack shares its x axis, and drew lags 0-40 s on 0.001-1 Hz).
        const auto acf = text.indexOf(QStringLiteral("Paper Fig. 4 (a)"));
        const auto psd = text.indexOf(QStringLiteral("Paper Fig. 4 (b)"));
        QVERIFY(acf > 0 && psd > acf);
        QVERIFY(text.mid(0, acf).lastIndexOf(QStringLiteral("lag [s]")) >
                text.mid(0, acf).lastIndexOf(QStringLiteral("<svg")));
        QVERIFY(!text.contains(QStringLiteral("lag [s] / frequency [Hz]")));
        QVERIFY(text.contains(QStringLiteral("Paper Fig. 5")));
        // The technical names the workbench keeps to its tooltips, in the appendix (issue #72 item 10).
        QVERIFY(text.contains(QStringLiteral("Appendix: the methods behind the workbench's words")) &&
                text.contains(QStringLiteral("Diebold-Mariano")) && text.contains(QStringLiteral("Holm")) &&
                text.contains(QStringLiteral("Newey-West")) && text.contains(QStringLiteral("BOBYQA")));
        // Table 2 says which line the controllers ran against, and how often each fell back.
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("<th[^>]*>fallbacks</th>"))));
        // The ablation's variants in the paper's words, not only their keys.
        QVERIFY(text.contains(QStringLiteral("no control-consistent weights")));
        QVERIFY(text.contains(QStringLiteral("on DryTwin's virtual")) &&
                text.contains(QStringLiteral("band ±")));
        // Numbers equal to the JSON beside it, in the report's own formatting.
        const auto json = [&](const char* name) {
            QFile f(dir.filePath(QStringLiteral("out/%1").arg(name)));
            f.open(QIODevice::ReadOnly);
            return nlohmann::json::parse(f.readAll().toStdString());
        };
        const double iae = json("mpc.json")["controllers"]["pbm"]["iae"].get<double>();
        // Named in words, as the workbench names them (in English, whatever its language).
        QVERIFY(text.contains(QStringLiteral("<td>Physics model</td><td>%1</td>").arg(iae, 0, 'f', 1)));
        const double mae = json("evaluate.json")["models"]["pgrl_cc"]["moisture"]["mae"].get<double>();
        QVERIFY(text.contains(
            QStringLiteral("<td>Physics + learnt correction (PGRL-CC)</td><td>%1</td>").arg(mae, 0, 'f', 4)));
        // Every table's header in <thead>, which the PDF repeats on each page a table runs over.
        QCOMPARE(text.count(QStringLiteral("<thead>")), text.count(QStringLiteral("<table")));
        // The reproducibility block hashes every data file.
        QVERIFY(text.contains(QString::fromStdString(context.dataFiles.front())));
        QFile pdf(files->at(1));
        QVERIFY(pdf.open(QIODevice::ReadOnly));
        QVERIFY(pdf.read(5) == "%PDF-");
        QVERIFY(pdf.size() > 50000);
    }
};

QTEST_MAIN(TestReport)
#include "TestReport.moc"
