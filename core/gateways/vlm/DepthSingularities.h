// DepthSingularities: thesis 4.1.1.1, the discontinuities of a point scan,
//     P_ds = { P_i : (d_i < d_{i±1}) and |d_i - d_{i±1}| > Δd_min },
// i.e. the near end of every depth jump larger than Δd_min between neighbouring beams. A beam
// without return (+inf, REP 117) counts as a jump to infinity; invalid beams (NaN) have no
// point and are no neighbour either.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/SensorData.h"

namespace rgnav {

// The points P_ds in the sensor frame, in beam order. Throws InvalidArgumentError for a
// non-positive minJumpM (Δd_min).
std::vector<Eigen::Vector2d> depthSingularities(const LaserScan& scan, double minJumpM);

}  // namespace rgnav
