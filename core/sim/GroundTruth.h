// GroundTruth: what a world knows about itself for evaluations only (never for algorithm
// modules): the room each cell belongs to, and the door lines between rooms.
#pragma once

#include <cmath>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct DoorLine {
  WorldPoint a;
  WorldPoint b;
  int roomA = -1;  // rooms on either side (-1 if unknown)
  int roomB = -1;
};

struct GroundTruth {
  // Same geometry as the world grid: labels[row * width + col] is a room ID 0..roomCount-1, or
  // -1 for cells that belong to no room (walls, outside, door separators).
  int width = 0;
  int height = 0;
  double resolution = 0.05;
  WorldPoint origin;
  std::vector<int> labels;
  int roomCount = 0;
  std::vector<DoorLine> doors;

  int roomAt(WorldPoint p) const {
    return roomOf({static_cast<int>(std::floor((p.x - origin.x) / resolution)),
                   static_cast<int>(std::floor((p.y - origin.y) / resolution))});
  }

  int roomOf(CellIndex c) const {
    if (c.col < 0 || c.row < 0 || c.col >= width || c.row >= height) return -1;
    return labels[static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c.col)];
  }
};

}  // namespace rgnav
