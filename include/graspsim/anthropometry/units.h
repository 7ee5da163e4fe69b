#pragma once
/// @file
/// The one place where the units of the source tables become SI units.
///
/// The anthropometry CSV files keep the units of their publications (percent, millimetres,
/// degrees); everything inside graspsim is SI (m, kg, rad) and fractions in [0, 1].
/// Every conversion goes through these functions so that no other file multiplies by 0.01,
/// 0.001 or pi/180.

namespace graspsim::anthropometry {

/// A percentage (%) as a fraction (1 = 100 %).
constexpr double fromPercent(double percent) { return percent / 100.0; }

/// A length in millimetres (mm) in metres (m).
constexpr double fromMillimetres(double millimetres) { return millimetres / 1000.0; }

/// An angle in degrees (deg) in radians (rad).
constexpr double fromDegrees(double degrees) {
    return degrees * (3.14159265358979323846 / 180.0);
}

}  // namespace graspsim::anthropometry
