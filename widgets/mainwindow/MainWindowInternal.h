#pragma once

// What the files of the main window (widgets/MainWindow.cpp and widgets/mainwindow/) share and
// nobody else needs: the widgets library's resources, and the tabs' keys in project files and
// screenshot names.

#include <QtGlobal>

// The widgets are a static library: its resources (window icon) must be registered by hand,
// and Q_INIT_RESOURCE must be called outside any namespace.
inline void initDryTwinResources() {
    Q_INIT_RESOURCE(drytwin);
}

namespace drytwin::widgets {

/// The tabs in their order, as a project file and a screenshot's name call them.
inline const char* kTabKeys[] = {"data",     "model", "calibrate", "residual", "diagnostics",
                                 "discover", "mpc",   "line3d",    "training"};

} // namespace drytwin::widgets
