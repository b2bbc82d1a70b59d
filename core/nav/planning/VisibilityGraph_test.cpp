// Tests the exact Euclidean shortest path: on random small grids its paths are free under
// segmentFree, as long as a brute-force optimum (Dijkstra over every grid vertex that is no
// diagonal squeeze, plus the two points, joined wherever segmentFree holds: the optimum bends only
// at grid vertices) to 1e-9, and never longer than the octile optimum; errors are typed.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/testing/RandomGrids.h"
#include "core/nav/planning/SegmentVisibility.h"
#include "core/nav/planning/VisibilityGraph.h"

using Eigen::Vector2d;
using rgnav::Cell;
using rgnav::OccupancyGrid;
using rgnav::segmentFree;
using rgnav::VisibilityGraph;
using rgnav::testing::randomGrid;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Dense Dijkstra over the grid vertices a path may bend at (all but diagonal squeezes) and the
// two points; infinity when they are not connected.
class BruteForce {
 public:
  explicit BruteForce(const OccupancyGrid& grid) : grid_(grid) {
    for (int y = 0; y <= grid.height(); ++y)
      for (int x = 0; x <= grid.width(); ++x) {
        const bool sw = grid.blocked({x - 1, y - 1}), se = grid.blocked({x, y - 1});
        const bool nw = grid.blocked({x - 1, y}), ne = grid.blocked({x, y});
        if (!(sw && ne) && !(se && nw)) vertices_.emplace_back(x, y);
      }
    const std::size_t n = vertices_.size();
    free_.assign(n * n, false);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        free_[i * n + j] = free_[j * n + i] = segmentFree(grid, vertices_[i], vertices_[j]);
  }

  double shortest(const Vector2d& a, const Vector2d& b) const {
    const std::size_t n = vertices_.size(), start = n, goal = n + 1;
    const auto at = [&](std::size_t i) { return i == start ? a : i == goal ? b : vertices_[i]; };
    const auto linked = [&](std::size_t i, std::size_t j) {
      return i < n && j < n ? free_[i * n + j] : segmentFree(grid_, at(i), at(j));
    };
    std::vector<double> dist(n + 2, kInf);
    std::vector<bool> done(n + 2, false);
    dist[start] = 0.0;
    for (;;) {
      std::size_t u = n + 2;
      for (std::size_t i = 0; i < n + 2; ++i)
        if (!done[i] && dist[i] < kInf && (u == n + 2 || dist[i] < dist[u])) u = i;
      if (u == n + 2 || u == goal) return dist[goal];
      done[u] = true;
      for (std::size_t v = 0; v < n + 2; ++v)
        if (!done[v] && linked(u, v)) dist[v] = std::min(dist[v], dist[u] + (at(u) - at(v)).norm());
    }
  }

 private:
  const OccupancyGrid& grid_;
  std::vector<Vector2d> vertices_;
  std::vector<bool> free_;
};

// The MovingAI octile optimum between two cell centres: 8-connected, a diagonal step needs both
// cardinal cells beside it free.
double octile(const OccupancyGrid& grid, int c0, int r0, int c1, int r1) {
  const int w = grid.width(), h = grid.height();
  std::vector<double> dist(static_cast<std::size_t>(w * h), kInf);
  std::vector<bool> done(dist.size(), false);
  dist[static_cast<std::size_t>(r0 * w + c0)] = 0.0;
  for (;;) {
    int u = -1;
    for (int i = 0; i < w * h; ++i)
      if (!done[static_cast<std::size_t>(i)] && dist[static_cast<std::size_t>(i)] < kInf &&
          (u < 0 || dist[static_cast<std::size_t>(i)] < dist[static_cast<std::size_t>(u)]))
        u = i;
    if (u < 0) return kInf;
    if (u == r1 * w + c1) return dist[static_cast<std::size_t>(u)];
    done[static_cast<std::size_t>(u)] = true;
    const int c = u % w, r = u / w;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        if ((dr == 0 && dc == 0) || grid.blocked({c + dc, r + dr})) continue;
        if (dr != 0 && dc != 0 && (grid.blocked({c + dc, r}) || grid.blocked({c, r + dr}))) continue;
        const auto v = static_cast<std::size_t>((r + dr) * w + c + dc);
        dist[v] = std::min(dist[v], dist[static_cast<std::size_t>(u)] + ((dr != 0 && dc != 0) ? std::sqrt(2.0) : 1.0));
      }
  }
}

void assertFreeAndMeasured(const OccupancyGrid& grid, const rgnav::EuclideanPath& path, const Vector2d& a,
                           const Vector2d& b) {
  CPPUNIT_ASSERT(path.points.size() >= 2);
  CPPUNIT_ASSERT(path.points.front() == a);
  CPPUNIT_ASSERT(path.points.back() == b);
  double length = 0.0;
  for (std::size_t i = 1; i < path.points.size(); ++i) {
    CPPUNIT_ASSERT(segmentFree(grid, path.points[i - 1], path.points[i]));
    length += (path.points[i] - path.points[i - 1]).norm();
  }
  CPPUNIT_ASSERT_DOUBLES_EQUAL(length, path.length, 1e-9);
}

}  // namespace

class VisibilityGraphTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(VisibilityGraphTest);
  CPPUNIT_TEST(bendsAroundASingleObstacle);
  CPPUNIT_TEST(doesNotSqueezeBetweenDiagonalObstacles);
  CPPUNIT_TEST(equalsTheBruteForceOptimumOnRandomGrids);
  CPPUNIT_TEST(isNeverLongerThanTheOctileOptimum);
  CPPUNIT_TEST(failuresAreTyped);
  CPPUNIT_TEST_SUITE_END();

 public:
  void bendsAroundASingleObstacle() {
    OccupancyGrid grid(3, 3, 1.0);
    grid.set({1, 1}, Cell::Occupied);
    const VisibilityGraph graph(grid);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, graph.vertexCount());
    const auto path = graph.shortestPath({0.5, 1.5}, {2.5, 1.5});
    assertFreeAndMeasured(grid, path, {0.5, 1.5}, {2.5, 1.5});
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, path.points.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 + std::sqrt(2.0), path.length, 1e-12);
  }

  void doesNotSqueezeBetweenDiagonalObstacles() {
    // Blocked cells (1,1) and (2,2) meet at vertex (2,2): the straight diagonal and any bend at
    // that vertex are closed; the path goes around one of the two cells.
    OccupancyGrid grid(4, 4, 1.0);
    grid.set({1, 1}, Cell::Occupied);
    grid.set({2, 2}, Cell::Occupied);
    const VisibilityGraph graph(grid);
    const Vector2d a(1.5, 2.5), b(2.5, 1.5);
    const auto path = graph.shortestPath(a, b);
    assertFreeAndMeasured(grid, path, a, b);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(BruteForce(grid).shortest(a, b), path.length, 1e-9);
    CPPUNIT_ASSERT(path.length > std::sqrt(2.0) + 0.5);
  }

  void equalsTheBruteForceOptimumOnRandomGrids() {
    std::mt19937 rng(26);
    std::uniform_real_distribution<double> share(0.1, 0.3);
    int compared = 0, unconnected = 0;
    for (int trial = 0; trial < 40; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 16, share(rng));
      const VisibilityGraph graph(grid);
      const BruteForce brute(grid);
      std::uniform_int_distribution<int> cell(0, 15), half(0, 32);
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      for (int query = 0; query < 25; ++query) {
        // Cell centres, half-lattice points (vertices, edge midpoints) and arbitrary points.
        const auto pick = [&]() -> Vector2d {
          for (;;) {
            Vector2d p;
            switch (query % 3) {
              case 0: p = Vector2d(cell(rng) + 0.5, cell(rng) + 0.5); break;
              case 1: p = Vector2d(half(rng) * 0.5, half(rng) * 0.5); break;
              default: p = Vector2d(cell(rng) + unit(rng), cell(rng) + unit(rng)); break;
            }
            if (segmentFree(grid, p, p)) return p;
          }
        };
        const Vector2d a = pick(), b = pick();
        const double expected = brute.shortest(a, b);
        if (expected == kInf) {
          CPPUNIT_ASSERT_THROW(graph.shortestPath(a, b), rgnav::NoPathError);
          ++unconnected;
          continue;
        }
        const auto path = graph.shortestPath(a, b);
        assertFreeAndMeasured(grid, path, a, b);
        CPPUNIT_ASSERT_DOUBLES_EQUAL(expected, path.length, 1e-9);
        ++compared;
      }
    }
    CPPUNIT_ASSERT(compared > 600);
    CPPUNIT_ASSERT(unconnected > 0);
  }

  void isNeverLongerThanTheOctileOptimum() {
    std::mt19937 rng(5);
    int compared = 0;
    for (int trial = 0; trial < 30; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 16, 0.25);
      const VisibilityGraph graph(grid);
      std::uniform_int_distribution<int> cell(0, 15);
      for (int query = 0; query < 20; ++query) {
        const int c0 = cell(rng), r0 = cell(rng), c1 = cell(rng), r1 = cell(rng);
        if (grid.blocked({c0, r0}) || grid.blocked({c1, r1})) continue;
        const double bound = octile(grid, c0, r0, c1, r1);
        if (bound == kInf) continue;
        const auto path = graph.shortestPath({c0 + 0.5, r0 + 0.5}, {c1 + 0.5, r1 + 0.5});
        CPPUNIT_ASSERT(path.length <= bound + 1e-9);
        ++compared;
      }
    }
    CPPUNIT_ASSERT(compared > 200);
  }

  void failuresAreTyped() {
    OccupancyGrid grid(5, 5, 1.0);
    for (int r = 0; r < 5; ++r) grid.set({2, r}, Cell::Occupied);
    const VisibilityGraph graph(grid);
    CPPUNIT_ASSERT_THROW(graph.shortestPath({2.5, 2.5}, {0.5, 0.5}), rgnav::StartBlockedError);
    CPPUNIT_ASSERT_THROW(graph.shortestPath({-0.5, 2.5}, {0.5, 0.5}), rgnav::StartBlockedError);
    CPPUNIT_ASSERT_THROW(graph.shortestPath({0.5, 0.5}, {2.5, 4.5}), rgnav::GoalBlockedError);
    CPPUNIT_ASSERT_THROW(graph.shortestPath({0.5, 0.5}, {4.5, 4.5}), rgnav::NoPathError);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, graph.shortestPath({0.5, 0.5}, {0.5, 4.5}).length, 1e-12);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(VisibilityGraphTest);
