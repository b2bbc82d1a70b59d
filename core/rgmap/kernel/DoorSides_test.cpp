// Tests DoorSides: a scan counts for the side of a door it was taken on only in front of the door
// (not on its line, not beyond its ends, not too far away); it saw the door only if the beam
// towards the midpoint reaches it (a no-return beam as far as the freespace counts it free), for
// any heading of the robot; bad probe distances are refused.
#include "core/rgmap/kernel/DoorSides.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/Errors.h"

using namespace rgnav;

namespace {

constexpr RegionId kRegion{1};
const GatewaySegment kDoor{{0.0, 0.0}, {1.0, 0.0}};  // left of it: y > 0
constexpr double kNoReturnFreeRangeM = 3.0;           // a beam without return sees this far

// A 360-beam scan from -pi, every beam `range` long, taken at (x, y) heading `theta`.
StoredScan scanAt(DataId id, double x, double y, double theta, float range) {
  StoredScan s;
  s.scan.id = id;
  s.scan.startAngle = -std::numbers::pi;
  s.scan.angleIncrement = 2.0 * std::numbers::pi / 360.0;
  s.scan.maxRange = 30.0;
  s.scan.ranges.assign(360, range);
  s.corrected = {x, y, theta};
  return s;
}

RgMapState stateWith(const std::vector<StoredScan>& scans) {
  RgMapState state;
  Region& region = state.regions[kRegion];
  region.id = kRegion;
  for (const StoredScan& s : scans) {
    state.scans[s.scan.id] = s;
    region.scans.push_back(s.scan.id);
  }
  return state;
}

unsigned stood(const std::vector<StoredScan>& scans) {
  const RgMapState state = stateWith(scans);
  return sidesStoodOn(state, state.regions.at(kRegion), kDoor, DoorSideProbe{});
}

unsigned seen(const std::vector<StoredScan>& scans) {
  const RgMapState state = stateWith(scans);
  return sidesSeenFrom(state, state.regions.at(kRegion), kDoor, DoorSideProbe{}, kNoReturnFreeRangeM);
}

}  // namespace

class DoorSidesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DoorSidesTest);
  CPPUNIT_TEST(onlyScansInFrontOfTheDoorCount);
  CPPUNIT_TEST(seenOnlyWhereTheBeamReachesTheMidpoint);
  CPPUNIT_TEST(anyHeadingFindsTheBeam);
  CPPUNIT_TEST(badProbesAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void onlyScansInFrontOfTheDoorCount() {
    CPPUNIT_ASSERT_EQUAL(unsigned(kRightSide), stood({scanAt(1, 0.5, -2.0, 0.0, 5.0f)}));
    CPPUNIT_ASSERT_EQUAL(unsigned(kLeftSide), stood({scanAt(1, -0.8, 7.5, 0.0, 5.0f)}));
    CPPUNIT_ASSERT_EQUAL(unsigned(kBothSides), stood({scanAt(1, 0.5, -2.0, 0.0, 5.0f), scanAt(2, 1.5, 3.0, 0.0, 5.0f)}));
    CPPUNIT_ASSERT_EQUAL(unsigned(kNoSide), stood({scanAt(1, 0.5, 0.1, 0.0, 5.0f)}));   // on the line
    CPPUNIT_ASSERT_EQUAL(unsigned(kNoSide), stood({scanAt(1, 2.2, -2.0, 0.0, 5.0f)}));  // beyond an end
    CPPUNIT_ASSERT_EQUAL(unsigned(kNoSide), stood({scanAt(1, 0.5, -8.5, 0.0, 5.0f)}));  // too far away
    CPPUNIT_ASSERT_EQUAL(unsigned(kNoSide), stood({}));
  }

  void seenOnlyWhereTheBeamReachesTheMidpoint() {
    CPPUNIT_ASSERT_EQUAL(unsigned(kRightSide), seen({scanAt(1, 0.5, -2.0, 0.0, 5.0f)}));
    CPPUNIT_ASSERT_EQUAL(unsigned(kRightSide), seen({scanAt(1, 0.5, -2.0, 0.0, 1.9f)}));  // within the tolerance
    CPPUNIT_ASSERT_EQUAL(unsigned(kNoSide), seen({scanAt(1, 0.5, -2.0, 0.0, 1.5f)}));     // blocked before it
    // A blocked view from one side and a clear one from the other.
    CPPUNIT_ASSERT_EQUAL(unsigned(kLeftSide), seen({scanAt(1, 0.5, -2.0, 0.0, 1.0f), scanAt(2, 0.5, 2.0, 0.0, 5.0f)}));
    const float noReturn = LaserScan::kNoReturn;
    CPPUNIT_ASSERT_EQUAL(unsigned(kRightSide), seen({scanAt(1, 0.5, -2.5, 0.0, noReturn)}));
    CPPUNIT_ASSERT_EQUAL(unsigned(kNoSide), seen({scanAt(1, 0.5, -3.5, 0.0, noReturn)}));
    CPPUNIT_ASSERT_EQUAL(unsigned(kNoSide), seen({scanAt(1, 0.5, -2.0, 0.0, LaserScan::kInvalid)}));
  }

  void anyHeadingFindsTheBeam() {
    // Only the beams towards the midpoint reach it: every other beam is 0.5 m long.
    for (double theta = -3.0; theta <= 3.0; theta += 0.5) {
      StoredScan s = scanAt(1, 0.5, 2.0, theta, 0.5f);
      const double towards = -std::numbers::pi / 2.0;  // from (0.5, 2) to the midpoint
      double k = std::fmod((towards - theta + std::numbers::pi) / s.scan.angleIncrement, 360.0);
      if (k < 0.0) k += 360.0;
      const long beam = std::lround(k) % 360;
      s.scan.ranges[std::size_t(beam)] = 5.0f;
      CPPUNIT_ASSERT_EQUAL(unsigned(kLeftSide), seen({s}));
    }
  }

  void badProbesAreRefused() {
    validate(DoorSideProbe{});
    DoorSideProbe negative;
    negative.depthM = -1.0;
    CPPUNIT_ASSERT_THROW(validate(negative), ConfigError);
    DoorSideProbe infinite;
    infinite.rangeToleranceM = std::numeric_limits<double>::infinity();
    CPPUNIT_ASSERT_THROW(validate(infinite), ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(DoorSidesTest);
