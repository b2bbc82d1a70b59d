// Tests fillEnclosedHoles (RegionHoles.h) on small maps: a region takes a hole its pixels enclose,
// not a gap open to the border of its bounding box, not a hole larger than the limit, not one
// holding another region's pixel; bad sizes are refused.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "tests/eval/rooms/RegionHoles.h"

namespace {

constexpr int kWidth = 7, kHeight = 7;

// A raster from rows of '#' (claimed) and '.' (not), top row first as written, row 0 at the bottom.
rgnav::RegionRaster raster(std::int64_t id, const std::vector<std::string>& rows) {
  rgnav::RegionRaster r{id, std::vector<std::uint8_t>(kWidth * kHeight, 0)};
  for (int row = 0; row < kHeight; ++row)
    for (int col = 0; col < kWidth; ++col)
      r.claimed[std::size_t(row * kWidth + col)] = rows[std::size_t(kHeight - 1 - row)][std::size_t(col)] == '#';
  return r;
}

// A 5 x 5 ring around a 3 x 3 hole, or with its top side open.
const std::vector<std::string> kRing{".......", ".#####.", ".#...#.", ".#...#.", ".#...#.", ".#####.", "......."};
const std::vector<std::string> kOpenRing{".......", ".#...#.", ".#...#.", ".#...#.", ".#...#.", ".#####.", "......."};

}  // namespace

class RegionHolesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionHolesTest);
  CPPUNIT_TEST(enclosedHoleIsTaken);
  CPPUNIT_TEST(gapOpenToTheBoxIsNot);
  CPPUNIT_TEST(holeLargerThanTheLimitIsNot);
  CPPUNIT_TEST(holeWithAnotherRegionsPixelIsNot);
  CPPUNIT_TEST(refusesWrongSizes);
  CPPUNIT_TEST_SUITE_END();

 public:
  void enclosedHoleIsTaken() {
    std::vector<rgnav::RegionRaster> regions{raster(1, kRing)};
    rgnav::fillEnclosedHoles(regions, kWidth, kHeight, 9);
    CPPUNIT_ASSERT(regions[0].claimed ==
                   raster(1, {".......", ".#####.", ".#####.", ".#####.", ".#####.", ".#####.", "......."}).claimed);
  }

  void gapOpenToTheBoxIsNot() {
    std::vector<rgnav::RegionRaster> regions{raster(1, kOpenRing)};
    rgnav::fillEnclosedHoles(regions, kWidth, kHeight, 100);
    CPPUNIT_ASSERT(regions[0].claimed == raster(1, kOpenRing).claimed);
  }

  void holeLargerThanTheLimitIsNot() {
    std::vector<rgnav::RegionRaster> regions{raster(1, kRing)};
    rgnav::fillEnclosedHoles(regions, kWidth, kHeight, 8);
    CPPUNIT_ASSERT(regions[0].claimed == raster(1, kRing).claimed);
  }

  void holeWithAnotherRegionsPixelIsNot() {
    std::vector<rgnav::RegionRaster> regions{
        raster(1, kRing), raster(2, {".......", ".......", ".......", "...#...", ".......", ".......", "......."})};
    rgnav::fillEnclosedHoles(regions, kWidth, kHeight, 9);
    CPPUNIT_ASSERT(regions[0].claimed == raster(1, kRing).claimed);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), std::size_t(std::count(regions[1].claimed.begin(), regions[1].claimed.end(), 1)));
  }

  void refusesWrongSizes() {
    std::vector<rgnav::RegionRaster> regions{raster(1, kRing)};
    CPPUNIT_ASSERT_THROW(rgnav::fillEnclosedHoles(regions, kWidth - 1, kHeight, 9), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::fillEnclosedHoles(regions, -1, kHeight, 9), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RegionHolesTest);
