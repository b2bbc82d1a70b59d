// CrowdPicture: drawing a crowd evaluation run (see the header).
#include "tests/eval/crowd/CrowdPicture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/raster/ImageGrid.h"
#include "core/raster/ImageFile.h"

namespace rgnav {

namespace {

constexpr double kPixelsPerMetre = 40.0;  // wished for; a whole number of pixels per cell gives it nearly
constexpr int kGoalRadiusPx = 7;
constexpr int kRingRadiusPx = 12;
constexpr int kCrossSizePx = 18;
constexpr int kStartRadiusPx = 9;

// Free, occupied and unknown cells in gray.
constexpr std::array<std::uint8_t, 3> kCellGray = {255, 70, 200};

// BGR; none of them red, so the failure marks stand out.
constexpr std::array<std::array<double, 3>, 7> kPalette = {{
    {200, 100, 0},   // blue
    {0, 150, 0},     // green
    {0, 140, 255},   // orange
    {160, 40, 160},  // purple
    {160, 160, 0},   // teal
    {40, 90, 140},   // brown
    {255, 0, 140},   // violet
}};

int pixelsPerCell(const OccupancyGrid& grid) {
  return std::max(1, static_cast<int>(std::lround(kPixelsPerMetre * grid.resolution())));
}

// The grid in gray, image row 0 at the top (grid row 0 is at the bottom), each cell a square.
cv::Mat gridImage(const OccupancyGrid& grid) {
  const cv::Mat cells = imageFromGrid(grid, [](Cell c) { return kCellGray[static_cast<std::size_t>(c)]; });
  const int k = pixelsPerCell(grid);
  cv::Mat gray, bgr;
  cv::resize(cells, gray, cv::Size(), k, k, cv::INTER_NEAREST);
  cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

std::vector<cv::Point> pixels(const OccupancyGrid& grid, const std::vector<Eigen::Vector2d>& points) {
  std::vector<cv::Point> out;
  out.reserve(points.size());
  for (const Eigen::Vector2d& p : points) out.push_back(crowdPicturePixel(grid, p));
  return out;
}

void drawStart(cv::Mat& image, const OccupancyGrid& grid, const Pose2D& start) {
  const cv::Point centre = crowdPicturePixel(grid, {start.x, start.y});
  const Eigen::Vector2d ahead(start.x + std::cos(start.theta) * 2.0 * kStartRadiusPx / kPixelsPerMetre,
                              start.y + std::sin(start.theta) * 2.0 * kStartRadiusPx / kPixelsPerMetre);
  const cv::Scalar black(0, 0, 0);
  cv::circle(image, centre, kStartRadiusPx, black, 2, cv::LINE_AA);
  cv::line(image, centre, crowdPicturePixel(grid, ahead), black, 2, cv::LINE_AA);
  cv::putText(image, "start", centre + cv::Point(-18, kStartRadiusPx + 16), cv::FONT_HERSHEY_SIMPLEX, 0.5, black, 1,
              cv::LINE_AA);
}

void drawGoal(cv::Mat& image, const OccupancyGrid& grid, const GoalOutcome& goal, std::size_t index) {
  const cv::Scalar colour = crowdGoalColour(index);
  const cv::Point at = crowdPicturePixel(grid, goal.goal);
  cv::circle(image, at, kGoalRadiusPx, colour, cv::FILLED, cv::LINE_AA);
  cv::circle(image, at, kGoalRadiusPx, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  cv::putText(image, std::to_string(index + 1), at + cv::Point(kRingRadiusPx + 2, -4), cv::FONT_HERSHEY_SIMPLEX, 0.6,
              colour, 2, cv::LINE_AA);
  if (goal.reached) return;
  cv::circle(image, at, kRingRadiusPx, crowdFailureColour(), 2, cv::LINE_AA);
  if (!goal.path.empty())
    cv::drawMarker(image, crowdPicturePixel(grid, goal.path.back()), crowdFailureColour(), cv::MARKER_TILTED_CROSS,
                   kCrossSizePx, 3, cv::LINE_8);
}

}  // namespace

cv::Scalar crowdGoalColour(std::size_t index) {
  const auto& c = kPalette[index % kPalette.size()];
  return {c[0], c[1], c[2]};
}

cv::Scalar crowdFailureColour() { return {0, 0, 230}; }

cv::Point crowdPicturePixel(const OccupancyGrid& grid, const Eigen::Vector2d& p) {
  const double k = pixelsPerCell(grid) / grid.resolution();
  return {static_cast<int>(std::floor((p.x() - grid.origin().x) * k)),
          static_cast<int>(std::floor((grid.height() * grid.resolution() - (p.y() - grid.origin().y)) * k))};
}

void writeCrowdPicture(const std::string& path, const OccupancyGrid& grid, const Pose2D& start,
                       const CrowdOutcome& outcome) {
  cv::Mat image = gridImage(grid);
  for (std::size_t i = 0; i < outcome.goals.size(); ++i)
    if (!outcome.goals[i].path.empty())
      cv::polylines(image, pixels(grid, outcome.goals[i].path), false, crowdGoalColour(i), 2, cv::LINE_8);
  drawStart(image, grid, start);
  for (std::size_t i = 0; i < outcome.goals.size(); ++i) drawGoal(image, grid, outcome.goals[i], i);
  writeImage(path, image);
}

}  // namespace rgnav
