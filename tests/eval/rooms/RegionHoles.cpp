// Holes in regions filled (see RegionHoles.h): the 4-connected gaps of each region's bounding box
// by cv::connectedComponentsWithStats; a gap is a hole if its box lies inside the region's box.
#include "tests/eval/rooms/RegionHoles.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

cv::Mat claimedMat(RegionRaster& region, int width, int height) {
  return cv::Mat(height, width, CV_8UC1, region.claimed.data());
}

}  // namespace

void fillEnclosedHoles(std::span<RegionRaster> regions, int width, int height, std::size_t maxHoleCells) {
  if (width < 0 || height < 0) throw InvalidArgumentError("fillEnclosedHoles: negative map size");
  const std::size_t cells = std::size_t(width) * std::size_t(height);
  for (const RegionRaster& region : regions)
    if (region.claimed.size() != cells)
      throw InvalidArgumentError("fillEnclosedHoles: region " + std::to_string(region.regionId) +
                                 " has a raster of the wrong size");
  if (cells == 0) return;
  // Before any filling: a hole holds no pixel of another region as the regions came in.
  cv::Mat anyClaimed(height, width, CV_8UC1, cv::Scalar(0));
  for (RegionRaster& region : regions) anyClaimed |= claimedMat(region, width, height) != 0;
  for (RegionRaster& region : regions) {
    const cv::Mat claimed = claimedMat(region, width, height);
    const cv::Rect box = cv::boundingRect(claimed);
    if (box.empty()) continue;
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(claimed(box) == 0, labels, stats, centroids, 4, CV_32S);
    std::vector<std::uint8_t> hole(std::size_t(n), 0);
    for (int label = 1; label < n; ++label) {
      const int left = stats.at<int>(label, cv::CC_STAT_LEFT), top = stats.at<int>(label, cv::CC_STAT_TOP);
      hole[std::size_t(label)] = left > 0 && top > 0 && left + stats.at<int>(label, cv::CC_STAT_WIDTH) < box.width &&
                                 top + stats.at<int>(label, cv::CC_STAT_HEIGHT) < box.height &&
                                 std::size_t(stats.at<int>(label, cv::CC_STAT_AREA)) <= maxHoleCells;
    }
    const cv::Mat others = anyClaimed(box);
    for (int row = 0; row < box.height; ++row)
      for (int col = 0; col < box.width; ++col)
        if (others.at<std::uint8_t>(row, col) != 0) hole[std::size_t(labels.at<int>(row, col))] = 0;
    cv::Mat inBox = claimed(box);
    for (int row = 0; row < box.height; ++row)
      for (int col = 0; col < box.width; ++col)
        if (hole[std::size_t(labels.at<int>(row, col))] != 0) inBox.at<std::uint8_t>(row, col) = 1;
  }
}

}  // namespace rgnav
