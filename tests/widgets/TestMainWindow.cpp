#include "MainWindow.h"

#include <QListWidget>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>

using drytwin::widgets::MainWindow;

namespace {
void writeText(const QString& path, const std::string& text) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << text;
}
const char* kGood =
    "time_s,T_hot_C,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct,X_out_pct,T_out_C\n"
    "0,170,6000,22,20,50,12.5,55\n1,171,6000,22,20,50,12.6,55.1\n2,171,6000,22,20,50,12.7,55.3\n";
} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void hasMenusAndAbout() {
        MainWindow w;
        QStringList menus;
        for (auto* a : w.menuBar()->actions()) {
            menus << a->text();
        }
        QVERIFY(menus.contains("&File"));
        QVERIFY(menus.contains("&Help"));
        const QString about = MainWindow::aboutText();
        for (const char* lib : {"Qt", "Qwt", "VTK", "SUNDIALS", "NLopt", "Ipopt", "Eigen"}) {
            QVERIFY2(about.contains(lib), lib);
        }
        QVERIFY(w.statusBar() != nullptr);
    }

    void loadsOnWorkerAndKeepsDataOnRejectedFile() {
        QTemporaryDir dir;
        writeText(dir.filePath("good.csv"), kGood);
        writeText(dir.filePath("bad.csv"), "time_s;T_hot_C\n0;1\n");
        MainWindow w;
        QSignalSpy spy(&w, &MainWindow::loadFinished);
        QSignalSpy shown(&w, &MainWindow::simulationShown);
        w.openDataSet(dir.filePath("good.csv"));
        QVERIFY(spy.wait(10000));
        QCOMPARE(spy.takeFirst().at(0).toBool(), true);
        QCOMPARE(w.dataSet().batches.size(), std::size_t(1));
        auto* list = w.findChild<QListWidget*>();
        QCOMPARE(list->count(), 1);
        // The physics model's predictions follow on the worker thread and are drawn dashed.
        QVERIFY(shown.count() > 0 || shown.wait(20000));
        bool modelDrawn = false;
        for (auto* plot : w.findChildren<QwtPlot*>()) {
            for (auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
                auto* curve = static_cast<QwtPlotCurve*>(item);
                modelDrawn =
                    modelDrawn || (curve->title().text().contains("model") && curve->dataSize() == 3);
            }
        }
        QVERIFY(modelDrawn);

        w.openDataSet(dir.filePath("bad.csv"));
        QVERIFY(spy.wait(10000));
        QCOMPARE(spy.takeFirst().at(0).toBool(), false);
        // The rejected file changed nothing.
        QCOMPARE(w.dataSet().batches.size(), std::size_t(1));
        QCOMPARE(list->count(), 1);
    }
};

QTEST_MAIN(TestMainWindow)
#include "TestMainWindow.moc"
