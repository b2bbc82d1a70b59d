// Tests the corner scan behind the tangent visibility graph: on larger sparse random grids (long
// sight lines, many interval splits) it returns exactly the corners a brute force over every
// corner accepts (tangent at both ends and segmentFree), from corners and from arbitrary points.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/nav/planning/SegmentVisibility.h"
#include "core/nav/planning/TangentVisibility.h"

using Eigen::Vector2d;
using rgnav::Cell;
using rgnav::OccupancyGrid;
using rgnav::TangentVisibility;

class TangentVisibilityTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TangentVisibilityTest);
  CPPUNIT_TEST(cornersAreVerticesWithOneBlockedCell);
  CPPUNIT_TEST(scanFindsExactlyTheBruteForceCorners);
  CPPUNIT_TEST_SUITE_END();

 public:
  void cornersAreVerticesWithOneBlockedCell() {
    OccupancyGrid grid(4, 3, 1.0);
    grid.set({1, 1}, Cell::Occupied);
    grid.set({2, 1}, Cell::Occupied);
    const TangentVisibility corners(grid);
    CPPUNIT_ASSERT_EQUAL(4, corners.cornerCount());
    for (int id = 0; id < corners.cornerCount(); ++id) {
      const Eigen::Vector2i v = corners.vertex(id), q = corners.wrap(id);
      CPPUNIT_ASSERT(grid.blocked({v.x() + (q.x() - 1) / 2, v.y() + (q.y() - 1) / 2}));
    }
  }

  void scanFindsExactlyTheBruteForceCorners() {
    std::mt19937 rng(3);
    int edges = 0;
    for (int trial = 0; trial < 12; ++trial) {
      OccupancyGrid grid(64, 48, 1.0);
      std::bernoulli_distribution blocked(trial % 2 == 0 ? 0.03 : 0.12);
      for (int r = 0; r < 48; ++r)
        for (int c = 0; c < 64; ++c)
          if (blocked(rng)) grid.set({c, r}, Cell::Occupied);
      const TangentVisibility corners(grid);
      std::uniform_real_distribution<double> x(0.0, 64.0), y(0.0, 48.0);
      std::vector<int> found;
      for (int source = 0; source < 20; ++source) {
        int from = -1;
        Vector2d p;
        if (source % 2 == 0) {
          from = std::uniform_int_distribution<int>(0, corners.cornerCount() - 1)(rng);
          p = corners.vertex(from).cast<double>();
        } else {
          do p = Vector2d(x(rng), y(rng));
          while (!rgnav::segmentFree(grid, p, p));
        }
        corners.seenTangentCorners(p, from, found);
        std::sort(found.begin(), found.end());
        std::vector<int> expected;
        for (int id = 0; id < corners.cornerCount(); ++id) {
          const Vector2d w = corners.vertex(id).cast<double>();
          if (id != from && corners.tangentAt(id, w - p) && (from < 0 || corners.tangentAt(from, w - p)) &&
              rgnav::segmentFree(grid, p, w))
            expected.push_back(id);
        }
        CPPUNIT_ASSERT(expected == found);
        edges += static_cast<int>(expected.size());
      }
    }
    CPPUNIT_ASSERT(edges > 2000);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TangentVisibilityTest);
