// ExplorationGrid: what exploration knows of the world, taken from an RG map (PlanningMap.h) on
// one map-frame grid: a cell is Free if it lies in some region's freespace (the regions' 15 cm
// freespace bitmaps placed by their region frames), Wall if it lies within wallClearanceM of a line
// of some region's line map (also where a freespace holds it), Unknown otherwise. Each free cell keeps the region whose freespace
// holds it (the one with the lowest ID where regions overlap). Built anew for each map revision.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/nav/exploration/ExplorationConfig.h"
#include "core/nav/planning/PlanningMap.h"

namespace rgnav {

enum class ExplorationCell : std::uint8_t { Unknown, Free, Wall };

class ExplorationGrid {
 public:
  ExplorationGrid() = default;
  // Throws ConfigError for a bad configuration. An empty map gives an empty grid.
  static ExplorationGrid fromMap(const PlanningMap& map, const ExplorationGridConfig& config);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolutionM() const { return resolutionM_; }
  const Eigen::Vector2d& originM() const { return originM_; }  // lower-left corner of cell (0, 0)

  ExplorationCell at(int col, int row) const;  // Unknown outside the grid
  RegionId regionAt(int col, int row) const;   // none unless Free
  // From the cell's centre to the nearest cell a line of the map passes through (OpenCV's exact
  // Euclidean distance transform of the rendered lines): within one cell's half diagonal of the
  // distance to the line itself. Infinite where the map has no line; 0 outside the grid.
  double wallDistanceM(int col, int row) const;
  Eigen::Vector2d cellCenter(int col, int row) const;
  // The cell holding `point`; false if it lies outside the grid.
  bool cellOf(const Eigen::Vector2d& point, int& col, int& row) const;
  std::size_t freeCount() const;

 private:
  double resolutionM_ = 0.1;
  Eigen::Vector2d originM_ = Eigen::Vector2d::Zero();
  int width_ = 0, height_ = 0;
  std::vector<ExplorationCell> cells_;  // row-major, row 0 at the bottom
  std::vector<RegionId> regions_;
  std::vector<float> wallDistanceM_;  // row-major, metres
};

}  // namespace rgnav
