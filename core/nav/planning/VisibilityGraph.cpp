// VisibilityGraph: A* over the lazily built tangent visibility graph of convex corners (see the
// header).
#include "core/nav/planning/VisibilityGraph.h"

#include <algorithm>
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
  explicit Impl(const OccupancyGrid& g) : grid(g), corners(g) {
    const std::size_t n = static_cast<std::size_t>(corners.cornerCount());
    neighbours.resize(n);
    expanded.assign(n, false);
    g_.resize(n + 2);
    parent.resize(n + 2);
    reached.assign(n + 2, 0);
    closed.assign(n + 2, 0);
    seesGoal.assign(n, 0);
  }

  const std::vector<int>& neighboursOf(int id) {
    auto& list = neighbours[static_cast<std::size_t>(id)];
    if (!expanded[static_cast<std::size_t>(id)]) {
      corners.seenTangentCorners(corners.vertex(id).cast<double>(), id, list);
      list.shrink_to_fit();
      expanded[static_cast<std::size_t>(id)] = true;
    }
    return list;
  }

  const OccupancyGrid& grid;
  TangentVisibility corners;
  // The tangent visibility graph, filled in as the searches expand corners.
  std::vector<std::vector<int>> neighbours;
  std::vector<bool> expanded;
  // Per-query search state, valid where reached / closed equal the query's stamp.
  std::vector<double> g_;
  std::vector<int> parent;
  std::vector<std::uint32_t> reached, closed, seesGoal;
  std::uint32_t query = 0;
  std::vector<int> scratch;
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
    for (auto* v : {&s.reached, &s.closed, &s.seesGoal}) std::fill(v->begin(), v->end(), 0);
    s.query = 1;
  }
  const int n = s.corners.cornerCount(), start = n, goal = n + 1;
  s.corners.seenTangentCorners(b, -1, s.scratch);
  for (int id : s.scratch) s.seesGoal[static_cast<std::size_t>(id)] = s.query;
  const auto point = [&](int node) {
    return node == start ? a : node == goal ? b : Eigen::Vector2d(s.corners.vertex(node).cast<double>());
  };

  using Entry = std::pair<double, int>;  // (f, node)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto relax = [&](int node, double g, int from) {
    const auto i = static_cast<std::size_t>(node);
    if (s.closed[i] == s.query || (s.reached[i] == s.query && s.g_[i] <= g)) return;
    s.reached[i] = s.query;
    s.g_[i] = g;
    s.parent[i] = from;
    open.emplace(g + (point(node) - b).norm(), node);
  };
  relax(start, 0.0, -1);
  if (!s.scratch.empty()) s.corners.seenTangentCorners(a, -1, s.scratch);
  while (!open.empty()) {
    const int node = open.top().second;
    open.pop();
    const auto i = static_cast<std::size_t>(node);
    if (s.closed[i] == s.query) continue;
    s.closed[i] = s.query;
    if (node == goal) {
      EuclideanPath path;
      path.length = s.g_[i];
      for (int k = goal; k >= 0; k = s.parent[static_cast<std::size_t>(k)]) path.points.push_back(point(k));
      std::reverse(path.points.begin(), path.points.end());
      return path;
    }
    const Eigen::Vector2d here = point(node);
    const double g = s.g_[i];
    if (node == start) {
      for (int next : s.scratch) relax(next, g + (point(next) - here).norm(), node);
      continue;
    }
    const Eigen::Vector2d in = point(s.parent[i]) - here;
    const Eigen::Vector2d wrap = s.corners.wrap(node).cast<double>();
    for (int next : s.neighboursOf(node)) {
      const Eigen::Vector2d out = point(next) - here;
      if (taut(in, out, wrap)) relax(next, g + out.norm(), node);
    }
    if (s.seesGoal[i] == s.query) relax(goal, g + (b - here).norm(), node);
  }
  throw NoPathError("VisibilityGraph: no path from " + pointText(a) + " to " + pointText(b));
}

}  // namespace rgnav
