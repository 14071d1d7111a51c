#pragma once
// Sentences of the Discover tab that the tab's tables and its evidence share, in the window's
// language (DiscoverPanelTexts.cpp).
#include "discovery/Discovery.h"
#include "properties/Parameters.h"

#include <QString>
#include <string>

namespace drytwin::widgets::finding_words {

/// A parameter's unit after its value (" 1/h"), nothing for a dimensionless one ("-").
QString paramUnitSuffix(properties::Param p);
/// What to look for on the plots, per cause.
QString lookForText(properties::Param p);
/// How to tell the members of a look-alike group apart on the line.
QString tellApartText(const std::string& group);
/// Why a candidate was set aside: a few words for the table, a sentence for the evidence.
QString rejectionShortText(const std::string& code);
QString rejectionText(const std::string& code);
/// An unexplained signature of the error, worded.
QString signatureText(const discovery::Signature& u);
/// Why discovery took another round.
QString roundReasonText(const discovery::Round& rd);

} // namespace drytwin::widgets::finding_words
