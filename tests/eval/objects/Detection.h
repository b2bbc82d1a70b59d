// Detection: one 2D object hypothesis of the evaluation, whatever found it, with the footprint
// it claims in the map grid (what is matched against the ground truth).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "core/objects/ConvexPolygon.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

enum class DetectionKind { kRectangle, kCircle, kCluster };
constexpr std::size_t kDetectionKinds = 3;
std::string kindName(DetectionKind kind);

struct Detection {
  DetectionKind kind = DetectionKind::kCluster;
  Polygon outline;                 // convex, counter-clockwise, world metres
  std::vector<std::size_t> cells;  // the footprint: row-major grid cell indices, ascending
  double score = 0.0;              // higher is better (confidence or support)
};

// The cells of `grid` whose centres lie inside `outline`, and those holding one of `anchors`
// (so that even a 5 cm table leg claims the cell it was seen in): row-major, ascending, unique.
std::vector<std::size_t> rasterize(const Polygon& outline, const std::vector<Eigen::Vector2d>& anchors,
                                   const OccupancyGrid& grid);

}  // namespace rgnav
