// FreeSpace: which grid cells laser beams have passed through (seen free). Object hypotheses
// whose inside the laser has seen through are not objects: a room's four walls group to a
// "rectangle" as well as a cabinet's four sides do, but the robot's beams cross the room.
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/SensorData.h"
#include "core/sim/OccupancyGrid.h"

namespace rgnav {

class FreeSpace {
 public:
  // Same geometry as `grid` (only its size, resolution and origin are used).
  explicit FreeSpace(const OccupancyGrid& grid);

  // Marks the cells along every beam with a return, up to one cell short of the return.
  void add(const LaserScan& scan);
  bool seenFree(std::size_t cell) const { return seen_[cell] != 0; }

 private:
  int width_;
  int height_;
  double resolution_;
  WorldPoint origin_;
  std::vector<std::uint8_t> seen_;
};

}  // namespace rgnav
