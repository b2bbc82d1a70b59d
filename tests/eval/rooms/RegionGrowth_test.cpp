// Tests growIntoUnclaimed (RegionGrowth.h) on one-row maps: regions grow into unclaimed free
// cells up to maxGrowCells, walls and other regions' cells stop nothing they already hold, cells
// claimed by two regions stay with both, and bad sizes are refused.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "tests/eval/rooms/RegionGrowth.h"

namespace {

constexpr int kWidth = 10, kHeight = 1;

// A raster claiming columns [from, to).
rgnav::RegionRaster claiming(std::int64_t id, int from, int to) {
  rgnav::RegionRaster raster{id, std::vector<std::uint8_t>(kWidth * kHeight, 0)};
  for (int c = from; c < to; ++c) raster.claimed[std::size_t(c)] = 1;
  return raster;
}

std::vector<std::uint8_t> allFree() { return std::vector<std::uint8_t>(kWidth * kHeight, 1); }

std::vector<std::uint8_t> row(std::initializer_list<int> values) {
  std::vector<std::uint8_t> out;
  for (const int v : values) out.push_back(std::uint8_t(v));
  return out;
}

}  // namespace

class RegionGrowthTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionGrowthTest);
  CPPUNIT_TEST(growsUpToMaxStepsAndStopsAtWalls);
  CPPUNIT_TEST(growsOnlyIntoCellsNoRegionClaims);
  CPPUNIT_TEST(refusesWrongSizes);
  CPPUNIT_TEST_SUITE_END();

 public:
  void growsUpToMaxStepsAndStopsAtWalls() {
    std::vector<std::uint8_t> free = allFree();
    free[7] = 0;
    std::vector<rgnav::RegionRaster> regions{claiming(4, 3, 5)};
    rgnav::growIntoUnclaimed(regions, free, kWidth, kHeight, 2);
    CPPUNIT_ASSERT(regions[0].claimed == row({0, 1, 1, 1, 1, 1, 1, 0, 0, 0}));
    std::vector<rgnav::RegionRaster> far{claiming(4, 3, 5)};
    rgnav::growIntoUnclaimed(far, free, kWidth, kHeight, 100);
    CPPUNIT_ASSERT(far[0].claimed == row({1, 1, 1, 1, 1, 1, 1, 0, 0, 0}));
  }

  void growsOnlyIntoCellsNoRegionClaims() {
    // Region 1 holds 0..3, region 2 holds 3..5: the shared cell 3 stays with both; region 1 does
    // not grow into 4, 5 (region 2's), region 2 grows into 6, 7.
    std::vector<rgnav::RegionRaster> regions{claiming(1, 0, 4), claiming(2, 3, 6)};
    rgnav::growIntoUnclaimed(regions, allFree(), kWidth, kHeight, 2);
    CPPUNIT_ASSERT(regions[0].claimed == row({1, 1, 1, 1, 0, 0, 0, 0, 0, 0}));
    CPPUNIT_ASSERT(regions[1].claimed == row({0, 0, 0, 1, 1, 1, 1, 1, 0, 0}));
  }

  void refusesWrongSizes() {
    std::vector<rgnav::RegionRaster> regions{claiming(1, 0, 2)};
    CPPUNIT_ASSERT_THROW(rgnav::growIntoUnclaimed(regions, std::vector<std::uint8_t>(3, 1), kWidth, kHeight, 1),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::growIntoUnclaimed(regions, allFree(), kWidth - 1, kHeight, 1),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::growIntoUnclaimed(regions, allFree(), kWidth, kHeight, -1),
                         rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RegionGrowthTest);
