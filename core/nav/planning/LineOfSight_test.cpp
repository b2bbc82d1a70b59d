// Tests LineOfSight against segmentFree: on grids with open space and scattered obstacles, for
// random segments between cell centres, grid vertices and arbitrary points, both always agree.
#include <cppunit/extensions/HelperMacros.h>

#include <random>

#include "core/nav/planning/LineOfSight.h"
#include "core/nav/planning/SegmentVisibility.h"

using Eigen::Vector2d;
using rgnav::Cell;
using rgnav::OccupancyGrid;

class LineOfSightTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LineOfSightTest);
  CPPUNIT_TEST(agreesWithSegmentFree);
  CPPUNIT_TEST_SUITE_END();

 public:
  void agreesWithSegmentFree() {
    std::mt19937 rng(17);
    int free = 0, blocked = 0;
    for (int trial = 0; trial < 12; ++trial) {
      OccupancyGrid grid(90, 70, 0.05);
      std::uniform_int_distribution<int> col(0, 89), row(0, 69), side(1, 6);
      for (int k = 0; k < 3 * trial; ++k) {  // rectangles and single cells
        const int c = col(rng), r = row(rng), w = k % 2 ? side(rng) : 1, h = k % 2 ? side(rng) : 1;
        for (int y = r; y < std::min(70, r + h); ++y)
          for (int x = c; x < std::min(90, c + w); ++x) grid.set({x, y}, Cell::Occupied);
      }
      const rgnav::LineOfSight lineOfSight(grid);
      std::uniform_int_distribution<int> half(0, 2 * 90);
      std::uniform_real_distribution<double> any(-1.0, 91.0);
      for (int k = 0; k < 3000; ++k) {
        const Vector2d a = k % 3 == 0 ? Vector2d(any(rng), any(rng) * 0.75) : Vector2d(half(rng) * 0.5, half(rng) * 0.5 * 0.75);
        const Vector2d b = k % 3 == 1 ? Vector2d(any(rng), any(rng) * 0.75) : Vector2d(half(rng) * 0.5, half(rng) * 0.5 * 0.75);
        const bool expected = rgnav::segmentFree(grid, a, b);
        CPPUNIT_ASSERT_EQUAL(expected, lineOfSight.free(a, b));
        (expected ? free : blocked) += 1;
      }
    }
    CPPUNIT_ASSERT(free > 3000);
    CPPUNIT_ASSERT(blocked > 3000);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LineOfSightTest);
