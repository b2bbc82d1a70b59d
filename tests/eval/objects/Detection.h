// Detection: one 2D object hypothesis of the evaluation, whatever found it, with the footprint
// it claims in the map grid: the cells whose centres lie inside its outline, plus the cells of
// its anchor points (so a detection of a 5 cm table leg claims at least the cell it was seen in).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "core/objects/ConvexPolygon.h"
#include "core/sim/OccupancyGrid.h"

namespace rgnav {

enum class DetectionKind { kRectangle, kCircle, kCluster };
constexpr std::size_t kDetectionKinds = 3;
std::string kindName(DetectionKind kind);

struct Detection {
  DetectionKind kind = DetectionKind::kCluster;
  Polygon outline;                        // convex, counter-clockwise, world metres
  std::vector<Eigen::Vector2d> anchors;   // world metres
  double score = 0.0;                     // higher is better (confidence or support)
};

// Row-major cell indices of `grid` the detection claims, ascending, without duplicates.
std::vector<std::size_t> footprint(const Detection& detection, const OccupancyGrid& grid);

// True if `p` lies inside the convex counter-clockwise `polygon` grown by `marginM`.
bool insideConvex(const Polygon& polygon, const Eigen::Vector2d& p, double marginM);

}  // namespace rgnav
