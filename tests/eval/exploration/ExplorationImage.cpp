// The picture of one exploration; see ExplorationImage.h.
#include "tests/eval/exploration/ExplorationImage.h"

#include <opencv2/imgproc.hpp>

#include "core/raster/ImageFile.h"
#include "core/rgmap/export/MapColours.h"
#include "tests/eval/rooms/RegionPixels.h"

namespace rgnav {
namespace {

const cv::Vec3b kBlocked(90, 90, 90);  // BGR
const cv::Vec3b kSeen(200, 240, 200);
const cv::Vec3b kUnseen(150, 150, 255);
const cv::Vec3b kOutOfReach(225, 225, 225);
const cv::Scalar kSeparator(0, 0, 0);
const cv::Scalar kPath(200, 60, 0);

cv::Vec3b bgr(const Rgb& c) { return {c.b, c.g, c.r}; }

}  // namespace

void writeExplorationImage(const std::string& path, const OccupancyGrid& world, const GroundTruth& truth,
                           const TruthCoverage& coverage, std::span<const Eigen::Vector2d> truePath,
                           const FinalMap& map, const Pose2D& mapToWorld) {
  const int width = world.width(), height = world.height();
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto at = [&](std::size_t cell) -> cv::Vec3b& {
    return image.at<cv::Vec3b>(height - 1 - int(cell / std::size_t(width)), int(cell % std::size_t(width)));
  };
  for (std::size_t cell = 0; cell < world.cells().size(); ++cell) {
    if (world.cells()[cell] != Cell::Free)
      at(cell) = kBlocked;
    else if (!coverage.reachable(cell))
      at(cell) = kOutOfReach;
    else
      at(cell) = coverage.seen(cell) ? kSeen : kUnseen;
  }
  const auto pixel = [&](double x, double y) {
    return cv::Point(int((x - world.origin().x) / world.resolution()),
                     height - 1 - int((y - world.origin().y) / world.resolution()));
  };
  for (const DoorLine& door : truth.doors) cv::line(image, pixel(door.a.x, door.a.y), pixel(door.b.x, door.b.y), kSeparator);
  for (const SegmentPixels& region : regionPixels(map, mapToWorld, world, 0.0, 0.0)) {
    cv::Mat mask(height, width, CV_8U, cv::Scalar(0));
    for (const std::size_t cell : region.pixels)
      mask.at<std::uint8_t>(height - 1 - int(cell / std::size_t(width)), int(cell % std::size_t(width))) = 255;
    std::vector<std::vector<cv::Point>> outlines;
    cv::findContours(mask, outlines, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    const cv::Vec3b colour = bgr(regionColour(RegionId(region.id)));
    const cv::Scalar darker(colour[0] * 0.6, colour[1] * 0.6, colour[2] * 0.6);
    cv::drawContours(image, outlines, -1, darker, 1);
    const cv::Moments m = cv::moments(mask, true);
    if (m.m00 > 0)
      cv::putText(image, std::to_string(region.id), cv::Point(int(m.m10 / m.m00), int(m.m01 / m.m00)),
                  cv::FONT_HERSHEY_SIMPLEX, 0.5, darker, 1);
  }
  std::vector<cv::Point> line;
  for (const Eigen::Vector2d& p : truePath) line.push_back(pixel(p.x(), p.y()));
  if (!line.empty()) {
    cv::polylines(image, line, false, kPath, 1);
    cv::circle(image, line.front(), 5, kSeparator, 2);
  }
  writeImage(path, image);
}

}  // namespace rgnav
