// VisibilityGraph: A* over the lazily built tangent visibility graph of convex corners (see the
// header).
#include "core/nav/planning/VisibilityGraph.h"

#include <algorithm>
#include <cstdint>
#include <queue>
#include <string>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/SegmentVisibility.h"
#include "core/nav/planning/TangentVisibility.h"

namespace rgnav {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether a path arriving at a corner from `in` (relative to the corner) and leaving towards
// `out` wraps around its obstacle (diagonal `wrap`): otherwise it can be shortened by cutting
// the corner, and no shortest path turns there (Oh & Leong's taut-path rule). Collinear paths
// pass.
bool taut(const Eigen::Vector2d& in, const Eigen::Vector2d& out, const Eigen::Vector2d& wrap) {
  const double turn = cross(in, out);
  if (turn == 0.0) return true;
  return cross(in, wrap) * turn >= 0.0 && cross(wrap, out) * turn >= 0.0;
}

std::string pointText(const Eigen::Vector2d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
}

}  // namespace

struct VisibilityGraph::Impl {
  // A cached edge of the tangent visibility graph: the corner it leads to, the offset to it
  // (taut tests without looking the corner up) and its length.
  struct Edge {
    int to;
    int dx, dy;
    double length;
  };
  // Per-query search state of a node (corners, then start, then goal), valid where `reached` /
  // `closed` equal the query's stamp; one record per node keeps a relaxation to one cache line.
  struct Node {
    double g;
    int parent;
    std::uint32_t reached, closed, seesGoal;
  };

  explicit Impl(const OccupancyGrid& g) : grid(g), corners(g) {
    const std::size_t n = static_cast<std::size_t>(corners.cornerCount());
    neighbours.resize(n);
    expanded.assign(n, false);
    nodes.assign(n + 2, Node{0.0, -1, 0, 0, 0});
  }

  const std::vector<Edge>& neighboursOf(int id) {
    auto& list = neighbours[static_cast<std::size_t>(id)];
    if (!expanded[static_cast<std::size_t>(id)]) {
      const Eigen::Vector2i here = corners.vertex(id);
      corners.seenTangentCorners(here.cast<double>(), id, scratch);
      list.reserve(scratch.size());
      for (int to : scratch) {
        const Eigen::Vector2i d = corners.vertex(to) - here;
        list.push_back({to, d.x(), d.y(), d.cast<double>().norm()});
      }
      expanded[static_cast<std::size_t>(id)] = true;
    }
    return list;
  }

  const OccupancyGrid& grid;
  TangentVisibility corners;
  // The tangent visibility graph, filled in as the searches expand corners.
  std::vector<std::vector<Edge>> neighbours;
  std::vector<bool> expanded;
  std::vector<Node> nodes;
  std::uint32_t query = 0;
  std::vector<int> scratch, startEdges;
};

VisibilityGraph::VisibilityGraph(const OccupancyGrid& grid) : impl_(std::make_unique<Impl>(grid)) {}

VisibilityGraph::~VisibilityGraph() = default;

std::size_t VisibilityGraph::vertexCount() const { return static_cast<std::size_t>(impl_->corners.cornerCount()); }

EuclideanPath VisibilityGraph::shortestPath(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  Impl& s = *impl_;
  if (!segmentFree(s.grid, a, a)) throw StartBlockedError("VisibilityGraph: start " + pointText(a) + " is not in a free cell");
  if (!segmentFree(s.grid, b, b)) throw GoalBlockedError("VisibilityGraph: goal " + pointText(b) + " is not in a free cell");
  if (segmentFree(s.grid, a, b)) return {{a, b}, (b - a).norm()};

  if (++s.query == 0) {
    for (auto& node : s.nodes) node.reached = node.closed = node.seesGoal = 0;
    s.query = 1;
  }
  const int n = s.corners.cornerCount(), start = n, goal = n + 1;
  s.corners.seenTangentCorners(b, -1, s.scratch);
  for (int id : s.scratch) s.nodes[static_cast<std::size_t>(id)].seesGoal = s.query;
  if (!s.scratch.empty()) s.corners.seenTangentCorners(a, -1, s.startEdges);
  const auto point = [&](int node) {
    return node == start ? a : node == goal ? b : Eigen::Vector2d(s.corners.vertex(node).cast<double>());
  };

  using Entry = std::pair<double, int>;  // (f, node)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto relax = [&](int node, const Eigen::Vector2d& at, double g, int from) {
    Impl::Node& state = s.nodes[static_cast<std::size_t>(node)];
    if (state.closed == s.query || (state.reached == s.query && state.g <= g)) return;
    state.reached = s.query;
    state.g = g;
    state.parent = from;
    open.emplace(g + (at - b).norm(), node);
  };
  relax(start, a, 0.0, -1);
  while (!open.empty()) {
    const int node = open.top().second;
    open.pop();
    Impl::Node& state = s.nodes[static_cast<std::size_t>(node)];
    if (state.closed == s.query) continue;
    state.closed = s.query;
    if (node == goal) {
      EuclideanPath path;
      path.length = state.g;
      for (int k = goal; k >= 0; k = s.nodes[static_cast<std::size_t>(k)].parent) path.points.push_back(point(k));
      std::reverse(path.points.begin(), path.points.end());
      return path;
    }
    const Eigen::Vector2d here = point(node);
    const double g = state.g;
    if (node == start) {
      for (int next : s.startEdges) relax(next, point(next), g + (point(next) - here).norm(), node);
      continue;
    }
    const Eigen::Vector2d in = point(state.parent) - here;
    const Eigen::Vector2d wrap = s.corners.wrap(node).cast<double>();
    const bool seesGoal = state.seesGoal == s.query;
    for (const Impl::Edge& edge : s.neighboursOf(node)) {
      const Eigen::Vector2d out(edge.dx, edge.dy);
      if (taut(in, out, wrap)) relax(edge.to, here + out, g + edge.length, node);
    }
    if (seesGoal) relax(goal, b, g + (b - here).norm(), node);
  }
  throw NoPathError("VisibilityGraph: no path from " + pointText(a) + " to " + pointText(b));
}

}  // namespace rgnav
