// PathSmoothing: string pulling and corner snapping (see the header).
#include "core/nav/planning/PathSmoothing.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>

#include "core/nav/planning/SegmentVisibility.h"

namespace rgnav {

namespace {

constexpr int kMaxRounds = 16;
constexpr double kShorter = 1e-9;  // a change must gain at least this much, so rounds terminate

// The cost of travelling a segment: its length times one plus the mean cell cost sampled every
// half cell along it.
double segmentCost(const OccupancyGrid& grid, const std::vector<float>& cellCost, const Eigen::Vector2d& a,
                   const Eigen::Vector2d& b) {
  const double length = (b - a).norm();
  const int samples = 1 + static_cast<int>(std::ceil(2.0 * length));
  double sum = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const Eigen::Vector2d p = a + (b - a) * (double(i) / samples);
    const int col = std::clamp(static_cast<int>(std::floor(p.x())), 0, grid.width() - 1);
    const int row = std::clamp(static_cast<int>(std::floor(p.y())), 0, grid.height() - 1);
    sum += cellCost[static_cast<std::size_t>(row) * grid.width() + col];
  }
  return length * (1.0 + sum / (samples + 1));
}

double travelCost(const OccupancyGrid& grid, const std::vector<float>& cellCost, const Eigen::Vector2d& a,
                  const Eigen::Vector2d& b) {
  return cellCost.empty() ? (b - a).norm() : segmentCost(grid, cellCost, a, b);
}

// Greedy string pulling from the first point: keeps a point only where the shortcut past it is
// blocked (or dearer). Returns whether a point was dropped.
bool pullString(const OccupancyGrid& grid, const std::vector<float>& cellCost, std::vector<Eigen::Vector2d>& points) {
  if (points.size() < 3) return false;
  std::vector<Eigen::Vector2d> kept{points.front()};
  std::size_t anchor = 0;
  double viaCost = 0.0;  // cost from points[anchor] along the kept polyline to points[i]
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Eigen::Vector2d& from = points[anchor];
    const Eigen::Vector2d& next = points[i + 1];
    bool skip = segmentFree(grid, from, next);
    double shortcut = 0.0;
    if (skip && !cellCost.empty()) {
      if (i == anchor + 1) viaCost = travelCost(grid, cellCost, from, points[i]);
      shortcut = travelCost(grid, cellCost, from, next);
      skip = shortcut <= viaCost + travelCost(grid, cellCost, points[i], next);
    }
    if (skip) {
      viaCost = shortcut;
    } else {
      kept.push_back(points[i]);
      anchor = i;
    }
  }
  kept.push_back(points.back());
  const bool changed = kept.size() < points.size();
  points = std::move(kept);
  return changed;
}

// Moves every bend that is not on a grid vertex onto the corners of its cell: one corner, or two
// along one side of the cell (a path through a door one cell wide bends at both jambs), whichever
// shortens the path most with every segment still free. Returns whether a bend moved.
bool snapBendsToCorners(const OccupancyGrid& grid, std::vector<Eigen::Vector2d>& points) {
  bool changed = false;
  std::vector<Eigen::Vector2d> snapped{points.front()};
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Eigen::Vector2d& a = snapped.back();
    const Eigen::Vector2d& b = points[i + 1];
    const Eigen::Vector2d p = points[i];
    if (std::floor(p.x()) == p.x() && std::floor(p.y()) == p.y()) {
      snapped.push_back(p);
      continue;
    }
    const double x0 = std::floor(p.x()), y0 = std::floor(p.y());
    const std::array<Eigen::Vector2d, 4> corners{Eigen::Vector2d(x0, y0), Eigen::Vector2d(x0 + 1, y0),
                                                 Eigen::Vector2d(x0 + 1, y0 + 1), Eigen::Vector2d(x0, y0 + 1)};
    double best = (p - a).norm() + (b - p).norm() - kShorter;
    std::array<Eigen::Vector2d, 2> chosen{p, p};
    std::size_t count = 1;
    for (std::size_t k = 0; k < 4; ++k) {
      const Eigen::Vector2d& c = corners[k];
      const double length = (c - a).norm() + (b - c).norm();
      if (length < best && segmentFree(grid, a, c) && segmentFree(grid, c, b)) {
        best = length;
        chosen = {c, c};
        count = 1;
      }
      for (const std::size_t next : {(k + 1) % 4, (k + 3) % 4}) {
        const Eigen::Vector2d& d = corners[next];
        const double twoBends = (c - a).norm() + 1.0 + (b - d).norm();
        if (twoBends < best && segmentFree(grid, a, c) && segmentFree(grid, c, d) && segmentFree(grid, d, b)) {
          best = twoBends;
          chosen = {c, d};
          count = 2;
        }
      }
    }
    changed = changed || chosen[0] != p;
    snapped.insert(snapped.end(), chosen.begin(), chosen.begin() + static_cast<std::ptrdiff_t>(count));
  }
  snapped.push_back(points.back());
  points = std::move(snapped);
  return changed;
}

}  // namespace

void smoothPath(const OccupancyGrid& grid, const std::vector<float>& cellCost, std::vector<Eigen::Vector2d>& points) {
  for (int round = 0; round < kMaxRounds; ++round) {
    const bool pulled = pullString(grid, cellCost, points);
    if (!cellCost.empty()) {
      if (!pulled) return;
      continue;
    }
    if (!snapBendsToCorners(grid, points) && !pulled) return;
  }
}

}  // namespace rgnav
