// Tests furnitureShareMean (ScoreBreakdown.h): the share of each room's pixels free in the empty
// floor plan and not in the furnished one, averaged over the rooms; pixels of no room do not count;
// furniture of another size than the ground truth is refused.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "tests/eval/rooms/ScoreBreakdown.h"

class ScoreBreakdownTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ScoreBreakdownTest);
  CPPUNIT_TEST(furnitureShareIsTheMeanOverRooms);
  CPPUNIT_TEST_SUITE_END();

 public:
  void furnitureShareIsTheMeanOverRooms() {
    // One row: room 0 on cells 0..3, a wall on 4, room 1 on 5..6, outside on 7.
    rgnav::GroundTruth truth;
    truth.width = 8;
    truth.height = 1;
    truth.labels = {0, 0, 0, 0, -1, 1, 1, -1};
    truth.roomCount = 2;
    rgnav::OccupancyGrid empty(8, 1, 0.05), furnished(8, 1, 0.05);
    empty.set({4, 0}, rgnav::Cell::Occupied);
    furnished.set({4, 0}, rgnav::Cell::Occupied);
    furnished.set({1, 0}, rgnav::Cell::Occupied);  // a quarter of room 0
    furnished.set({7, 0}, rgnav::Cell::Occupied);  // outside every room: no share
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.125, rgnav::furnitureShareMean(truth, rgnav::furnitureTruth(furnished, empty, 1)),
                                 1e-12);
    furnished.set({6, 0}, rgnav::Cell::Occupied);  // half of room 1
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.375, rgnav::furnitureShareMean(truth, rgnav::furnitureTruth(furnished, empty, 1)),
                                 1e-12);
    const rgnav::OccupancyGrid shorter(7, 1, 0.05);
    CPPUNIT_ASSERT_THROW(rgnav::furnitureShareMean(truth, rgnav::furnitureTruth(shorter, shorter, 1)),
                         rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ScoreBreakdownTest);
