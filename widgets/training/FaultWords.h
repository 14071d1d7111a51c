#pragma once

#include "plant/Mechanisms.h"
#include "training/TrainingSession.h"

#include <QString>

namespace drytwin::widgets {

// The instructor's words for the faults and the score, apart from TrainingPanel.cpp (issue #72
// item 9): a fault's strength with its unit, whether each fault is found or still within the
// trainee's time to react, and the score line.

/// @brief The unit after a fault's strength: the mechanism's unit (" s", " % wb"), or for a
/// dimensionless strength what the number is a share of (" of h_HDT lost"): "0.400" alone
/// beside Discover's "1/h" read as a number without a unit.
QString faultStrengthUnit(plant::Mechanism mechanism);
/// @brief The strength and its unit ("0.4 of h_HDT lost", "120 s").
QString faultStrengthText(plant::Mechanism mechanism, double strength);
/// @brief What the strength means and how it relates to the parameter Discover fits for the
/// same cause (another form, another unit), for the strength's tooltip.
QString faultStrengthToolTip(plant::Mechanism mechanism);
/// @brief A fault's state for the instructor's table: not acting yet, found after N s, within the
/// time to react (and how long is left), or not found.
QString faultStateText(const training::FaultScore* score, bool actingYet);
/// @brief The score line: points, faults found, those still within their time to react, wrong
/// answers and product out of the band.
QString scoreText(const training::TrainingScore& score);

} // namespace drytwin::widgets
