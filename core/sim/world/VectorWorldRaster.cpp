// rasterize: footprints (oriented rectangles and discs) painted into a grid by distance test.
#include "core/sim/world/VectorWorldRaster.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace rgnav {
namespace {

struct Rectangle2D {
  Eigen::Vector2d center;
  Eigen::Vector2d axis;  // unit, along the length
  double halfLength;
  double halfWidth;
};

bool reachesPlane(double elevation, double height, double planeHeight) {
  return elevation <= planeHeight && elevation + height >= planeHeight;
}

double distanceTo(const Rectangle2D& r, const Eigen::Vector2d& p) {
  const Eigen::Vector2d q = p - r.center;
  const double along = std::max(std::abs(q.dot(r.axis)) - r.halfLength, 0.0);
  const double across = std::max(std::abs(r.axis.x() * q.y() - r.axis.y() * q.x()) - r.halfWidth, 0.0);
  return std::hypot(along, across);
}

double reach(const Rectangle2D& r) { return std::hypot(r.halfLength, r.halfWidth); }

// A cell centre exactly half a cell from a shape (a face on a cell boundary) stays free.
constexpr double kTouchTolerance = 1e-9;  // m

// Marks occupied every cell within `radius` of `center` whose centre is closer than half a cell
// to the shape.
template <typename Distance>
void paint(OccupancyGrid& grid, const Eigen::Vector2d& center, double radius, Distance distance) {
  const double res = grid.resolution();
  const WorldPoint o = grid.origin();
  const double margin = radius + res;
  const int col0 = std::max(0, static_cast<int>(std::floor((center.x() - margin - o.x) / res)));
  const int row0 = std::max(0, static_cast<int>(std::floor((center.y() - margin - o.y) / res)));
  const int col1 = std::min(grid.width() - 1, static_cast<int>(std::floor((center.x() + margin - o.x) / res)));
  const int row1 = std::min(grid.height() - 1, static_cast<int>(std::floor((center.y() + margin - o.y) / res)));
  for (int row = row0; row <= row1; ++row) {
    for (int col = col0; col <= col1; ++col) {
      const WorldPoint c = grid.center({col, row});
      if (distance(Eigen::Vector2d(c.x, c.y)) < res / 2.0 - kTouchTolerance) grid.set({col, row}, Cell::Occupied);
    }
  }
}

void paintRectangle(OccupancyGrid& grid, const Rectangle2D& r) {
  paint(grid, r.center, reach(r), [&](const Eigen::Vector2d& p) { return distanceTo(r, p); });
}

// The solid stretches of a wall, [start, end] along it, once its open doors are cut out.
std::vector<std::pair<double, double>> solidStretches(const VectorWorld& world, std::size_t wallIndex) {
  const Wall& wall = world.walls[wallIndex];
  std::vector<std::pair<double, double>> openings;
  for (const Door& door : world.doors) {
    if (door.wall == wallIndex && door.open) {
      openings.emplace_back(door.offset - door.width / 2.0, door.offset + door.width / 2.0);
    }
  }
  std::sort(openings.begin(), openings.end());
  std::vector<std::pair<double, double>> solid;
  double start = -wall.thickness / 2.0;
  for (const auto& [open, close] : openings) {
    if (open > start) solid.emplace_back(start, open);
    start = std::max(start, close);
  }
  const double end = wallLength(wall) + wall.thickness / 2.0;
  if (end > start) solid.emplace_back(start, end);
  return solid;
}

void paintWall(OccupancyGrid& grid, const VectorWorld& world, std::size_t wallIndex) {
  const Wall& wall = world.walls[wallIndex];
  for (const auto& [start, end] : solidStretches(world, wallIndex)) {
    paintRectangle(grid, {pointOnWall(wall, (start + end) / 2.0, 0.0), wallDirection(wall), (end - start) / 2.0,
                          wall.thickness / 2.0});
  }
}

OccupancyGrid emptyGrid(const VectorWorld& world) {
  if (world.floorPlan) return *world.floorPlan;
  const auto cells = [&](double extent) { return static_cast<int>(std::ceil(extent / world.resolution - 1e-9)); };
  return OccupancyGrid(cells(world.max.x - world.min.x), cells(world.max.y - world.min.y), world.resolution,
                       world.min);
}

}  // namespace

OccupancyGrid rasterize(const VectorWorld& world, double planeHeight) {
  OccupancyGrid grid = emptyGrid(world);
  for (std::size_t i = 0; i < world.walls.size(); ++i) {
    if (reachesPlane(0.0, world.walls[i].height, planeHeight)) paintWall(grid, world, i);
  }
  for (const Box& box : world.boxes) {
    if (!reachesPlane(box.elevation, box.height, planeHeight)) continue;
    paintRectangle(grid, {Eigen::Vector2d(box.center.x, box.center.y),
                          Eigen::Vector2d(std::cos(box.yaw), std::sin(box.yaw)), box.length / 2.0, box.width / 2.0});
  }
  for (const Cylinder& cylinder : world.cylinders) {
    if (!reachesPlane(cylinder.elevation, cylinder.height, planeHeight)) continue;
    const Eigen::Vector2d center(cylinder.center.x, cylinder.center.y);
    paint(grid, center, cylinder.radius,
          [&](const Eigen::Vector2d& p) { return std::max((p - center).norm() - cylinder.radius, 0.0); });
  }
  return grid;
}

}  // namespace rgnav
