// The map-frame exploration grid of an RG map (ExplorationGrid.h): the regions' freespace bitmaps
// sampled at the grid's cell centres through the region frames, the regions' line maps rendered
// into it with OpenCV's cv::line (8-connected, sub-cell endpoints) and their distance taken with
// cv::distanceTransform (exact Euclidean), so that every cell within wallClearanceM of a line is
// Wall, also where a region's freespace claims it.
#include "core/nav/exploration/ExplorationGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <opencv2/imgproc.hpp>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {
namespace {

constexpr double kMaxCells = 5e7;  // 5000 m² at 1 cm, 500 000 m² at 10 cm: far beyond any building
constexpr int kLineShift = 4;      // cv::line's fractional bits for sub-cell endpoints

struct Box {
  Eigen::Vector2d min = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d max = -Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  void add(const Eigen::Vector2d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool empty() const { return !(min.x() <= max.x()); }
};

// The map-frame box around the region's free cells; empty if it has none.
Box freeBox(const RegionView& region) {
  const FreespaceBitmap& f = region.freespace;
  int c0 = f.width, c1 = -1, r0 = f.height, r1 = -1;
  for (int row = 0; row < f.height; ++row)
    for (int col = 0; col < f.width; ++col)
      if (f.isFree(col, row)) {
        c0 = std::min(c0, col), c1 = std::max(c1, col);
        r0 = std::min(r0, row), r1 = std::max(r1, row);
      }
  Box box;
  if (c1 < 0) return box;
  const Eigen::Vector2d lo = f.originM + Eigen::Vector2d(c0, r0) * f.resolutionM;
  const Eigen::Vector2d hi = f.originM + Eigen::Vector2d(c1 + 1, r1 + 1) * f.resolutionM;
  for (const Eigen::Vector2d& corner : {lo, hi, Eigen::Vector2d(lo.x(), hi.y()), Eigen::Vector2d(hi.x(), lo.y())})
    box.add(transformPoint(region.summary.frame, corner));
  return box;
}

}  // namespace

ExplorationGrid ExplorationGrid::fromMap(const PlanningMap& map, const ExplorationGridConfig& config) {
  requirePositive(config.resolutionM, "exploration grid resolution_m");
  requireNonNegative(config.wallClearanceM, "exploration grid wall_clearance_m");
  ExplorationGrid grid;
  grid.resolutionM_ = config.resolutionM;
  const double res = config.resolutionM;

  std::vector<Box> boxes;
  Box all;
  for (const RegionView& region : map.regions) {
    boxes.push_back(freeBox(region));
    if (!boxes.back().empty()) {
      all.add(boxes.back().min);
      all.add(boxes.back().max);
    }
  }
  if (all.empty()) return grid;
  // A margin of unknown cells around the free ones, wide enough for the wall band.
  const int margin = 2 + static_cast<int>(std::ceil(config.wallClearanceM / res));
  const Eigen::Vector2d lo = (all.min / res).array().floor().matrix() * res;
  const double cols = std::ceil((all.max.x() - lo.x()) / res) + 2 * margin;
  const double rows = std::ceil((all.max.y() - lo.y()) / res) + 2 * margin;
  if (cols * rows > kMaxCells)
    throw InvalidArgumentError("exploration grid: " + std::to_string(cols * rows) + " cells at " + std::to_string(res) +
                               " m exceed the limit; the map is too large for this resolution");
  grid.originM_ = lo - Eigen::Vector2d::Constant(margin * res);
  grid.width_ = static_cast<int>(cols);
  grid.height_ = static_cast<int>(rows);
  const std::size_t cells = static_cast<std::size_t>(grid.width_) * static_cast<std::size_t>(grid.height_);
  grid.cells_.assign(cells, ExplorationCell::Unknown);
  grid.regions_.assign(cells, RegionId{});

  // Free: the regions in ascending ID, so the lowest ID claims a cell where freespaces overlap.
  std::vector<std::size_t> order(map.regions.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return map.regions[a].summary.id < map.regions[b].summary.id; });
  for (const std::size_t i : order) {
    const RegionView& region = map.regions[i];
    if (boxes[i].empty()) continue;
    const Pose2D toRegion = inverse(region.summary.frame);
    int c0 = 0, r0 = 0, c1 = 0, r1 = 0;
    grid.cellOf(boxes[i].min, c0, r0);
    grid.cellOf(boxes[i].max, c1, r1);
    for (int row = r0; row <= r1; ++row)
      for (int col = c0; col <= c1; ++col) {
        const std::size_t k = static_cast<std::size_t>(row) * grid.width_ + col;
        if (grid.cells_[k] == ExplorationCell::Free) continue;
        if (!region.freespace.isFreeAt(transformPoint(toRegion, grid.cellCenter(col, row)))) continue;
        grid.cells_[k] = ExplorationCell::Free;
        grid.regions_[k] = region.summary.id;
      }
  }

  // Walls: every region's lines in the map frame; image row = grid row.
  cv::Mat lines(grid.height_, grid.width_, CV_8U, cv::Scalar(255));
  bool anyLine = false;
  const double scale = (1 << kLineShift) / res;
  const auto pixel = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d q = (p - grid.originM_) * scale - Eigen::Vector2d::Constant(0.5 * (1 << kLineShift));
    return cv::Point(static_cast<int>(std::lround(q.x())), static_cast<int>(std::lround(q.y())));
  };
  for (const RegionView& region : map.regions)
    for (const Segment2& line : region.lines) {
      const Eigen::Vector2d a = transformPoint(region.summary.frame, line.a);
      const Eigen::Vector2d b = transformPoint(region.summary.frame, line.b);
      if (!a.allFinite() || !b.allFinite()) continue;
      cv::line(lines, pixel(a), pixel(b), cv::Scalar(0), 1, cv::LINE_8, kLineShift);
      anyLine = true;
    }
  grid.wallDistanceM_.assign(cells, std::numeric_limits<float>::infinity());
  if (anyLine && cv::countNonZero(lines) < lines.rows * lines.cols) {
    cv::Mat distance;
    cv::distanceTransform(lines, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
    for (int row = 0; row < grid.height_; ++row)
      for (int col = 0; col < grid.width_; ++col) {
        const std::size_t k = static_cast<std::size_t>(row) * grid.width_ + col;
        grid.wallDistanceM_[k] = distance.at<float>(row, col) * static_cast<float>(res);
        if (grid.wallDistanceM_[k] <= config.wallClearanceM) {
          grid.cells_[k] = ExplorationCell::Wall;
          grid.regions_[k] = RegionId{};
        }
      }
  }
  return grid;
}

ExplorationCell ExplorationGrid::at(int col, int row) const {
  if (col < 0 || row < 0 || col >= width_ || row >= height_) return ExplorationCell::Unknown;
  return cells_[static_cast<std::size_t>(row) * width_ + col];
}

RegionId ExplorationGrid::regionAt(int col, int row) const {
  if (col < 0 || row < 0 || col >= width_ || row >= height_) return RegionId{};
  return regions_[static_cast<std::size_t>(row) * width_ + col];
}

double ExplorationGrid::wallDistanceM(int col, int row) const {
  if (col < 0 || row < 0 || col >= width_ || row >= height_) return 0.0;
  return wallDistanceM_[static_cast<std::size_t>(row) * width_ + col];
}

Eigen::Vector2d ExplorationGrid::cellCenter(int col, int row) const {
  return originM_ + Eigen::Vector2d(col + 0.5, row + 0.5) * resolutionM_;
}

bool ExplorationGrid::cellOf(const Eigen::Vector2d& point, int& col, int& row) const {
  const Eigen::Vector2d q = (point - originM_) / resolutionM_;
  if (!q.allFinite()) return false;
  const double c = std::floor(q.x()), r = std::floor(q.y());
  if (c < 0 || r < 0 || c >= width_ || r >= height_) return false;
  col = static_cast<int>(c);
  row = static_cast<int>(r);
  return true;
}

std::size_t ExplorationGrid::freeCount() const {
  return static_cast<std::size_t>(std::count(cells_.begin(), cells_.end(), ExplorationCell::Free));
}

}  // namespace rgnav
