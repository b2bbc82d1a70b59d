// Tests squaredDistanceToBlocked against brute force on random grids, and its two edge cases.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <random>

#include "core/raster/DistanceField.h"

using namespace rgnav;

class DistanceFieldTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DistanceFieldTest);
  CPPUNIT_TEST(matchesBruteForceOnRandomGrids);
  CPPUNIT_TEST(longDistancesStayExactSquares);
  CPPUNIT_TEST(gridWithoutBlockedCells);
  CPPUNIT_TEST_SUITE_END();

 public:
  void matchesBruteForceOnRandomGrids() {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 10; ++trial) {
      OccupancyGrid grid(17 + trial, 13, 0.05);
      for (int row = 0; row < grid.height(); ++row)
        for (int col = 0; col < grid.width(); ++col)
          if (rng() % 100 < 8) grid.set({col, row}, trial % 2 ? Cell::Unknown : Cell::Occupied);
      grid.set({0, 0}, Cell::Occupied);
      const std::vector<float> squared = squaredDistanceToBlocked(grid);
      for (int row = 0; row < grid.height(); ++row)
        for (int col = 0; col < grid.width(); ++col) {
          long best = -1;
          for (int r = 0; r < grid.height(); ++r)
            for (int c = 0; c < grid.width(); ++c)
              if (grid.at({c, r}) != Cell::Free) {
                const long d = long(c - col) * (c - col) + long(r - row) * (r - row);
                best = best < 0 ? d : std::min(best, d);
              }
          CPPUNIT_ASSERT_EQUAL(float(best), squared[std::size_t(row * grid.width() + col)]);
        }
    }
  }

  // One blocked cell in a corner of a 1500 x 1000 grid: squares up to 3.25 million, exact.
  void longDistancesStayExactSquares() {
    OccupancyGrid grid(1500, 1000, 0.05);
    grid.set({0, 0}, Cell::Occupied);
    const std::vector<float> squared = squaredDistanceToBlocked(grid);
    for (const CellIndex c : {CellIndex{1499, 999}, CellIndex{1234, 567}, CellIndex{7, 998}, CellIndex{1, 1}})
      CPPUNIT_ASSERT_EQUAL(float(c.col * c.col + c.row * c.row), squared[std::size_t(c.row * 1500 + c.col)]);
  }

  void gridWithoutBlockedCells() {
    const std::vector<float> squared = squaredDistanceToBlocked(OccupancyGrid(5, 4, 0.1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(20), squared.size());
    CPPUNIT_ASSERT(std::all_of(squared.begin(), squared.end(), [](float s) { return s == kNoBlockedCell; }));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(DistanceFieldTest);
