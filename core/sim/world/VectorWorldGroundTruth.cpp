// groundTruthOf: room polygons to cell labels, doors to door lines.
#include "core/sim/world/VectorWorldGroundTruth.h"

#include "core/sim/world/GroundTruthAssembly.h"

namespace rgnav {
namespace {

bool inside(const std::vector<WorldPoint>& polygon, WorldPoint p) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const WorldPoint& a = polygon[i];
    const WorldPoint& b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

int roomContaining(const VectorWorld& world, WorldPoint p) {
  for (std::size_t i = 0; i < world.rooms.size(); ++i) {
    if (inside(world.rooms[i].polygon, p)) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

GroundTruth groundTruthOf(const VectorWorld& world, const OccupancyGrid& grid) {
  std::vector<int> labels(grid.cells().size(), -1);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (grid.at({col, row}) != Cell::Free) continue;
      labels[static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.width()) + static_cast<std::size_t>(col)] =
          roomContaining(world, grid.center({col, row}));
    }
  }
  GroundTruth truth = groundTruthFrame(grid, std::move(labels), static_cast<int>(world.rooms.size()));
  for (const Door& door : world.doors) {
    const auto [a, b] = doorOpening(world, door);
    DoorLine line{a, b};
    assignDoorRooms(truth, line, world.walls.at(door.wall).thickness / 2.0 + kDoorProbeBeyondWall);
    truth.doors.push_back(line);
  }
  return truth;
}

}  // namespace rgnav
