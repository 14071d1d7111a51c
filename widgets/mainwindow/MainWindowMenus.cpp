// What the menus offer and what each entry does: File (open data, the demo, generate plant data,
// models, projects and the recent ones), View ▸ Language, and Help. The entries only ask for a
// path and hand it on; the work is in the project, data and help files beside this one.

#include "MainWindow.h"

#include "common/Translations.h"
#include "common/WidgetHelpers.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QWhatsThis>
#include <utility>

namespace drytwin::widgets {

namespace {
constexpr int kMaxRecent = 8;
} // namespace

void MainWindow::createMenus() {
    auto* file = menuBar()->addMenu(tr("&File"));
    auto* openFile = file->addAction(tr("&Open batch file…"), this, [this] {
        const QString p = askOpenFile(this, tr("Open batch file"), tr("Batch files (*.csv)"));
        if (!p.isEmpty()) {
            openDataSet(p);
        }
    });
    openFile->setShortcut(QKeySequence::Open);
    file->addAction(tr("Open data set &folder…"), this, [this] {
        const QString p = askFolder(this, tr("Open data set folder"));
        if (!p.isEmpty()) {
            openDataSet(p);
        }
    });
    file->addAction(tr("Open the bundled &demo"), this, &MainWindow::openBundledDemo);
    file->addAction(tr("&Generate virtual-plant data…"), this, [this] {
        const QString folder = askFolder(this, tr("Folder for the virtual plant's batches"));
        if (folder.isEmpty()) {
            return;
        }
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(2025); // the bundled demo: distributed plant, realistic sensors
        g.outFolder = folder.toStdString();
        m_workbench.generate(g);
    });
    file->addAction(tr("Open &model…"), this, [this] {
        const QString p = askOpenFile(this, tr("Open model"), tr("Model files (*.json)"));
        if (!p.isEmpty()) {
            m_workbench.openModel(p);
        }
    });
    file->addAction(tr("Save model &as…"), this, [this] {
        const QString p =
            askSaveFile(this, tr("Save model"), QStringLiteral("model.json"), tr("Model files (*.json)"));
        if (!p.isEmpty()) {
            m_workbench.saveModel(p);
        }
    });
    file->addSeparator();
    file->addAction(tr("Open &project…"), this, [this] {
        const QString p = askOpenFile(this, tr("Open project"), tr("DryTwin projects (*.drytwin)"));
        QString error;
        if (!p.isEmpty() && !openProject(p, &error)) {
            showError(tr("Open project"), error);
        }
    });
    auto* save = file->addAction(tr("&Save project"), this, [this] {
        QString p = m_projectPath;
        if (p.isEmpty()) {
            p = askSaveFile(this, tr("Save project"), QStringLiteral("project.drytwin"),
                            tr("DryTwin projects (*.drytwin)"));
        }
        QString error;
        if (!p.isEmpty() && !saveProject(p, &error)) {
            showError(tr("Save project"), error);
        }
    });
    save->setShortcut(QKeySequence::Save);
    file->addAction(tr("Save project as…"), this, [this] {
        const QString p = askSaveFile(this, tr("Save project"), QStringLiteral("project.drytwin"),
                                      tr("DryTwin projects (*.drytwin)"));
        QString error;
        if (!p.isEmpty() && !saveProject(p, &error)) {
            showError(tr("Save project"), error);
        }
    });
    file->addSeparator();
    file->addAction(tr("Export &report…"), this, &MainWindow::askAndExportReport);
    m_recent = file->addMenu(tr("Recent projects"));
    fillRecent();
    file->addSeparator();
    auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    auto* view = menuBar()->addMenu(tr("&View"));
    auto* language = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(this);
    const QString current = currentLanguage();
    for (const auto& [code, name] :
         {std::pair<QString, QString>{QStringLiteral("en"), QStringLiteral("English")},
          std::pair<QString, QString>{QStringLiteral("zh_CN"), QStringLiteral("简体中文")}}) {
        auto* a = language->addAction(name);
        a->setCheckable(true);
        a->setChecked(current == code || (current.isEmpty() && code == QLatin1String("en")));
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code = code] {
            if (code == currentLanguage()) {
                return;
            }
            QString error;
            if (auto* w = reopenInLanguage(code, &error)) {
                w->show();
            } else {
                showError(tr("Language"), error);
            }
        });
    }
    auto* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&User guide"), this, &MainWindow::showUserGuide)
        ->setShortcut(QKeySequence::HelpContents);
    help->addAction(QWhatsThis::createAction(this));
    help->addAction(tr("&About DryTwin"), this,
                    [this] { QMessageBox::about(this, tr("About DryTwin"), aboutText()); });
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::rememberRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("recentProjects")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) {
        recent.removeLast();
    }
    settings.setValue(QStringLiteral("recentProjects"), recent);
    fillRecent();
}

void MainWindow::fillRecent() {
    m_recent->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentProjects")).toStringList();
    for (const auto& p : recent) {
        m_recent->addAction(p, this, [this, p] {
            QString error;
            if (!openProject(p, &error)) {
                showError(tr("Open project"), error);
            }
        });
    }
    m_recent->setEnabled(!recent.isEmpty());
}

} // namespace drytwin::widgets
