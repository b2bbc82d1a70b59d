// GridSearch: binary-heap A* with lazy deletion, and a breadth-first flood fill for connectivity.
#include "core/nav/grid/GridSearch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

namespace rgnav {

namespace {

struct Move {
  int dc;
  int dr;
  double length;  // in cells
};
constexpr std::array<Move, 8> kMoves = {{{1, 0, 1.0},
                                         {-1, 0, 1.0},
                                         {0, 1, 1.0},
                                         {0, -1, 1.0},
                                         {1, 1, M_SQRT2},
                                         {1, -1, M_SQRT2},
                                         {-1, 1, M_SQRT2},
                                         {-1, -1, M_SQRT2}}};

struct Open {
  double f;  // cost so far + heuristic
  double g;  // cost so far when pushed
  std::size_t index;
  bool operator>(const Open& o) const { return f > o.f || (f == o.f && index > o.index); }
};

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

}  // namespace

GridSearch::GridSearch(const ClearanceMap& map, const ClearanceCost& cost) : map_(&map), cost_(cost) {}

std::size_t GridSearch::indexOf(CellIndex c) const { return rowMajor(c, map_->grid().width()); }

CellIndex GridSearch::cellAt(std::size_t i) const {
  const auto width = static_cast<std::size_t>(map_->grid().width());
  return {static_cast<int>(i % width), static_cast<int>(i / width)};
}

bool GridSearch::traversable(CellIndex c) const {
  return map_->grid().contains(c) && map_->at(c) >= cost_.minimum;
}

double GridSearch::costFactor(CellIndex c) const {
  const double span = cost_.comfort - cost_.minimum;
  if (span <= 0.0) {
    return 1.0;
  }
  const double p = std::clamp((cost_.comfort - map_->at(c)) / span, 0.0, 1.0);
  return 1.0 + cost_.weight * p * p;
}

std::optional<GridPath> GridSearch::search(CellIndex start, std::span<const CellIndex> goals) const {
  const std::size_t cells = map_->grid().cells().size();
  std::vector<std::size_t> goalOf(cells, kNone);
  std::vector<CellIndex> targets;  // the traversable goals, for the heuristic
  for (std::size_t g = 0; g < goals.size(); ++g) {
    if (traversable(goals[g]) && goalOf[indexOf(goals[g])] == kNone) {
      goalOf[indexOf(goals[g])] = g;
      targets.push_back(goals[g]);
    }
  }
  if (!traversable(start) || targets.empty()) {
    return std::nullopt;
  }
  const auto heuristic = [&targets](CellIndex c) {
    double best = std::numeric_limits<double>::infinity();
    for (const CellIndex& t : targets) {
      best = std::min(best, std::hypot(double(t.col - c.col), double(t.row - c.row)));
    }
    return best;
  };
  std::vector<double> cost(cells, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> parent(cells, kNone);
  std::priority_queue<Open, std::vector<Open>, std::greater<>> open;
  cost[indexOf(start)] = 0.0;
  open.push({heuristic(start), 0.0, indexOf(start)});
  while (!open.empty()) {
    const Open top = open.top();
    open.pop();
    if (top.g > cost[top.index]) {
      continue;  // stale entry, the cell was reached more cheaply since
    }
    const CellIndex c = cellAt(top.index);
    if (goalOf[top.index] != kNone) {
      GridPath path;
      path.goal = goalOf[top.index];
      for (std::size_t i = top.index; i != kNone; i = parent[i]) {
        path.cells.push_back(cellAt(i));
      }
      std::reverse(path.cells.begin(), path.cells.end());
      return path;
    }
    for (const Move& m : kMoves) {
      const CellIndex n{c.col + m.dc, c.row + m.dr};
      if (!traversable(n)) {
        continue;
      }
      const double g = cost[top.index] + m.length * costFactor(n);
      const std::size_t ni = indexOf(n);
      if (g < cost[ni]) {
        cost[ni] = g;
        parent[ni] = top.index;
        open.push({g + heuristic(n), g, ni});
      }
    }
  }
  return std::nullopt;
}

std::vector<bool> GridSearch::connected(CellIndex start) const {
  std::vector<bool> reached(map_->grid().cells().size(), false);
  if (!traversable(start)) {
    return reached;
  }
  std::queue<CellIndex> frontier;
  reached[indexOf(start)] = true;
  frontier.push(start);
  while (!frontier.empty()) {
    const CellIndex c = frontier.front();
    frontier.pop();
    for (const Move& m : kMoves) {
      const CellIndex n{c.col + m.dc, c.row + m.dr};
      if (traversable(n) && !reached[indexOf(n)]) {
        reached[indexOf(n)] = true;
        frontier.push(n);
      }
    }
  }
  return reached;
}

}  // namespace rgnav
