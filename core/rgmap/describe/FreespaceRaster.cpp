// Region freespace in a global raster; see FreespaceRaster.h.
#include "core/rgmap/describe/FreespaceRaster.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

std::vector<std::uint8_t> rasteriseFreespace(const FreespaceBitmap& map, const Pose2D& regionInGlobal,
                                             const RasterFrame& frame) {
  if (!std::isfinite(regionInGlobal.x) || !std::isfinite(regionInGlobal.y) || !std::isfinite(regionInGlobal.theta) ||
      !frame.originM.allFinite() || !(frame.resolutionM > 0.0) || !std::isfinite(frame.resolutionM) ||
      frame.width < 0 || frame.height < 0)
    throw InvalidArgumentError("rasterise freespace: need a finite pose and origin, positive resolution, size >= 0");
  std::vector<std::uint8_t> raster(std::size_t(frame.width) * std::size_t(frame.height), 0);
  if (map.freeCount() == 0) return raster;

  // Only the raster cells under the map's footprint can be free.
  Eigen::AlignedBox2d footprint;
  const Eigen::Vector2d size = map.resolutionM * Eigen::Vector2d(map.width, map.height);
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, 0), Eigen::Vector2d(size.x(), 0), size,
                                        Eigen::Vector2d(0, size.y())})
    footprint.extend(transformPoint(regionInGlobal, map.originM + corner));
  const Eigen::Vector2d lo = (footprint.min() - frame.originM) / frame.resolutionM;
  const Eigen::Vector2d hi = (footprint.max() - frame.originM) / frame.resolutionM;
  const int col0 = int(std::clamp(std::floor(lo.x()), 0.0, double(frame.width)));
  const int col1 = int(std::clamp(std::ceil(hi.x()), 0.0, double(frame.width)));
  const int row0 = int(std::clamp(std::floor(lo.y()), 0.0, double(frame.height)));
  const int row1 = int(std::clamp(std::ceil(hi.y()), 0.0, double(frame.height)));

  const Pose2D globalInRegion = inverse(regionInGlobal);
  for (int row = row0; row < row1; ++row)
    for (int col = col0; col < col1; ++col) {
      const Eigen::Vector2d center = frame.originM + frame.resolutionM * Eigen::Vector2d(col + 0.5, row + 0.5);
      if (map.isFreeAt(transformPoint(globalInRegion, center)))
        raster[std::size_t(row) * std::size_t(frame.width) + std::size_t(col)] = 1;
    }
  return raster;
}

}  // namespace rgnav
