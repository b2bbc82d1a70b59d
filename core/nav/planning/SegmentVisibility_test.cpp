// Tests the shared collision model: a diagonal step between cell centres is free unless both
// cardinal cells beside it are blocked (it may touch one corner), segments along grid lines and through vertices follow the rules
// of the header, and random segments agree with a dense sampling of cell interiors.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <random>

#include "core/nav/planning/testing/RandomGrids.h"
#include "core/nav/planning/SegmentVisibility.h"

using Eigen::Vector2d;
using rgnav::Cell;
using rgnav::CellIndex;
using rgnav::OccupancyGrid;
using rgnav::segmentFree;
using rgnav::testing::randomGrid;

namespace {

Vector2d centre(int c, int r) { return {c + 0.5, r + 0.5}; }

}  // namespace

class SegmentVisibilityTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SegmentVisibilityTest);
  CPPUNIT_TEST(diagonalStepsMayTouchOneCorner);
  CPPUNIT_TEST(gridLinesNeedOneFreeSide);
  CPPUNIT_TEST(cornersMayBeTouchedButNotSqueezedThrough);
  CPPUNIT_TEST(randomSegmentsAgreeWithSampledInteriors);
  CPPUNIT_TEST(outsideTheGridIsBlocked);
  CPPUNIT_TEST_SUITE_END();

 public:
  void diagonalStepsMayTouchOneCorner() {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 12, 0.3);
      for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 12; ++c)
          for (int dr = -1; dr <= 1; ++dr)
            for (int dc = -1; dc <= 1; ++dc) {
              if (dr == 0 && dc == 0) continue;
              bool expected = !grid.blocked({c, r}) && !grid.blocked({c + dc, r + dr});
              if (dr != 0 && dc != 0) expected = expected && !(grid.blocked({c + dc, r}) && grid.blocked({c, r + dr}));
              CPPUNIT_ASSERT_EQUAL(expected, segmentFree(grid, centre(c, r), centre(c + dc, r + dr)));
            }
    }
  }

  void gridLinesNeedOneFreeSide() {
    OccupancyGrid grid(4, 4, 1.0);
    grid.set({1, 1}, Cell::Occupied);
    CPPUNIT_ASSERT(segmentFree(grid, {1.0, 0.0}, {1.0, 3.0}));  // along the blocked cell's left side
    grid.set({0, 1}, Cell::Occupied);
    CPPUNIT_ASSERT(!segmentFree(grid, {1.0, 0.0}, {1.0, 3.0}));  // between two blocked cells
    CPPUNIT_ASSERT(segmentFree(grid, {1.0, 2.0}, {1.0, 4.0}));   // starts on their top corner
    CPPUNIT_ASSERT(!segmentFree(grid, {0.0, 1.5}, {4.0, 1.5}));  // through their interiors
  }

  void cornersMayBeTouchedButNotSqueezedThrough() {
    OccupancyGrid grid(4, 4, 1.0);
    grid.set({1, 1}, Cell::Occupied);
    CPPUNIT_ASSERT(!segmentFree(grid, {0.5, 2.5}, {2.5, 0.5}));  // along the blocked cell's diagonal
    CPPUNIT_ASSERT(segmentFree(grid, {0.5, 3.5}, {3.5, 0.5}));  // through vertex (2, 2): touches the corner
    grid.set({2, 2}, Cell::Occupied);
    CPPUNIT_ASSERT(!segmentFree(grid, {0.5, 3.5}, {3.5, 0.5}));  // squeezes between (1,1) and (2,2)
    CPPUNIT_ASSERT(!segmentFree(grid, {2.0, 0.0}, {2.0, 4.0}));  // along x = 2 past the pinch at (2, 2)
    CPPUNIT_ASSERT(segmentFree(grid, {0.5, 0.5}, {1.0, 2.0}));  // (0,0), (0,1), ends on a vertex of (1,1)
  }

  void randomSegmentsAgreeWithSampledInteriors() {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> half(1, 39);
    for (int trial = 0; trial < 3000; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 20, 0.08);
      const Vector2d a(half(rng) * 0.5, half(rng) * 0.5), b(half(rng) * 0.5, half(rng) * 0.5);
      // Sample the segment; a sample strictly inside a cell must find the cell free. The sampling
      // misses squeezes, so it may only say "free" where the walk says "blocked" at a vertex or
      // grid line: assert the walk never says free where a sample lies inside a blocked cell.
      bool sampledFree = true;
      const int n = 4000;
      for (int k = 0; k <= n && sampledFree; ++k) {
        const Vector2d p = a + (b - a) * (double(k) / n);
        const double fx = p.x() - std::floor(p.x()), fy = p.y() - std::floor(p.y());
        if (fx < 1e-9 || fy < 1e-9) continue;
        if (grid.blocked({int(std::floor(p.x())), int(std::floor(p.y()))})) sampledFree = false;
      }
      if (segmentFree(grid, a, b)) CPPUNIT_ASSERT(sampledFree);
    }
  }

  void outsideTheGridIsBlocked() {
    OccupancyGrid grid(3, 3, 1.0);
    CPPUNIT_ASSERT(segmentFree(grid, {0.0, 0.0}, {3.0, 3.0}));
    CPPUNIT_ASSERT(!segmentFree(grid, {0.5, 0.5}, {3.5, 0.5}));
    CPPUNIT_ASSERT(segmentFree(grid, {0.0, 0.0}, {0.0, 3.0}));  // along the border: one side is free
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(SegmentVisibilityTest);
