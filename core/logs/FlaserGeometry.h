// FlaserGeometry: beam angles of scans whose log gives no field of view (CARMEN FLASER and the
// Intel JSON keyframes): 180° starting at -90°, the increment following from the beam count.
#pragma once

#include <cmath>
#include <cstddef>

namespace rgnav {

inline constexpr double kFlaserStartAngle = -M_PI / 2.0;

// 180 -> 1°, 181 -> 1° (both ends included), 360 -> 0.5°, 361 -> 0.5° (both ends included),
// otherwise pi/(n-1); 0 for fewer than two beams.
double flaserAngleIncrement(std::size_t beams);

}  // namespace rgnav
