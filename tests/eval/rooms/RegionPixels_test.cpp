// Tests regionPixels (RegionPixels.h) on a hand-made map: a region's freespace lands on the floor
// plan pixels its frame pose and mapToWorld put it on, only on the world's free pixels, grows
// over free pixels up to growM and takes the holes up to maxHoleM2 it encloses.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>

#include "core/common/Errors.h"
#include "tests/eval/rooms/RegionPixels.h"

namespace {

constexpr int kWidth = 40, kHeight = 20;  // 2 x 1 m at 5 cm

// A 0.3 x 0.3 m freespace (2 x 2 cells of 15 cm) from the region frame's origin.
rgnav::FinalMap oneRegion(const rgnav::Pose2D& frame) {
  rgnav::RegionView region;
  region.summary.id = rgnav::RegionId{7};
  region.summary.frame = frame;
  region.freespace = rgnav::FreespaceBitmap::allOccupied(0.15, Eigen::Vector2d::Zero(), 2, 2);
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 2; ++col) region.freespace.setFree(col, row);
  rgnav::FinalMap map;
  map.regions.push_back(region);
  return map;
}

std::size_t pixel(int col, int row) { return std::size_t(row * kWidth + col); }

bool holds(const rgnav::SegmentPixels& s, std::size_t p) {
  return std::find(s.pixels.begin(), s.pixels.end(), p) != s.pixels.end();
}

}  // namespace

class RegionPixelsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionPixelsTest);
  CPPUNIT_TEST(placesTheFreespaceByFrameAndMapToWorld);
  CPPUNIT_TEST(keepsOnlyTheWorldsFreePixels);
  CPPUNIT_TEST(growsOverFreePixelsUpToGrowM);
  CPPUNIT_TEST(takesTheHolesItEncloses);
  CPPUNIT_TEST_SUITE_END();

 public:
  void placesTheFreespaceByFrameAndMapToWorld() {
    const rgnav::OccupancyGrid world(kWidth, kHeight, 0.05);
    // Region frame at (0.2, 0.1) in the map, the map shifted by (0.5, 0.2) in the world: the
    // freespace covers [0.7, 1.0) x [0.3, 0.6), pixel columns 14..19 and rows 6..11.
    const std::vector<rgnav::SegmentPixels> segments =
        rgnav::regionPixels(oneRegion({0.2, 0.1, 0.0}), {0.5, 0.2, 0.0}, world, 0.0, 0.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), segments.size());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(7), segments[0].id);
    CPPUNIT_ASSERT_EQUAL(std::size_t(36), segments[0].pixels.size());
    CPPUNIT_ASSERT(holds(segments[0], pixel(14, 6)));
    CPPUNIT_ASSERT(holds(segments[0], pixel(19, 11)));
    CPPUNIT_ASSERT(!holds(segments[0], pixel(20, 11)));
  }

  void keepsOnlyTheWorldsFreePixels() {
    rgnav::OccupancyGrid world(kWidth, kHeight, 0.05);
    for (int row = 0; row < kHeight; ++row) world.set({16, row}, rgnav::Cell::Occupied);
    const std::vector<rgnav::SegmentPixels> segments =
        rgnav::regionPixels(oneRegion({0.2, 0.1, 0.0}), {0.5, 0.2, 0.0}, world, 0.0, 0.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(30), segments[0].pixels.size());
    CPPUNIT_ASSERT(!holds(segments[0], pixel(16, 8)));
  }

  void growsOverFreePixelsUpToGrowM() {
    rgnav::OccupancyGrid world(kWidth, kHeight, 0.05);
    for (int row = 0; row < kHeight; ++row) world.set({22, row}, rgnav::Cell::Occupied);
    // Columns 14..19 claimed; 0.1 m of growth adds columns 12, 13, 20, 21 (the wall at 22 stops
    // it) and rows 4, 5, 12, 13.
    const std::vector<rgnav::SegmentPixels> segments =
        rgnav::regionPixels(oneRegion({0.2, 0.1, 0.0}), {0.5, 0.2, 0.0}, world, 0.1, 0.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(10 * 10), segments[0].pixels.size());
    CPPUNIT_ASSERT(holds(segments[0], pixel(12, 4)));
    CPPUNIT_ASSERT(holds(segments[0], pixel(21, 13)));
    CPPUNIT_ASSERT(!holds(segments[0], pixel(23, 8)));
  }

  // A 2 x 2 pixel block standing inside the region: left out of its freespace, taken as a hole
  // of 0.01 m^2 when holes that large are allowed; a negative limit is refused.
  void takesTheHolesItEncloses() {
    rgnav::OccupancyGrid world(kWidth, kHeight, 0.05);
    for (int row = 8; row <= 9; ++row)
      for (int col = 16; col <= 17; ++col) world.set({col, row}, rgnav::Cell::Occupied);
    const auto pixelsWith = [&](double maxHoleM2) {
      return rgnav::regionPixels(oneRegion({0.2, 0.1, 0.0}), {0.5, 0.2, 0.0}, world, 0.0, maxHoleM2)[0].pixels.size();
    };
    CPPUNIT_ASSERT_EQUAL(std::size_t(32), pixelsWith(0.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(32), pixelsWith(0.009));
    CPPUNIT_ASSERT_EQUAL(std::size_t(36), pixelsWith(0.011));
    CPPUNIT_ASSERT_THROW(pixelsWith(-1.0), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RegionPixelsTest);
