// Number formatting of the RG Map exports (RgMapJson.h, RgMapSvg.h, MapServerWriter.h): values are
// rounded to a fixed step before they are written, so that files stay small and the same map
// always gives the same bytes (no digits of floating-point noise that a harmless change of the
// computation order would flip).
#pragma once

#include <string>

namespace rgnav {

// Decimals the exports keep.
inline constexpr int kLengthDecimals = 3;  // positions and lengths in m: 1 mm (areas in m^2, variances in m^2 too)
inline constexpr int kAngleDecimals = 4;   // angles in rad: 0.1 mrad, 1 mm at 10 m
inline constexpr int kRatioDecimals = 4;   // probabilities, shares, completeness

// `value` rounded to `decimals` decimals (0..15; halves away from zero) as the double nearest to
// that decimal, so that a shortest-form writer prints exactly those digits; -0 becomes +0 and a
// non-finite value stays as it is.
double roundDecimals(double value, int decimals);

// `value` with at most `decimals` decimals and no trailing zeros: 1.5, -0.25, 3 ("-0" is "0").
// A non-finite value throws InvalidArgumentError.
std::string decimalText(double value, int decimals);

}  // namespace rgnav
