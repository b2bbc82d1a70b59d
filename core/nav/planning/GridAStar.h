// GridAStar: 8-connected A* over the cells of an OccupancyGrid with the octile heuristic and the
// MovingAI rule (a diagonal step needs both cardinal cells beside it free; Sturtevant,
// "Benchmarks for Grid-Based Pathfinding", 2012): the uniform-grid baseline of issue 26 that the
// framed-quadtree planner is timed against. Flat per-cell arrays reused across searches (a search
// stamp instead of clearing), a binary heap with lazy deletion, ties broken towards larger g.
// plan() calls on one instance are serialised by a mutex (the search state is shared).
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct GridPath {
  std::vector<CellIndex> cells;  // start first, goal last
  double length = 0.0;           // octile length, cells
  std::size_t expansions = 0;
};

class GridAStar {
 public:
  // `grid` must outlive the planner.
  explicit GridAStar(const OccupancyGrid& grid);
  // Throws StartBlockedError / GoalBlockedError (cell not free) and NoPathError (not connected).
  GridPath plan(CellIndex start, CellIndex goal) const;

 private:
  struct CellState {
    double g = 0.0;
    std::int32_t parent = -1;
    std::uint32_t seen = 0;    // search stamp: g and parent are valid
    std::uint32_t closed = 0;  // search stamp: expanded
  };
  struct Open {
    double f;
    double g;
    std::int32_t cell;
  };

  const OccupancyGrid& grid_;
  mutable std::mutex mutex_;
  mutable std::vector<CellState> state_;
  mutable std::vector<Open> heap_;
  mutable std::uint32_t search_ = 0;
};

}  // namespace rgnav
