// TruthCoverage: what the exploration evaluation (issue 29, "rgctl eval exploration") measures
// against the world's truth, never shown to the robot:
//   - the reachable free area: the cells a disk of the robot's radius can cover when its centre
//     moves from the start over traversable cells (GridPlanner: clearance >= radius + half a cell
//     diagonal) connected to the start, i.e. those traversable cells dilated by the radius and kept
//     where the furnished world is free. Niches narrower than the robot (between chair legs) and
//     rooms behind passages it cannot pass are not part of it;
//   - the seen area: reachable cells a beam of the TRUE laser passed through or ended in, each
//     beam cast from the scan's true sensor pose up to its measured range, capped at the useful
//     range (8 m by default: farther, 1-degree beams are over 14 cm apart and miss cells);
//     cells are those of cv::LineIterator (8-connected) from the sensor's cell to the end's;
//   - per ground-truth room: its reachable cells and how many were seen. A room is reachable if
//     it has at least kIpaMinRoomPixels reachable cells (the benchmark's smallest room: fewer are
//     the robot's edge reaching through a door it cannot pass); it is found once half of its
//     reachable cells were seen.
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/SensorData.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"

namespace rgnav {

inline constexpr double kFoundRoomShare = 0.5;  // a room is found once this share of it was seen

struct RoomCoverage {
  int room = -1;
  std::size_t reachableCells = 0;
  std::size_t seenCells = 0;
  bool reachable() const;
  bool found() const { return reachable() && double(seenCells) >= kFoundRoomShare * double(reachableCells); }
};

class TruthCoverage {
 public:
  // Keeps references to `world` and `truth`, which must outlive it. Throws StartBlockedError if
  // the robot cannot stand at `start`, InvalidArgumentError if the truth does not share the
  // world's geometry or usefulRangeM is not positive.
  TruthCoverage(const OccupancyGrid& world, const GroundTruth& truth, const WorldPoint& start, double robotRadiusM,
                double usefulRangeM);

  // One scan of the true laser: its sensorPose is the true laser pose.
  void addScan(const LaserScan& scan);

  std::size_t reachableCells() const { return reachableCount_; }
  std::size_t seenCells() const { return seenCount_; }
  double seenShare() const;
  bool reachable(std::size_t cell) const { return reachable_[cell] != 0; }  // row-major, row 0 at the bottom
  bool seen(std::size_t cell) const { return seen_[cell] != 0; }
  // By room ID.
  std::vector<RoomCoverage> rooms() const;

 private:
  const OccupancyGrid& world_;
  const GroundTruth& truth_;
  double usefulRangeM_;
  std::vector<std::uint8_t> reachable_;
  std::vector<std::uint8_t> seen_;
  std::size_t reachableCount_ = 0;
  std::size_t seenCount_ = 0;
};

}  // namespace rgnav
