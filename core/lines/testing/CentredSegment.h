// Test helper: a line segment given by its centre, orientation and length.
#pragma once

#include "core/lines/LineSegment.h"

namespace rgnav::testing {

// A segment of `length` centred at `center`, at `angle` (radians) to the x-axis.
LineSegment centredSegment(SegmentId id, const Eigen::Vector2d& center, double angle, double length);

}  // namespace rgnav::testing
