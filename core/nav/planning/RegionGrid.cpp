// RegionGrid: rendering, inflation and freespace masking of a region's planning grid.
#include "core/nav/planning/RegionGrid.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether segments pq and ab share a point.
bool segmentsMeet(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double d1 = cross(q - p, a - p), d2 = cross(q - p, b - p), d3 = cross(b - a, p - a), d4 = cross(b - a, q - a);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  const auto onSegment = [](const Eigen::Vector2d& s, const Eigen::Vector2d& t, const Eigen::Vector2d& x, double side) {
    return side == 0.0 && x.x() >= std::min(s.x(), t.x()) && x.x() <= std::max(s.x(), t.x()) &&
           x.y() >= std::min(s.y(), t.y()) && x.y() <= std::max(s.y(), t.y());
  };
  return onSegment(p, q, a, d1) || onSegment(p, q, b, d2) || onSegment(a, b, p, d3) || onSegment(a, b, q, d4);
}

}  // namespace

Eigen::Vector2d RegionGrid::toCells(const Eigen::Vector2d& p) const {
  return {(p.x() - grid.origin().x) / grid.resolution(), (p.y() - grid.origin().y) / grid.resolution()};
}

Eigen::Vector2d RegionGrid::toRegion(const Eigen::Vector2d& c) const {
  return {grid.origin().x + c.x() * grid.resolution(), grid.origin().y + c.y() * grid.resolution()};
}

bool RegionGrid::freeAt(const Eigen::Vector2d& p) const {
  const auto cell = grid.cellOf({p.x(), p.y()});
  return cell && !grid.blocked(*cell);
}

std::optional<Eigen::Vector2d> RegionGrid::nearestFree(const Eigen::Vector2d& p, double maxDistanceM, bool overWalls,
                                                       const std::function<bool(CellIndex)>& usable) const {
  const auto accepted = [&](CellIndex cell) { return !grid.blocked(cell) && (!usable || usable(cell)); };
  if (const auto cell = grid.cellOf({p.x(), p.y()}); cell && accepted(*cell)) return p;
  const Eigen::Vector2d c = toCells(p);
  const int reach = static_cast<int>(std::ceil(maxDistanceM / grid.resolution()));
  const int col = static_cast<int>(std::floor(c.x())), row = static_cast<int>(std::floor(c.y()));
  std::optional<Eigen::Vector2d> best;
  double bestDistance = maxDistanceM;
  for (int r = row - reach; r <= row + reach; ++r)
    for (int k = col - reach; k <= col + reach; ++k) {
      if (!accepted({k, r})) continue;
      const Eigen::Vector2d centre = toRegion({k + 0.5, r + 0.5});
      const double d = (centre - p).norm();
      if (d > bestDistance) continue;
      if (!overWalls &&
          std::any_of(walls.begin(), walls.end(), [&](const Segment2& w) { return segmentsMeet(p, centre, w.a, w.b); }))
        continue;
      bestDistance = d;
      best = centre;
    }
  return best;
}

RegionGrid buildRegionGrid(const RegionView& region, double resolutionM, double robotRadiusM) {
  if (!(resolutionM > 0.0) || !(robotRadiusM >= 0.0))
    throw InvalidArgumentError("region grid: the resolution must be positive and the radius not negative");
  const FreespaceBitmap& free = region.freespace;
  if (free.width == 0 || free.height == 0) return {OccupancyGrid(1, 1, resolutionM, {}, Cell::Unknown), region.lines};

  const Eigen::Vector2d lo = free.originM;
  const Eigen::Vector2d hi = lo + Eigen::Vector2d(free.width, free.height) * free.resolutionM;
  const int width = static_cast<int>(std::ceil((hi.x() - lo.x()) / resolutionM));
  const int height = static_cast<int>(std::ceil((hi.y() - lo.y()) / resolutionM));
  RegionGrid out{OccupancyGrid(width, height, resolutionM, {lo.x(), lo.y()}, Cell::Unknown), region.lines};

  // Walls: 0 on a line, 255 elsewhere, so that the distance transform measures to the lines.
  cv::Mat open(height, width, CV_8U, cv::Scalar(255));
  const auto pixel = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d c = out.toCells(p);
    return cv::Point(static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y())));
  };
  for (const Segment2& line : region.lines) cv::line(open, pixel(line.a), pixel(line.b), cv::Scalar(0), 1, cv::LINE_8);
  cv::Mat distance;
  cv::distanceTransform(open, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);

  // A cell is free if its centre lies in the freespace and no wall cell lies within the radius
  // (distances between cell centres; a wall cell itself is at distance 0).
  const double clearCells = robotRadiusM / resolutionM;
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      const Eigen::Vector2d centre = out.toRegion({c + 0.5, r + 0.5});
      if (free.isFreeAt(centre) && distance.at<float>(r, c) > clearCells) out.grid.set({c, r}, Cell::Free);
    }
  return out;
}

}  // namespace rgnav
