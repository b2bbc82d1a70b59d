// rasteriseFreespace: a region's 1-bit freespace map placed into a global frame as a raster, for
// scoring regions against ground-truth room images (e.g. the simulator's room segmentation) and for
// showing an RG Map in one picture (thesis 2.3.2: global metric maps "can be extracted easily on
// demand"). The raster follows OccupancyGrid's convention: cell (col, row) covers
// [originM.x + col * res, originM.x + (col + 1) * res) x [originM.y + row * res, ...) in the global
// frame, row 0 at the bottom; values are row-major from row 0. A raster cell is 1 if its centre
// lies in a free cell of the region map (nearest-cell sampling), else 0.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/rgmap/describe/FreespaceBitmap.h"

namespace rgnav {

struct RasterFrame {
  double resolutionM = 0.05;
  Eigen::Vector2d originM = Eigen::Vector2d::Zero();
  int width = 0;
  int height = 0;
};

// width * height values. Throws InvalidArgumentError for a non-finite pose or origin, a
// non-positive resolution or a negative size.
std::vector<std::uint8_t> rasteriseFreespace(const FreespaceBitmap& map, const Pose2D& regionInGlobal,
                                             const RasterFrame& frame);

}  // namespace rgnav
