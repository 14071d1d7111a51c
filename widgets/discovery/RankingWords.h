#pragma once

#include <QString>

class QTableWidget;
class QTableWidgetItem;

namespace drytwin::widgets {

/// @brief The ranking table's headers in a process engineer's words ("How strong the evidence
/// is", "Chance it is noise"), each with the statistician's name and meaning in its tooltip
/// (issue #72 item 10). @p againstReference: the evidence is a change since the reference period.
void setRankingHeaders(QTableWidget* ranking, bool againstReference);

/// @brief A candidate's p in the ranking: the number alone on screen; where it comes from the
/// cause's own score test (a timing cause's), the cell's tooltip says so instead of a "*".
void setRankingPValue(QTableWidgetItem* cell, double pHolm, bool fromOwnScreen);

} // namespace drytwin::widgets
