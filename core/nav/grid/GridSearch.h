// GridSearch: A* (Hart, Nilsson, Raphael, "A Formal Basis for the Heuristic Determination of
// Minimum Cost Paths", 1968) over the 8-connected cells of a ClearanceMap whose clearance is at
// least a minimum, to the cheapest of one or more goal cells. The cost of a move is its length
// times (1 + weight * p^2), p = how far the clearance of the cell entered falls short of the
// comfort clearance, as a fraction of (comfort - minimum): paths keep away from walls where the
// room allows it (the "inflation cost" of costmap-based planners). The heuristic, the Euclidean
// distance to the nearest goal, is admissible because every move costs at least its length.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/nav/grid/ClearanceMap.h"

namespace rgnav {

struct ClearanceCost {
  double minimum = 0.0;  // m: cells with less clearance are not entered
  double comfort = 0.0;  // m: cells with at least this much clearance cost nothing extra
  double weight = 0.0;   // extra cost factor at the minimum clearance
};

struct GridPath {
  std::vector<CellIndex> cells;  // start first, goal last
  std::size_t goal = 0;          // index into the goals the search was given
};

class GridSearch {
 public:
  // Keeps a reference to `map`, which must outlive the search.
  GridSearch(const ClearanceMap& map, const ClearanceCost& cost);
  GridSearch(ClearanceMap&&, const ClearanceCost&) = delete;

  bool traversable(CellIndex c) const;
  // The cheapest path from `start` to any of `goals` (all traversable cells), or nullopt if none
  // is connected to `start`.
  std::optional<GridPath> search(CellIndex start, std::span<const CellIndex> goals) const;
  // For every cell: whether it is traversable and 8-connected to `start` through traversable
  // cells (row-major, like the grid).
  std::vector<bool> connected(CellIndex start) const;

 private:
  double costFactor(CellIndex c) const;
  std::size_t indexOf(CellIndex c) const;
  CellIndex cellAt(std::size_t i) const;

  const ClearanceMap* map_;
  ClearanceCost cost_;
};

}  // namespace rgnav
