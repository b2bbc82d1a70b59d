// GridAStar: the 8-connected octile A* baseline (see the header).
#include "core/nav/planning/GridAStar.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/nav/grid/PlanningErrors.h"

namespace rgnav {

namespace {

constexpr double kSqrt2 = 1.4142135623730951;

double octile(int dx, int dy) {
  dx = std::abs(dx);
  dy = std::abs(dy);
  return dx + dy + (kSqrt2 - 2.0) * std::min(dx, dy);
}

std::string cellName(CellIndex c) { return "(" + std::to_string(c.col) + ", " + std::to_string(c.row) + ")"; }

}  // namespace

GridAStar::GridAStar(const OccupancyGrid& grid) : grid_(grid) {}

GridPath GridAStar::plan(CellIndex start, CellIndex goal) const {
  if (grid_.blocked(start)) throw StartBlockedError("grid A*: start cell " + cellName(start) + " is not free");
  if (grid_.blocked(goal)) throw GoalBlockedError("grid A*: goal cell " + cellName(goal) + " is not free");
  const std::lock_guard lock(mutex_);
  const int width = grid_.width(), height = grid_.height();
  const Cell* cells = grid_.cells().data();
  if (state_.size() != grid_.cells().size()) {
    state_.assign(grid_.cells().size(), CellState{});
    search_ = 0;
  }
  if (++search_ == 0) {  // the stamp wrapped: forget every old search
    std::fill(state_.begin(), state_.end(), CellState{});
    search_ = 1;
  }
  const auto later = [](const Open& a, const Open& b) { return a.f > b.f || (a.f == b.f && a.g < b.g); };
  const auto cellId = [width](int col, int row) { return static_cast<std::int32_t>(row * width + col); };
  const std::int32_t startId = cellId(start.col, start.row), goalId = cellId(goal.col, goal.row);

  heap_.clear();
  state_[startId] = {0.0, -1, search_, 0};
  heap_.push_back({octile(goal.col - start.col, goal.row - start.row), 0.0, startId});
  GridPath path;
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Open top = heap_.back();
    heap_.pop_back();
    CellState& s = state_[top.cell];
    if (s.closed == search_ || top.g > s.g) continue;
    s.closed = search_;
    ++path.expansions;
    if (top.cell == goalId) break;
    const int col = top.cell % width, row = top.cell / width;
    const auto freeAt = [&](int c, int r) {
      return c >= 0 && r >= 0 && c < width && r < height && cells[r * width + c] == Cell::Free;
    };
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const int c = col + dx, r = row + dy;
        if (!freeAt(c, r)) continue;
        if (dx != 0 && dy != 0 && (!freeAt(col + dx, row) || !freeAt(col, row + dy))) continue;
        const std::int32_t n = cellId(c, r);
        CellState& ns = state_[n];
        const double g = top.g + (dx != 0 && dy != 0 ? kSqrt2 : 1.0);
        if (ns.seen == search_ && (ns.closed == search_ || ns.g <= g)) continue;
        ns = {g, top.cell, search_, 0};
        heap_.push_back({g + octile(goal.col - c, goal.row - r), g, n});
        std::push_heap(heap_.begin(), heap_.end(), later);
      }
  }
  if (state_[goalId].closed != search_)
    throw NoPathError("grid A*: no path from " + cellName(start) + " to " + cellName(goal));
  path.length = state_[goalId].g;
  for (std::int32_t c = goalId; c != -1; c = state_[c].parent) path.cells.push_back({c % width, c / width});
  std::reverse(path.cells.begin(), path.cells.end());
  return path;
}

}  // namespace rgnav
