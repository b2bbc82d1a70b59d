// RoutePictures: drawing the routes evaluation's pictures (see the header).
#include "tests/eval/routes/RoutePictures.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "core/lines/ScanPoints.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/FramedQuadtreePlanner.h"
#include "core/nav/planning/RegionGrid.h"
#include "core/raster/ImageFile.h"
#include "core/rgmap/export/MapExtent.h"
#include "core/rgmap/export/RgMapPng.h"

namespace rgnav {

namespace {

constexpr double kMapResolutionM = 0.05;
constexpr int kPixelsPerCell = 4;

void drawPolyline(cv::Mat& image, const std::vector<cv::Point>& points, const cv::Scalar& colour, int thickness) {
  for (std::size_t i = 1; i < points.size(); ++i) cv::line(image, points[i - 1], points[i], colour, thickness, cv::LINE_AA);
}

}  // namespace

void writeRoutesPicture(const std::string& path, const RgMapSnapshot& map, const std::vector<ComparedPaths>& pairs) {
  cv::Mat image = renderRgMap(map, kMapResolutionM);
  const Eigen::AlignedBox2d extent = pictureExtent(map);
  const auto pixel = [&](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>((p.x() - extent.min().x()) / kMapResolutionM),
                     static_cast<int>((extent.max().y() - p.y()) / kMapResolutionM));
  };
  for (const ComparedPaths& pair : pairs) {
    std::vector<cv::Point> rg, floor;
    for (const auto& p : pair.rg) rg.push_back(pixel(p));
    for (const auto& p : pair.floor) floor.push_back(pixel(p));
    drawPolyline(image, floor, cv::Scalar(255, 80, 0), 2);
    drawPolyline(image, rg, cv::Scalar(0, 0, 230), 2);
    if (!rg.empty()) {
      cv::circle(image, rg.front(), 5, cv::Scalar(0, 160, 0), cv::FILLED);
      cv::circle(image, rg.back(), 5, cv::Scalar(0, 160, 0), cv::FILLED);
    }
  }
  writeImage(path, image);
}

void writeQuadtreePicture(const std::string& path, const RegionView& region, const RoutePlannerConfig& config,
                          const Eigen::Vector2d& from) {
  const RegionGrid grid = buildRegionGrid(region, config.gridResolutionM, config.robotRadiusM);
  const FramedQuadtreePlanner planner(grid.grid, config.region);
  const Eigen::Vector2d start = grid.toCells(transformPoint(inverse(region.summary.frame), from));
  std::vector<std::pair<double, Eigen::Vector2d>> candidates;
  for (int r = 0; r < grid.grid.height(); ++r)
    for (int c = 0; c < grid.grid.width(); ++c)
      if (!grid.grid.blocked({c, r})) {
        const Eigen::Vector2d centre(c + 0.5, r + 0.5);
        candidates.emplace_back(-(centre - start).norm(), centre);
      }
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::optional<CellUnitPath> found;
  for (std::size_t i = 0; i < candidates.size() && !found; i += std::max<std::size_t>(1, candidates.size() / 50)) try {
      found = planner.plan(start, candidates[i].second);
    } catch (const NoPathError&) {
    }
  if (!found) throw NoPathError("quadtree picture: no free cell of region " + std::to_string(region.summary.id.value()) +
                                " is reachable from the start");
  const CellUnitPath& cells = *found;
  const int w = grid.grid.width(), h = grid.grid.height();
  cv::Mat image(h * kPixelsPerCell, w * kPixelsPerCell, CV_8UC3, cv::Scalar(60, 60, 60));
  const auto pixel = [&](double col, double row) {
    return cv::Point(static_cast<int>(col * kPixelsPerCell), static_cast<int>((h - row) * kPixelsPerCell));
  };
  const FramedQuadtree& tree = planner.tree();
  for (const FramedQuadtree::Quad& q : tree.quads()) {
    cv::rectangle(image, pixel(q.col, q.row + q.size), pixel(q.col + q.size, q.row), cv::Scalar(250, 250, 250), cv::FILLED);
    for (std::int32_t n = q.firstNode; n < q.firstNode + q.nodeCount; ++n) {
      const CellIndex c = tree.nodeCell(n);
      cv::rectangle(image, pixel(c.col, c.row + 1), pixel(c.col + 1, c.row), cv::Scalar(225, 215, 200), cv::FILLED);
    }
    cv::rectangle(image, pixel(q.col, q.row + q.size), pixel(q.col + q.size, q.row), cv::Scalar(170, 140, 110), 1);
  }
  std::vector<cv::Point> line;
  for (const Eigen::Vector2d& c : cells.points) line.push_back(pixel(c.x(), c.y()));
  drawPolyline(image, line, cv::Scalar(0, 0, 230), 2);
  for (const cv::Point& p : line) cv::circle(image, p, 3, cv::Scalar(0, 0, 150), cv::FILLED);
  writeImage(path, image);
}

}  // namespace rgnav
