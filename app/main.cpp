// drytwin: the GUI without a subcommand, a headless subcommand otherwise (CONTRACT.md §2).
#include "CommandLine.h"
#include "MainWindow.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <algorithm>
#include <cstdio>
#include <cstring>

namespace {

int runGui(int argc, char** argv, const QString& dataPath, const QString& screenshotPath) {
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
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("DryTwin"));
    QApplication::setOrganizationName(QStringLiteral("DryTwin"));
    drytwin::widgets::MainWindow window;
    window.show();
    if (!screenshotPath.isEmpty()) {
        auto save = [&window, screenshotPath] {
            const bool ok = window.grab().save(screenshotPath);
            std::fprintf(stderr, ok ? "drytwin: saved %s\n" : "drytwin: could not save %s\n",
                         qPrintable(screenshotPath));
            QApplication::exit(ok ? 0 : 3);
        };
        if (dataPath.isEmpty()) {
            QTimer::singleShot(500, &window, save);
        } else {
            // After the model's predictions are drawn, or at once when the data was rejected.
            QObject::connect(&window, &drytwin::widgets::MainWindow::simulationShown, &window,
                             [save] { QTimer::singleShot(300, save); });
            QObject::connect(&window, &drytwin::widgets::MainWindow::loadFinished, &window, [save](bool ok) {
                if (!ok) {
                    QTimer::singleShot(300, save);
                }
            });
        }
    }
    if (!dataPath.isEmpty()) {
        window.openDataSet(dataPath);
    }
    return QApplication::exec();
}

} // namespace

int main(int argc, char** argv) {
    drytwin::app::CommandLine commandLine;
    const auto parsed = commandLine.parse(argc, argv);
    if (parsed.exitNow) {
        return parsed.exitCode;
    }
    if (parsed.gui) {
        return runGui(argc, argv, QString::fromStdString(parsed.guiDataPath),
                      QString::fromStdString(parsed.screenshotPath));
    }
    return commandLine.run();
}
