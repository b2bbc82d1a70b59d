// BeamEvidence: per grid cell, how many laser returns fell into it (hits, the return pushed half
// a cell along its beam, see PointCloud.h) and how many beams passed through it (passes, up to
// one cell short of the return): the counts of occupancy grid mapping. A cell is seen free when
// more beams passed through it than ended in it. Object hypotheses whose inside the laser has
// seen through are not objects: a room's four walls group to a "rectangle" as well as a
// cabinet's four sides do, but the robot's beams cross the room. A return grazing a surface
// can land in the free cell before it; the passes of the other beams outvote it. Cells no beam
// reached are unobserved: the back of an object seen from one side.
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/SensorData.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class BeamEvidence {
 public:
  // Same geometry as `grid` (only its size, resolution and origin are used).
  explicit BeamEvidence(const OccupancyGrid& grid);

  // Counts the beams of `scan` (taken at its sensorPose).
  void add(const LaserScan& scan);
  bool seenFree(std::size_t cell) const { return passes_[cell] > hits_[cell]; }
  bool hit(std::size_t cell) const { return hits_[cell] > 0; }
  // No beam ended in or passed through the cell: hidden behind an object (or never in view).
  bool unobserved(std::size_t cell) const { return hits_[cell] == 0 && passes_[cell] == 0; }

  // `cells` (row-major, ascending) grown by up to `steps` 4-neighbour steps into unobserved
  // cells: the hidden back of an object seen from one side. Ascending, unique.
  std::vector<std::size_t> growIntoUnobserved(std::vector<std::size_t> cells, int steps) const;

 private:
  // The row-major index of the cell holding (x, y), or -1 outside the grid.
  std::int64_t cellAt(double x, double y) const;

  int width_;
  int height_;
  double resolution_;
  WorldPoint origin_;
  std::vector<std::uint32_t> hits_;
  std::vector<std::uint32_t> passes_;
};

}  // namespace rgnav
