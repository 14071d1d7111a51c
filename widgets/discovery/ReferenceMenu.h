#pragma once

class QMenu;
class QWidget;

namespace drytwin::widgets {

class Workbench;

/// @brief The menu of Discover's "Compare with a reference period…" button: a folder of batch
/// files, one batch or historian file, or none; and first, when the loaded data set has one, the
/// reference offered for it (a training recording's commissioning runs, issue #72 item 5). Built
/// afresh each time it opens, so that it follows the loaded data set.
QMenu* makeReferenceMenu(Workbench& workbench, QWidget* parent);

} // namespace drytwin::widgets
