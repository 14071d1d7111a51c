// What Help shows: the user guide (shipped as a resource, in the window's language, English where
// there is none) and the About box with DryTwin's version and every library's.

#include "MainWindow.h"

#include "common/LibraryVersions.h"
#include "common/Translations.h"
#include "mainwindow/MainWindowInternal.h"

#include <QFile>
#include <QTextBrowser>
#include <qwt_global.h>
#include <vtkVersion.h>

namespace drytwin::widgets {

QString MainWindow::userGuideHtml(const QString& language) {
    initDryTwinResources();
    QFile f(QStringLiteral(":/guide/user-guide.%1.html").arg(language));
    if (!f.open(QIODevice::ReadOnly)) {
        f.setFileName(QStringLiteral(":/guide/user-guide.en.html"));
        if (!f.open(QIODevice::ReadOnly)) {
            return {};
        }
    }
    return QString::fromUtf8(f.readAll());
}

void MainWindow::showUserGuide() {
    if (!m_guide) {
        m_guide = new QTextBrowser(this);
        m_guide->setWindowFlag(Qt::Window);
        m_guide->setWindowTitle(tr("DryTwin user guide"));
        m_guide->resize(720, 760);
        m_guide->setOpenExternalLinks(true);
    }
    m_guide->setHtml(userGuideHtml(currentLanguage()));
    m_guide->show();
    m_guide->raise();
}

QString MainWindow::aboutText() {
    QString html = tr("<h3>DryTwin %1</h3><p>Digital-twin workbench for pneumatic drying lines, "
                      "implementing the PGRL-CC method.</p><table>")
                       .arg(QString::fromStdString(dryTwinVersion()));
    auto row = [&](const QString& name, const QString& version) {
        html += QStringLiteral("<tr><td>%1</td><td>&nbsp;%2</td></tr>")
                    .arg(name.toHtmlEscaped(), version.toHtmlEscaped());
    };
    row(QStringLiteral("Qt"), QString::fromLatin1(qVersion()));
    row(QStringLiteral("Qwt"), QStringLiteral(QWT_VERSION_STR));
    row(QStringLiteral("VTK"), QString::fromLatin1(vtkVersion::GetVTKVersion()));
    for (const auto& [name, version] : engineLibraryVersions()) {
        row(QString::fromStdString(name), QString::fromStdString(version));
    }
    html += QStringLiteral("</table>");
    return html;
}

} // namespace drytwin::widgets
