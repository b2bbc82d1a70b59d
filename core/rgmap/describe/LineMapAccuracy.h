// lineMapAccuracy: how well a region's 2D line segment map fits the measurements taken in the
// region (thesis 2.1.1, table 2.1 "characteristic measures: accuracy"; the thesis names the
// measure but does not define it). Definition: for each measurement point p (a MeasurementSample
// of the region), d(p) is the Euclidean distance from p to the nearest map segment (to the
// segment, not its infinite line), clamped to maxDistanceM so that clutter the line map does not
// model (chairs, people) weighs at most that much;
//   inlierShare   = share of points with d(p) <= toleranceM,
//   meanDistanceM = mean of the clamped d(p),
//   rmsDistanceM  = root mean square of the clamped d(p).
// A perfect map gives inlierShare 1 and distances near the sensor noise. Without map lines every
// d(p) is maxDistanceM; without points all values are 0 and pointCount is 0 (undefined).
// Cost: points x lines distance evaluations (2048 x 40 in well under a millisecond).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>

#include "core/lines/LineSegment.h"

namespace rgnav {

struct AccuracyParams {
  double toleranceM = 0.05;   // inlier distance: a few times the laser noise and D_L^max (2 cm)
  double maxDistanceM = 0.5;  // clamp for points the map does not explain
};

template <class V>
void describe(V& v, AccuracyParams& c) {
  v.field("tolerance_m", c.toleranceM);
  v.field("max_distance_m", c.maxDistanceM);
}

struct LineMapAccuracy {
  std::size_t pointCount = 0;
  double inlierShare = 0.0;
  double meanDistanceM = 0.0;
  double rmsDistanceM = 0.0;
};

// Throws InvalidArgumentError unless 0 < toleranceM <= maxDistanceM (both finite).
LineMapAccuracy lineMapAccuracy(std::span<const Eigen::Vector2d> points, std::span<const LineSegment> lines,
                                const AccuracyParams& params = {});

}  // namespace rgnav
