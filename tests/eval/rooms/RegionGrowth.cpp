// Regions grown into the unclaimed free cells along their walls (see RegionGrowth.h): the
// wavefront is a geodesic dilation, cv::dilate with the 8-neighbourhood repeated maxGrowCells
// times within the region's own and the unclaimed cells.
#include "tests/eval/rooms/RegionGrowth.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

void growIntoUnclaimed(std::span<RegionRaster> regions, std::span<const std::uint8_t> mapFree, int width, int height,
                       int maxGrowCells) {
  if (width < 0 || height < 0 || maxGrowCells < 0)
    throw InvalidArgumentError("growIntoUnclaimed: negative map size or growth");
  const std::size_t cells = std::size_t(width) * std::size_t(height);
  if (mapFree.size() != cells) throw InvalidArgumentError("growIntoUnclaimed: the free map has the wrong size");
  std::vector<std::uint8_t> unclaimed(mapFree.begin(), mapFree.end());
  for (const RegionRaster& region : regions) {
    if (region.claimed.size() != cells)
      throw InvalidArgumentError("growIntoUnclaimed: region " + std::to_string(region.regionId) +
                                 " has a raster of the wrong size");
    for (std::size_t i = 0; i < cells; ++i)
      if (region.claimed[i] != 0) unclaimed[i] = 0;
  }
  if (cells == 0) return;
  const cv::Mat unclaimedMask = cv::Mat(height, width, CV_8UC1, unclaimed.data()) != 0;
  const cv::Mat neighbours = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
  for (RegionRaster& region : regions) {
    cv::Mat claimed(height, width, CV_8UC1, region.claimed.data());
    const cv::Mat reachable = (claimed != 0) | unclaimedMask;
    cv::Mat grown = claimed != 0;
    for (int step = 0; step < maxGrowCells; ++step) {
      cv::Mat next;
      cv::dilate(grown, next, neighbours);
      next &= reachable;
      if (cv::countNonZero(next != grown) == 0) break;
      grown = next;
    }
    claimed.setTo(1, grown & unclaimedMask);
  }
}

}  // namespace rgnav
