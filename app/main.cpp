// drytwin: the GUI without a subcommand, a headless subcommand otherwise (CONTRACT.md §2).
#include "CommandLine.h"
#include "MainWindow.h"
#include "common/AllocatorTuning.h"
#include "common/BlasThreads.h"
#include "common/Translations.h"
#include "report/ReportWriter.h"
#include "workflow/Session.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTimer>
#include <QTranslator>
#include <QVTKOpenGLNativeWidget.h>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace {

/// Qt wants a private runtime folder (XDG_RUNTIME_DIR) and, where a session has none (a console
/// login as root, a container, CI), prints "QStandardPaths: XDG_RUNTIME_DIR not set" into the
/// middle of DryTwin's own output before falling back on /tmp/runtime-<user>. The same folder,
/// made here (owner only, as Qt requires) and named, without the warning.
void provideRuntimeFolder() {
#ifdef Q_OS_UNIX
    if (qEnvironmentVariableIsSet("XDG_RUNTIME_DIR")) {
        return;
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path dir = fs::temp_directory_path(ec) / ("runtime-" + std::to_string(getuid()));
    if (ec) {
        return;
    }
    fs::create_directories(dir, ec);
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace, ec);
    if (!ec) {
        qputenv("XDG_RUNTIME_DIR", QByteArray::fromStdString(dir.string()));
    }
#endif
}

int runGui(int argc, char** argv, const drytwin::app::ParsedCommandLine& parsed) {
    const bool platformGiven =
        qEnvironmentVariableIsSet("QT_QPA_PLATFORM") ||
        std::any_of(argv, argv + argc, [](const char* a) { return std::strcmp(a, "-platform") == 0; });
    if (!platformGiven && !qEnvironmentVariableIsSet("DISPLAY") &&
        !qEnvironmentVariableIsSet("WAYLAND_DISPLAY")) {
        std::fprintf(stderr,
                     "drytwin: no display for the GUI (DISPLAY is not set); run a subcommand headless, "
                     "e.g. drytwin pipeline --data DIR --out DIR, or see drytwin --help\n");
        return 2;
    }
    // Must precede QApplication for the VTK view (PLATFORM-NOTES.md).
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    provideRuntimeFolder();
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("DryTwin"));
    QApplication::setOrganizationName(QStringLiteral("DryTwin"));
    QString language = QString::fromStdString(parsed.language);
    if (language.isEmpty()) {
        language = QSettings().value(QStringLiteral("language")).toString();
    }
    if (language.isEmpty()) {
        language = QLocale::system().name().startsWith(QLatin1String("zh")) ? QStringLiteral("zh_CN")
                                                                            : QStringLiteral("en");
    }
    drytwin::widgets::setLanguage(language);
    QElapsedTimer sinceStart;
    sinceStart.start();
    drytwin::widgets::MainWindow window;
    window.show();
    // How long until the data and the physics model are on screen (scripts/measure-gui.sh).
    QObject::connect(&window, &drytwin::widgets::MainWindow::simulationShown, &window, [&sinceStart] {
        static bool once = false;
        if (!once) {
            once = true;
            std::fprintf(stderr, "drytwin: data loaded, simulated and drawn %.2f s after start\n",
                         sinceStart.elapsed() / 1000.0);
        }
    });
    const QString screenshot = QString::fromStdString(parsed.screenshotPath);
    const QString dataPath = QString::fromStdString(parsed.guiDataPath);
    const QString projectPath = QString::fromStdString(parsed.projectPath);
    const QString saveProjectPath = QString::fromStdString(parsed.saveProjectPath);
    if (!screenshot.isEmpty() || !saveProjectPath.isEmpty()) {
        // What is done once the window is idle: the project saved (its model file is written by a
        // job: idle again first), then the screenshots and quit; with no screenshot, the window
        // stays open after saving.
        auto projectToSave = std::make_shared<QString>(saveProjectPath);
        // A scripted run says what failed (loading the data, a model file, an action) on stderr and
        // ends with exit 3, as the headless commands do, rather than 0 beside a screenshot of it.
        auto failures = std::make_shared<int>(0);
        QObject::connect(&window.workbench(), &drytwin::widgets::Workbench::failed, &window,
                         [failures](const QString&, const QString& message, bool cancelled) {
                             if (!cancelled) {
                                 ++*failures;
                                 std::fprintf(stderr, "drytwin: error: %s\n", qPrintable(message));
                             }
                         });
        QObject::connect(&window, &drytwin::widgets::MainWindow::trainingSessionFailed, &window,
                         [failures](const QString& message) {
                             ++*failures;
                             std::fprintf(stderr, "drytwin: error: %s\n", qPrintable(message));
                         });
        auto finish = [&window, screenshot, projectToSave, failures]() -> bool {
            if (!projectToSave->isEmpty()) {
                QString error;
                if (!window.saveProject(*projectToSave, &error)) {
                    std::fprintf(stderr, "drytwin: error: %s\n", qPrintable(error));
                    QApplication::exit(3);
                    return true;
                }
                std::fprintf(stderr, "drytwin: project saved to %s\n", qPrintable(*projectToSave));
                projectToSave->clear();
                return false; // wait until the model file is written
            }
            if (screenshot.isEmpty()) {
                return true; // the window stays open, its failures shown in it
            }
            int rc = 0;
            if (screenshot.endsWith(QLatin1String(".png"), Qt::CaseInsensitive)) {
                const bool ok = window.grab().save(screenshot);
                std::fprintf(stderr, ok ? "drytwin: saved %s\n" : "drytwin: could not save %s\n",
                             qPrintable(screenshot));
                rc = ok ? 0 : 3;
            } else {
                const QStringList files = window.saveTabScreenshots(screenshot);
                for (const auto& f : files) {
                    std::fprintf(stderr, "drytwin: saved %s\n", qPrintable(f));
                }
                rc = files.size() > window.tabs()->count() ? 0 : 3; // every tab, the training tab twice
            }
            QApplication::exit(*failures > 0 ? 3 : rc);
            return true;
        };
        // Once the work the window started is done (data loaded and simulated), or at once
        // when the data was rejected or there was nothing to load.
        auto whenIdle = [&window, finish] {
            // Idle for a whole second (three polls in a row): every queued action and what its
            // results started have finished drawing.
            auto* poll = new QTimer(&window);
            auto idlePolls = std::make_shared<int>(0);
            QObject::connect(poll, &QTimer::timeout, &window, [&window, finish, poll, idlePolls] {
                const bool idle = !window.jobs().busy() && !window.hasPendingActions();
                *idlePolls = idle ? *idlePolls + 1 : 0;
                if (*idlePolls >= 3) {
                    *idlePolls = 0;
                    if (finish()) {
                        poll->stop();
                    }
                }
            });
            poll->start(350);
        };
        if (dataPath.isEmpty() && projectPath.isEmpty()) {
            QTimer::singleShot(500, &window, whenIdle);
        } else {
            auto started = std::make_shared<bool>(false);
            auto once = [whenIdle, started] {
                if (!*started) {
                    *started = true;
                    whenIdle();
                }
            };
            QObject::connect(&window, &drytwin::widgets::MainWindow::simulationShown, &window, once);
            QObject::connect(&window, &drytwin::widgets::MainWindow::loadFinished, &window, [once](bool ok) {
                if (!ok) {
                    once();
                }
            });
        }
    }
    if (!parsed.referencePath.empty()) {
        window.workbench().setReferencePath(QString::fromStdString(parsed.referencePath));
    }
    if (!projectPath.isEmpty()) {
        QString error;
        if (!window.openProject(projectPath, &error)) {
            std::fprintf(stderr, "drytwin: error: %s\n", qPrintable(error));
            return 3;
        }
    } else {
        // --model alone (a training session's learnt controllers) is opened too; it was ignored
        // without --data.
        if (!parsed.modelPath.empty()) {
            window.workbench().openModel(QString::fromStdString(parsed.modelPath));
        }
        if (!dataPath.isEmpty()) {
            window.openDataSet(dataPath, QString::fromStdString(parsed.mappingPath));
        }
    }
    if (!parsed.trainingSession.empty()) {
        window.openTrainingSession(QString::fromStdString(parsed.trainingSession));
    }
    if (!parsed.runActions.empty()) {
        window.runAfterLoad(
            QString::fromStdString(parsed.runActions).split(QLatin1Char(','), Qt::SkipEmptyParts));
    }
    return QApplication::exec();
}

} // namespace

/// The pipeline's HTML/PDF report, drawn by the GUI's plot code on Qt's offscreen platform when
/// there is no display.
std::vector<std::string> renderReport(char** argv, const drytwin::workflow::PipelineResult& result,
                                      const drytwin::workflow::Session& session, const std::string& folder,
                                      const std::string& command, std::string& error) {
    if (!QCoreApplication::instance()) {
        if (!qEnvironmentVariableIsSet("DISPLAY") && !qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) {
            qputenv("QT_QPA_PLATFORM", "offscreen");
        }
        static int qtArgc = 1;
        static char* qtArgv[] = {argv[0], nullptr};
        provideRuntimeFolder();
        new QApplication(qtArgc, qtArgv); // lives until exit: the report's widgets need it
    }
    drytwin::widgets::ReportContext context;
    context.command = QString::fromStdString(command);
    context.resultsFile = QString::fromStdString(result.resultsFrom);
    if (const auto data = session.dataSet()) {
        for (const auto& b : data->batches) {
            context.dataFiles.push_back(b.sourcePath);
        }
    }
    auto files = drytwin::widgets::writeHtmlPdfReport(result, session.siBatches(), context,
                                                      QString::fromStdString(folder));
    if (!files) {
        error = files.error().message();
        return {};
    }
    std::vector<std::string> out;
    for (const auto& f : *files) {
        out.push_back(f.toStdString());
    }
    return out;
}

int main(int argc, char** argv) {
    drytwin::tuneAllocatorForLargeMatrices();
    drytwin::blasInCallingThread();
    if (const std::string problem = drytwin::blasConcurrencyProblem(); !problem.empty()) {
        std::fprintf(stderr, "drytwin: warning: %s\n", problem.c_str());
    }
    drytwin::app::CommandLine commandLine;
    std::string command;
    for (int i = 0; i < argc; ++i) {
        command += (i ? " " : "") + std::string(argv[i]);
    }
    commandLine.setReportRenderer(
        [argv, command](const drytwin::workflow::PipelineResult& r, const drytwin::workflow::Session& s,
                        const std::string& folder,
                        std::string& error) { return renderReport(argv, r, s, folder, command, error); },
        command);
    const auto parsed = commandLine.parse(argc, argv);
    if (parsed.exitNow) {
        return parsed.exitCode;
    }
    if (parsed.gui) {
        return runGui(argc, argv, parsed);
    }
    return commandLine.run();
}
