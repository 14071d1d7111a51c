#include "discovery/ReferenceMenu.h"

#include "common/Workbench.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>

namespace drytwin::widgets {

namespace {

// The words are in the Discover panel's translation context, where they were before the menu
// moved here: their translations stay (lupdate needs the context as a literal).

/// How many batch files a reference folder holds (its commissioning runs), for the menu's words.
int batchFilesIn(const QString& folder) {
    return static_cast<int>(QDir(folder).entryList({QStringLiteral("*.csv")}, QDir::Files).size());
}

} // namespace

QMenu* makeReferenceMenu(Workbench& workbench, QWidget* parent) {
    auto* menu = new QMenu(parent);
    QObject::connect(menu, &QMenu::aboutToShow, menu, [menu, &workbench, parent] {
        menu->clear();
        const QString offered = workbench.suggestedReference();
        if (!offered.isEmpty() && QFileInfo::exists(offered)) {
            const int runs = batchFilesIn(offered);
            auto* commissioning = menu->addAction(
                runs > 0 ? QCoreApplication::translate("drytwin::widgets::DiscoverPanel",
                                                       "The line's commissioning runs (%1 runs, %2)")
                               .arg(runs)
                               .arg(QDir::toNativeSeparators(offered))
                         : QCoreApplication::translate("drytwin::widgets::DiscoverPanel",
                                                       "The line's commissioning runs (%1)")
                               .arg(QDir::toNativeSeparators(offered)),
                menu, [&workbench, offered] { workbench.setReferencePath(offered); });
            commissioning->setToolTip(QCoreApplication::translate(
                "drytwin::widgets::DiscoverPanel", "The runs the training line was commissioned on: what "
                                                   "changed since then is named more surely than from the "
                                                   "recording alone"));
            menu->addSeparator();
        }
        // The dialogs start at the offered reference where there is one, else at the data.
        const QString start = offered.isEmpty() ? workbench.dataPath() : offered;
        menu->addAction(
            QCoreApplication::translate("drytwin::widgets::DiscoverPanel", "A folder of batch files…"), menu,
            [&workbench, parent, start] {
                const QString dir = QFileDialog::getExistingDirectory(
                    parent,
                    QCoreApplication::translate("drytwin::widgets::DiscoverPanel",
                                                "Reference period: a folder of batch files"),
                    start);
                if (!dir.isEmpty()) {
                    workbench.setReferencePath(dir);
                }
            });
        menu->addAction(
            QCoreApplication::translate("drytwin::widgets::DiscoverPanel", "One batch or historian file…"),
            menu, [&workbench, parent, start] {
                const QString file = QFileDialog::getOpenFileName(
                    parent,
                    QCoreApplication::translate("drytwin::widgets::DiscoverPanel",
                                                "Reference period: a batch or historian file"),
                    start,
                    QCoreApplication::translate("drytwin::widgets::DiscoverPanel",
                                                "CSV files (*.csv *.txt)"));
                if (!file.isEmpty()) {
                    workbench.setReferencePath(file);
                }
            });
        menu->addAction(QCoreApplication::translate("drytwin::widgets::DiscoverPanel",
                                                    "No reference: judge the data alone"),
                        menu, [&workbench] { workbench.setReferencePath({}); });
    });
    return menu;
}

} // namespace drytwin::widgets
