#pragma once

/// Conversions between the units of batch files (°C, % wet basis, kg/h, % RH) and the engine's
/// SI / dry-basis form (CONTRACT.md §1). The one place these factors live.

namespace drytwin::units {

/// @brief 0 °C in kelvin.
inline constexpr double kKelvinOffset = 273.15;
/// @brief Seconds per hour.
inline constexpr double kSecondsPerHour = 3600.0;

/// @brief °C to K.
constexpr double celsiusToKelvin(double c) {
    return c + kKelvinOffset;
}
/// @brief K to °C.
constexpr double kelvinToCelsius(double k) {
    return k - kKelvinOffset;
}

/// @brief Wet-basis percent to dry-basis fraction: X_db = X_wb / (1 − X_wb) (paper §IV.A).
constexpr double wetPctToDry(double wetPct) {
    const double x = wetPct / 100.0;
    return x / (1.0 - x);
}
/// @brief Dry-basis fraction to wet-basis percent.
constexpr double dryToWetPct(double dry) {
    return 100.0 * dry / (1.0 + dry);
}

/// @brief kg/h to kg/s.
constexpr double kgPerHourToKgPerS(double kgPerHour) {
    return kgPerHour / kSecondsPerHour;
}
/// @brief kg/s to kg/h.
constexpr double kgPerSToKgPerHour(double kgPerS) {
    return kgPerS * kSecondsPerHour;
}

/// @brief Relative humidity in % to a fraction 0..1.
constexpr double percentToFraction(double pct) {
    return pct / 100.0;
}
/// @brief A fraction 0..1 to %.
constexpr double fractionToPercent(double f) {
    return 100.0 * f;
}

} // namespace drytwin::units
