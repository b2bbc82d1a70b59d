// RegionFreespace: the freespace of one region (thesis 2.1.1, table 2.1 "2D freespace"; 5.2
// "freespace map"), grown scan by scan in the region frame from the beams inside the region
// (RegionBeams.h). Cells lie on a fixed lattice of the region frame: cell (i, j) covers
// [i * s, (i + 1) * s) x [j * s, (j + 1) * s) for the cell size s, so grids of the same region
// always line up. Each cell counts the beams that ended in it on an obstacle (hit) and the beams
// that passed through it or ended in it without one (free):
//   - unknown: no beam passed or ended in it;
//   - free: free >= 1 and free >= freePerHit * hit (where something was seen, the cell is free
//     again once beams have passed it freePerHit times as often: people walking by leave no
//     lasting obstacle, while a wall, hit far more often than beams graze its cells, stays);
//   - occupied: otherwise.
// The grid grows as scans need it (with a margin, so growth is rare), never beyond maxExtentM per
// side: a region that outgrows it (outdoors, a long stretch with no gateway) keeps the cells it
// has, beams are cut at the grid's border, and a scan taken beyond it adds nothing.
// The exported map is the 1-bit FreespaceBitmap, cropped to the free cells.
// Deliberate difference: the thesis stores only the bit per cell; we keep the two counts while the
// region is built, because revisited and merged regions (thesis 2.2, 6.1.1) must combine evidence,
// and completeness needs to tell obstacles from unexplored space.
// Memory: 8 bytes per cell of the grown grid (a 6 x 5 m room with its margins: about 40 kB).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/rgmap/describe/FreespaceBitmap.h"
#include "core/rgmap/describe/GridTraversal.h"
#include "core/rgmap/describe/RegionBeams.h"

namespace rgnav {

struct FreespaceConfig {
  double cellSizeM = 0.15;          // thesis 5.2: 15 cm in x and y
  double noReturnFreeRangeM = 3.0;  // beams without return are free up to here
  double maxExtentM = 200.0;        // the grid never gets wider or taller than this
  double freePerHit = 4.0;          // free passes needed per hit for a cell to count as free
};

template <class V>
void describe(V& v, FreespaceConfig& c) {
  v.field("cell_size_m", c.cellSizeM);
  v.field("no_return_free_range_m", c.noReturnFreeRangeM);
  v.field("max_extent_m", c.maxExtentM);
  v.field("free_per_hit", c.freePerHit);
}

enum class FreespaceCell : std::uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

// The part of the lattice a grid holds: cells i in [col0, col0 + width), j in [row0, row0 + height).
struct CellWindow {
  int col0 = 0;
  int row0 = 0;
  int width = 0;
  int height = 0;

  bool empty() const { return width == 0 || height == 0; }
  bool contains(int i, int j) const { return i >= col0 && j >= row0 && i < col0 + width && j < row0 + height; }
  friend bool operator==(const CellWindow&, const CellWindow&) = default;
};

class RegionFreespace {
 public:
  // Throws ConfigError for a non-positive or non-finite cell size or extent, a negative
  // noReturnFreeRangeM or freePerHit, or more than 10000 cells per side.
  explicit RegionFreespace(const FreespaceConfig& config = {});

  // Adds `scan` taken with the sensor at `sensorPose` (its aligned pose in the region frame);
  // `gateways` are the region's gateway lines in the region frame. Beams are cut where the grid
  // cannot grow further (maxExtentM); a scan whose sensor lies beyond that adds nothing (false).
  // Throws InvalidArgumentError (and changes nothing) for invalid input (see regionBeams).
  bool addScan(const LaserScan& scan, const Pose2D& sensorPose, std::span<const GatewaySegment> gateways);
  // The same for beams already clipped to the region (regionBeams with config().noReturnFreeRangeM).
  bool addBeams(const RegionBeams& beams);

  // Adds the evidence of `other` (another region, or an earlier visit of this one) whose frame
  // has the pose `otherInThis` in this region's frame: every cell of this grid that the other
  // grid covers gets the counts of the other's cell under its centre. With the identity pose and
  // the same cell size this is exactly the evidence of all scans of both; where both together
  // outgrow maxExtentM, this grid keeps its cells and takes what fits of the other's. Throws
  // InvalidArgumentError for a non-finite pose or for other == *this.
  void mergeFrom(const RegionFreespace& other, const Pose2D& otherInThis);

  const FreespaceConfig& config() const { return config_; }
  double cellSizeM() const { return config_.cellSizeM; }
  const CellWindow& window() const { return window_; }
  // State of lattice cell (i, j); Unknown outside the window.
  FreespaceCell cell(int i, int j) const;
  // The lattice cell containing `point` (region frame, finite).
  LatticeCell cellOf(const Eigen::Vector2d& point) const;
  Eigen::Vector2d cellCenter(int i, int j) const;
  std::size_t scanCount() const { return scans_; }

  // The free cells as a 1-bit map cropped to their bounding box (empty if there is none).
  FreespaceBitmap bitmap() const;

 private:
  struct Counts {
    std::uint32_t free = 0;
    std::uint32_t hit = 0;
  };

  FreespaceCell state(const Counts& c) const;
  // Grows the window to cover the lattice box [lo, hi] (cell units, doubles so that far-off
  // input is rejected before any conversion; InvalidArgumentError before changing anything).
  // Where the box does not fit into maxExtentM, the window grows as far as it can towards it
  // while it keeps its cells and the box [keepLo, keepHi]; false (and nothing changes) if even
  // those do not fit.
  bool ensureCovers(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Eigen::Vector2d& keepLo,
                    const Eigen::Vector2d& keepHi);
  Counts& at(int i, int j) {
    return counts_[std::size_t(j - window_.row0) * std::size_t(window_.width) + std::size_t(i - window_.col0)];
  }
  const Counts& at(int i, int j) const {
    return counts_[std::size_t(j - window_.row0) * std::size_t(window_.width) + std::size_t(i - window_.col0)];
  }

  FreespaceConfig config_;
  int maxCells_ = 0;
  CellWindow window_;
  std::vector<Counts> counts_;  // row-major over the window
  std::size_t scans_ = 0;
};

}  // namespace rgnav
