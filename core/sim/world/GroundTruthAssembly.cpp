// Ground-truth assembly: geometry from the grid, door sides by perpendicular probing in
// half-cell steps.
#include "core/sim/world/GroundTruthAssembly.h"

#include <cmath>
#include <utility>

namespace rgnav {
namespace {

int roomAt(const GroundTruth& truth, double x, double y) {
  return truth.roomOf({static_cast<int>(std::floor((x - truth.origin.x) / truth.resolution)),
                       static_cast<int>(std::floor((y - truth.origin.y) / truth.resolution))});
}

int probe(const GroundTruth& truth, const DoorLine& door, double side, double maxDistance) {
  const double dx = door.b.x - door.a.x;
  const double dy = door.b.y - door.a.y;
  const double length = std::hypot(dx, dy);
  const double nx = length > 0.0 ? -dy / length : 0.0;
  const double ny = length > 0.0 ? dx / length : 1.0;
  const double step = truth.resolution / 2.0;
  for (const double fraction : {0.5, 0.25, 0.75}) {
    const double x0 = door.a.x + fraction * dx;
    const double y0 = door.a.y + fraction * dy;
    for (double d = step; d <= maxDistance; d += step) {
      const int room = roomAt(truth, x0 + side * d * nx, y0 + side * d * ny);
      if (room >= 0) return room;
    }
  }
  return -1;
}

}  // namespace

GroundTruth groundTruthFrame(const OccupancyGrid& grid, std::vector<int> labels, int roomCount) {
  GroundTruth truth;
  truth.width = grid.width();
  truth.height = grid.height();
  truth.resolution = grid.resolution();
  truth.origin = grid.origin();
  truth.labels = std::move(labels);
  truth.roomCount = roomCount;
  return truth;
}

void assignDoorRooms(const GroundTruth& truth, DoorLine& door, double maxDistance) {
  door.roomA = probe(truth, door, 1.0, maxDistance);
  door.roomB = probe(truth, door, -1.0, maxDistance);
}

}  // namespace rgnav
