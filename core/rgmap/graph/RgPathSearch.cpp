// A* search on the RG Graph (thesis 5.4); see RgPathSearch.h.
#include "core/rgmap/graph/RgPathSearch.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

void checkPlace(const RgGraph& graph, const RgPlace& place, const char* name) {
  if (!graph.hasRegion(place.region))
    throw InvalidArgumentError(std::string(name) + " region " + std::to_string(place.region.value()) +
                               " is not in the RG graph");
  if (!place.position.allFinite()) throw InvalidArgumentError(std::string(name) + " position is not finite");
}

// The search over the graph's nodes 0..n-1 plus the temporary start (n) and goal (n + 1).
class AStar {
 public:
  AStar(const RgGraph& graph, const RgPlace& start, const RgPlace& goal)
      : graph_(graph), start_(start), goal_(goal), startIndex_(graph.nodes().size()), goalIndex_(startIndex_ + 1),
        cost_(goalIndex_ + 1, std::numeric_limits<double>::infinity()), parent_(goalIndex_ + 1, kNone),
        parentEdge_(goalIndex_ + 1, kNone), closed_(goalIndex_ + 1, false) {}

  RgPath run() {
    cost_[startIndex_] = 0.0;
    open_.push({heuristic(startIndex_), startIndex_});
    while (!open_.empty()) {
      const std::size_t u = open_.top().second;
      open_.pop();
      if (closed_[u]) continue;
      closed_[u] = true;
      if (u == goalIndex_) return path();
      expand(u);
    }
    throw NotAvailableError("no path in the RG graph from region " + std::to_string(start_.region.value()) + " to region " +
                            std::to_string(goal_.region.value()));
  }

 private:
  const Eigen::Vector2d& position(std::size_t i) const {
    if (i == startIndex_) return start_.position;
    if (i == goalIndex_) return goal_.position;
    return graph_.nodes()[i].position;
  }

  double distance(std::size_t u, std::size_t v) const { return (position(u) - position(v)).norm(); }
  double heuristic(std::size_t i) const { return distance(i, goalIndex_); }

  void expand(std::size_t u) {
    if (u == startIndex_) {
      for (const std::size_t v : graph_.nodesInRegion(start_.region)) relax(u, v, distance(u, v), kNone);
      if (start_.region == goal_.region) relax(u, goalIndex_, distance(u, goalIndex_), kNone);
      return;
    }
    for (const std::size_t e : graph_.edgesAt(u)) {
      const RgEdge& edge = graph_.edges()[e];
      relax(u, edge.from == u ? edge.to : edge.from, edge.costM, e);
    }
    if (graph_.nodes()[u].region == goal_.region) relax(u, goalIndex_, distance(u, goalIndex_), kNone);
  }

  void relax(std::size_t u, std::size_t v, double edgeCost, std::size_t edge) {
    if (closed_[v]) return;
    const double c = cost_[u] + edgeCost;
    if (c >= cost_[v]) return;
    cost_[v] = c;
    parent_[v] = u;
    parentEdge_[v] = edge;
    open_.push({c + heuristic(v), v});
  }

  RgPath path() const {
    RgPath out;
    out.costM = cost_[goalIndex_];
    std::vector<std::size_t> edges;
    for (std::size_t v = goalIndex_; v != startIndex_; v = parent_[v]) {
      if (parentEdge_[v] == kNone) out.lengthM += distance(v, parent_[v]);
      else edges.push_back(parentEdge_[v]);
      if (v != goalIndex_) out.crossings.push_back(graph_.nodes()[v]);
    }
    std::reverse(out.crossings.begin(), out.crossings.end());
    std::reverse(edges.begin(), edges.end());
    for (const std::size_t e : edges) {
      out.edges.push_back(graph_.edges()[e].key);
      out.lengthM += graph_.edges()[e].lengthM;
    }
    return out;
  }

  using Entry = std::pair<double, std::size_t>;  // f = cost + heuristic, node

  const RgGraph& graph_;
  const RgPlace& start_;
  const RgPlace& goal_;
  const std::size_t startIndex_;
  const std::size_t goalIndex_;
  std::vector<double> cost_;
  std::vector<std::size_t> parent_;
  std::vector<std::size_t> parentEdge_;  // graph edge into the node, kNone for a start or goal link
  std::vector<bool> closed_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open_;
};

}  // namespace

RgPath findPath(const RgGraph& graph, const RgPlace& start, const RgPlace& goal) {
  checkPlace(graph, start, "start");
  checkPlace(graph, goal, "goal");
  return AStar(graph, start, goal).run();
}

}  // namespace rgnav
