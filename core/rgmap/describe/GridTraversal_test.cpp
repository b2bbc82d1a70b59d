// Tests the lattice walk of a segment (Amanatides & Woo): it visits the cells in order, one step
// at a time in x or y, and ends in the cell of the end point, also through lattice corners, along
// cell borders and backwards.
#include "core/rgmap/describe/GridTraversal.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cstdlib>
#include <random>
#include <vector>

using rgnav::LatticeCell;
using rgnav::traverseCells;

namespace {

// The visited cells and the last one.
std::vector<LatticeCell> walk(double x0, double y0, double x1, double y1) {
  std::vector<LatticeCell> cells;
  const LatticeCell last = traverseCells(x0, y0, x1, y1, [&](int i, int j) { cells.push_back({i, j}); });
  cells.push_back(last);
  return cells;
}

}  // namespace

class GridTraversalTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GridTraversalTest);
  CPPUNIT_TEST(sameCellVisitsNothing);
  CPPUNIT_TEST(horizontalAndDiagonal);
  CPPUNIT_TEST(randomSegmentsAreFourConnectedAndEndRight);
  CPPUNIT_TEST_SUITE_END();

 public:
  void sameCellVisitsNothing() {
    int visits = 0;
    const LatticeCell last = traverseCells(2.2, -0.7, 2.9, -0.1, [&](int, int) { ++visits; });
    CPPUNIT_ASSERT_EQUAL(0, visits);
    CPPUNIT_ASSERT(last == (LatticeCell{2, -1}));
  }

  void horizontalAndDiagonal() {
    CPPUNIT_ASSERT(walk(0.5, 0.5, 3.5, 0.5) == (std::vector<LatticeCell>{{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
    CPPUNIT_ASSERT(walk(3.5, 0.5, 0.5, 0.5) == (std::vector<LatticeCell>{{3, 0}, {2, 0}, {1, 0}, {0, 0}}));
    // Exactly through the corner (1, 1): y first, then x.
    CPPUNIT_ASSERT(walk(0.5, 0.5, 1.5, 1.5) == (std::vector<LatticeCell>{{0, 0}, {0, 1}, {1, 1}}));
    // Along a cell border (y = 1 belongs to row 1).
    CPPUNIT_ASSERT(walk(0.2, 1.0, 2.7, 1.0) == (std::vector<LatticeCell>{{0, 1}, {1, 1}, {2, 1}}));
  }

  void randomSegmentsAreFourConnectedAndEndRight() {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-40.0, 40.0);
    for (int k = 0; k < 2000; ++k) {
      const double x0 = u(random), y0 = u(random), x1 = u(random), y1 = u(random);
      const auto cells = walk(x0, y0, x1, y1);
      CPPUNIT_ASSERT(cells.front() == (LatticeCell{int(std::floor(x0)), int(std::floor(y0))}));
      CPPUNIT_ASSERT(cells.back() == (LatticeCell{int(std::floor(x1)), int(std::floor(y1))}));
      CPPUNIT_ASSERT_EQUAL(std::size_t(std::abs(cells.back().i - cells.front().i) +
                                       std::abs(cells.back().j - cells.front().j) + 1),
                           cells.size());
      for (std::size_t c = 1; c < cells.size(); ++c) {
        // One step, and the segment really passes through the cell (its distance to the cell
        // centre is at most half a diagonal).
        CPPUNIT_ASSERT_EQUAL(1, std::abs(cells[c].i - cells[c - 1].i) + std::abs(cells[c].j - cells[c - 1].j));
        const double cx = cells[c].i + 0.5 - x0, cy = cells[c].j + 0.5 - y0, dx = x1 - x0, dy = y1 - y0;
        CPPUNIT_ASSERT(std::fabs(cx * dy - cy * dx) / std::hypot(dx, dy) <= std::sqrt(0.5) + 1e-9);
      }
    }
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(GridTraversalTest);
