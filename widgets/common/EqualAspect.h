#pragma once

class QwtPlot;

namespace drytwin::widgets {

/// @brief Keeps one unit as long across as up on @p plot at any size (a unit circle stays round),
/// showing at least [-radius, radius] on both axes around the origin; call again with a new radius.
void keepEqualAspect(QwtPlot* plot, double radius);

} // namespace drytwin::widgets
