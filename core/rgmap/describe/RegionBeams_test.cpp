// Tests the clipping of beams to a region (thesis 5.2, "laser beams that cross a gateway are
// filtered out"): REP 117 ranges, the cap for beams without return, cuts at the first gateway
// crossed, and typed errors for invalid input.
#include "core/rgmap/describe/RegionBeams.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"

using Eigen::Vector2d;
using rgnav::GatewaySegment;
using rgnav::LaserScan;
using rgnav::Pose2D;
using rgnav::regionBeams;

namespace {

// Four beams at 0, 90, 180 and 270 degrees from the sensor heading.
LaserScan crossScan(std::vector<float> ranges, double maxRange = 30.0) {
  LaserScan scan;
  scan.startAngle = 0.0;
  scan.angleIncrement = M_PI / 2;
  scan.maxRange = maxRange;
  scan.ranges = std::move(ranges);
  return scan;
}

bool near(const Vector2d& a, const Vector2d& b) { return (a - b).norm() < 1e-9; }

}  // namespace

class RegionBeamsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionBeamsTest);
  CPPUNIT_TEST(rangesFollowRep117);
  CPPUNIT_TEST(noReturnIsCappedByMaxRange);
  CPPUNIT_TEST(gatewayCutsAtFirstCrossing);
  CPPUNIT_TEST(invalidInputIsTypedError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void rangesFollowRep117() {
    // Sensor at (1, 2) facing +y: beams go +y, -x, -y, +x.
    const auto beams = regionBeams(crossScan({2.0f, LaserScan::kNoReturn, LaserScan::kInvalid, -1.0f}),
                                   {1.0, 2.0, M_PI / 2}, {}, 3.0);
    CPPUNIT_ASSERT(near(Vector2d(1, 2), beams.origin));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), beams.beams.size());
    CPPUNIT_ASSERT(near(Vector2d(1, 4), beams.beams[0].end) && beams.beams[0].hit);
    CPPUNIT_ASSERT(near(Vector2d(-2, 2), beams.beams[1].end) && !beams.beams[1].hit);
    // A range at or beyond maxRange is no return as well.
    const auto far = regionBeams(crossScan({30.0f}, 30.0), {}, {}, 3.0);
    CPPUNIT_ASSERT(near(Vector2d(3, 0), far.beams[0].end) && !far.beams[0].hit);
  }

  void noReturnIsCappedByMaxRange() {
    const auto beams = regionBeams(crossScan({LaserScan::kNoReturn}, 1.5), {}, {}, 3.0);
    CPPUNIT_ASSERT(near(Vector2d(1.5, 0), beams.beams[0].end));
    // Without a maximum range the cap alone counts.
    const auto open = regionBeams(crossScan({LaserScan::kNoReturn}, 0.0), {}, {}, 3.0);
    CPPUNIT_ASSERT(near(Vector2d(3, 0), open.beams[0].end));
  }

  void gatewayCutsAtFirstCrossing() {
    // Gateways across the +x beam at x = 2 and x = 1; the beam hits a wall at x = 4.
    const std::vector<GatewaySegment> gateways{{{2, -1}, {2, 1}}, {{1, -1}, {1, 1}}};
    const auto beams = regionBeams(crossScan({4.0f, 4.0f, 4.0f, 4.0f}), {}, gateways, 3.0);
    CPPUNIT_ASSERT(near(Vector2d(1, 0), beams.beams[0].end) && !beams.beams[0].hit);
    CPPUNIT_ASSERT(near(Vector2d(0, 4), beams.beams[1].end) && beams.beams[1].hit);
    // A beam ending exactly on a gateway loses its obstacle; one ending before it keeps it.
    const std::vector<GatewaySegment> at{{{4, -1}, {4, 1}}};
    CPPUNIT_ASSERT(!regionBeams(crossScan({4.0f}), {}, at, 3.0).beams[0].hit);
    CPPUNIT_ASSERT(regionBeams(crossScan({3.9f}), {}, at, 3.0).beams[0].hit);
    // A beam without return is cut as well.
    const auto open = regionBeams(crossScan({LaserScan::kNoReturn}), {}, gateways, 3.0);
    CPPUNIT_ASSERT(near(Vector2d(1, 0), open.beams[0].end) && !open.beams[0].hit);
  }

  void invalidInputIsTypedError() {
    const auto scan = crossScan({1.0f});
    CPPUNIT_ASSERT_THROW(regionBeams(scan, {std::nan(""), 0, 0}, {}, 3.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(regionBeams(scan, {0, 0, INFINITY}, {}, 3.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(regionBeams(scan, {}, {}, -1.0), rgnav::InvalidArgumentError);
    const std::vector<GatewaySegment> bad{{{0, 0}, {std::nan(""), 1}}};
    CPPUNIT_ASSERT_THROW(regionBeams(scan, {}, bad, 3.0), rgnav::InvalidArgumentError);
    auto badAngles = scan;
    badAngles.angleIncrement = std::nan("");
    CPPUNIT_ASSERT_THROW(regionBeams(badAngles, {}, {}, 3.0), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RegionBeamsTest);
