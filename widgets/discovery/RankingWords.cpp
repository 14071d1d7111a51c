#include "discovery/RankingWords.h"

#include <QCoreApplication>
#include <QTableWidget>

namespace drytwin::widgets {

namespace {
QString rankingWords(const char* text) {
    return QCoreApplication::translate("drytwin::widgets::DiscoverPanel", text);
}
} // namespace

void setRankingHeaders(QTableWidget* ranking, bool againstReference) {
    const QString texts[] = {
        rankingWords(QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel", "Cause")),
        rankingWords(QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel", "Outcome")),
        againstReference
            ? rankingWords(QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel", "How far\nit moved"))
            : rankingWords(
                  QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel", "How strong\nthe evidence is")),
        rankingWords(QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel", "Chance it\nis noise")),
        rankingWords(QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel", "Fitted")),
        rankingWords(QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel", "Loss"))};
    const QString tips[] = {
        QString(),
        rankingWords(
            QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel",
                              "Outcome: named, or why not (the whole reason in the cell's tooltip, and under "
                              "the evidence).")),
        // Against a reference the z is the change of the cause's one-step estimate from its normal
        // value; a timing cause's p may come from its own score test instead, which is why a small
        // z can sit beside a small p.
        againstReference ? rankingWords(QT_TRANSLATE_NOOP(
                               "drytwin::widgets::DiscoverPanel",
                               "Change z: how far the cause's one-step estimate here lies from its normal "
                               "value on the reference period, in units of both estimates' errors and the "
                               "spread between the reference's periods; above 2 it moved."))
                         : rankingWords(QT_TRANSLATE_NOOP(
                               "drytwin::widgets::DiscoverPanel",
                               "Score z: how strongly the model's error points at this cause, in standard "
                               "deviations of chance; above about 3 is strong evidence.")),
        rankingWords(QT_TRANSLATE_NOOP(
            "drytwin::widgets::DiscoverPanel",
            "p (Holm): the chance of evidence this strong if the cause were absent, corrected "
            "for testing many causes at once (Holm's method); below 0.05 the cause is taken "
            "seriously.")),
        rankingWords(QT_TRANSLATE_NOOP(
            "drytwin::widgets::DiscoverPanel",
            "Fitted: whether the cause's parameter was fitted to the data (only the leading "
            "causes are).")),
        rankingWords(
            QT_TRANSLATE_NOOP("drytwin::widgets::DiscoverPanel",
                              "Loss: the fit's error with the cause in the model; lower is a better fit."))};
    for (int c = 0; c < ranking->columnCount() && c < 6; ++c) {
        auto* header = ranking->horizontalHeaderItem(c);
        if (!header) {
            header = new QTableWidgetItem;
            ranking->setHorizontalHeaderItem(c, header);
        }
        header->setText(texts[c]);
        header->setToolTip(tips[c]);
    }
}

void setRankingPValue(QTableWidgetItem* cell, double pHolm, bool fromOwnScreen) {
    cell->setText(QString::number(pHolm, 'g', 3));
    if (fromOwnScreen) {
        cell->setToolTip(rankingWords(QT_TRANSLATE_NOOP(
            "drytwin::widgets::DiscoverPanel",
            "From the cause's own score test (a timing cause is screened on its own signature), not the "
            "shared screen: that is why it can be small beside a small first number.")));
    }
}

} // namespace drytwin::widgets
