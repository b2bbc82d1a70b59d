// HallwayLayout: arms as rotated copies of one rectangle, wall faces where no hallway continues.
#include "core/sim/scenarios/HallwayLayout.h"

#include <algorithm>
#include <cmath>

#include "core/common/ValueChecks.h"

namespace rgnav {

namespace {

struct Direction {
  double x;
  double y;
};

// Maps local arm coordinates (u along the arm away from the gateway area, v to its left) to the
// gateway frame.
WorldPoint toFrame(Direction d, double u, double v) { return {d.x * u - d.y * v, d.y * u + d.x * v}; }

WorldRect boundsOf(WorldPoint a, WorldPoint b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

// A hallway of `length` leaving the gateway area in direction d: its rectangle, its two side
// walls and its end wall.
void addArm(HallwayLayout& layout, Direction d, double length) {
  const double h = layout.width / 2.0;
  layout.hallways.push_back(boundsOf(toFrame(d, h, -h), toFrame(d, h + length, h)));
  const WorldPoint leftInward = toFrame(d, 0.0, -1.0);
  const WorldPoint rightInward = toFrame(d, 0.0, 1.0);
  const WorldPoint endInward = toFrame(d, -1.0, 0.0);
  layout.walls.push_back({toFrame(d, h, h), toFrame(d, h + length, h), leftInward});
  layout.walls.push_back({toFrame(d, h, -h), toFrame(d, h + length, -h), rightInward});
  layout.walls.push_back({toFrame(d, h + length, -h), toFrame(d, h + length, h), endInward});
}

// The side of the gateway area facing direction d, closed by a wall.
void closeSide(HallwayLayout& layout, Direction d) {
  const double h = layout.width / 2.0;
  layout.walls.push_back({toFrame(d, h, -h), toFrame(d, h, h), toFrame(d, -1.0, 0.0)});
}

}  // namespace

HallwayLayout makeHallwayLayout(GatewayClass gatewayClass, double width, double approachLength,
                                double armLength) {
  requirePositive(width, "hallway width");
  requirePositive(approachLength, "approach hallway length");
  requirePositive(armLength, "hallway arm length");
  HallwayLayout layout;
  layout.gatewayClass = gatewayClass;
  layout.width = width;
  const double h = width / 2.0;
  layout.hallways.push_back({-h, -h, h, h});
  addArm(layout, {-1.0, 0.0}, approachLength);
  const GatewayOpenings open = openingsOf(gatewayClass);
  const Direction left{0.0, 1.0}, straight{1.0, 0.0}, right{0.0, -1.0};
  for (const auto& [isOpen, d] : {std::pair{open.left, left}, std::pair{open.straight, straight},
                                  std::pair{open.right, right}}) {
    if (isOpen) {
      addArm(layout, d, armLength);
    } else {
      closeSide(layout, d);
    }
  }
  return layout;
}

OccupancyGrid rasterize(const HallwayLayout& layout, double resolution, double wallThickness) {
  requirePositive(resolution, "grid resolution");
  requirePositive(wallThickness, "wall thickness");
  WorldRect all = layout.hallways.front();
  for (const WorldRect& r : layout.hallways) {
    all = {std::min(all.minX, r.minX), std::min(all.minY, r.minY), std::max(all.maxX, r.maxX),
           std::max(all.maxY, r.maxY)};
  }
  const WorldPoint origin{all.minX - wallThickness, all.minY - wallThickness};
  const int width = static_cast<int>(std::ceil((all.maxX - all.minX + 2.0 * wallThickness) / resolution));
  const int height = static_cast<int>(std::ceil((all.maxY - all.minY + 2.0 * wallThickness) / resolution));
  OccupancyGrid grid(width, height, resolution, origin, Cell::Occupied);
  for (const WorldRect& r : layout.hallways) {
    fillRect(grid, r, Cell::Free);
  }
  return grid;
}

bool insideHallways(const HallwayLayout& layout, WorldPoint p) {
  return std::any_of(layout.hallways.begin(), layout.hallways.end(), [p](const WorldRect& r) {
    return p.x >= r.minX && p.x <= r.maxX && p.y >= r.minY && p.y <= r.maxY;
  });
}

}  // namespace rgnav
