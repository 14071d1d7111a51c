// drytwin: the GUI without a subcommand, a headless subcommand otherwise (CONTRACT.md §2).
#include "CommandLine.h"
#include "MainWindow.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

namespace {

int runGui(int argc, char** argv, const QString& dataPath) {
    // Must precede QApplication for the VTK view (PLATFORM-NOTES.md).
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("DryTwin"));
    QApplication::setOrganizationName(QStringLiteral("DryTwin"));
    drytwin::widgets::MainWindow window;
    window.show();
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
        return runGui(argc, argv, QString::fromStdString(parsed.guiDataPath));
    }
    return commandLine.run();
}
