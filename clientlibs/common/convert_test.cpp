// Round trips of every Common.idl / Module.idl conversion, including NaN/inf ranges.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "clientlibs/common/convert.h"

using namespace rgnav;

class CommonConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CommonConvertTest);
  CPPUNIT_TEST(timeRoundTripKeepsMicroseconds);
  CPPUNIT_TEST(laserScanRoundTripKeepsEveryBeam);
  CPPUNIT_TEST(odometryRoundTrip);
  CPPUNIT_TEST(moduleStatusRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void timeRoundTripKeepsMicroseconds() {
    for (double t : {0.0, 0.000246, 2683.77, 976052890.244111, -1.25}) {
      CPPUNIT_ASSERT_DOUBLES_EQUAL(t, fromIdl(toIdlTime(t)), 1e-6);
    }
    const RGNav::Time edge = toIdlTime(1.9999999999);
    CPPUNIT_ASSERT(edge.nsec < 1000000000u);
  }
  void laserScanRoundTripKeepsEveryBeam() {
    LaserScan scan;
    scan.id = 42;
    scan.stamp = 976052890.244111;
    scan.odometry = {1.0, -2.0, 0.5};
    scan.sensorPose = {1.1, -2.1, 0.6};
    scan.startAngle = -M_PI / 2;
    scan.angleIncrement = M_PI / 180;
    scan.maxRange = 80.0;
    scan.ranges = {1.5f, LaserScan::kNoReturn, 0.0f, 79.99f};
    scan.ranges.push_back(LaserScan::kInvalid);
    const LaserScan back = fromIdl(toIdl(scan));
    CPPUNIT_ASSERT_EQUAL(scan.id, back.id);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.stamp, back.stamp, 1e-6);
    CPPUNIT_ASSERT(scan.odometry == back.odometry);
    CPPUNIT_ASSERT(scan.sensorPose == back.sensorPose);
    CPPUNIT_ASSERT_EQUAL(scan.startAngle, back.startAngle);
    CPPUNIT_ASSERT_EQUAL(scan.angleIncrement, back.angleIncrement);
    CPPUNIT_ASSERT_EQUAL(scan.maxRange, back.maxRange);
    CPPUNIT_ASSERT_EQUAL(scan.ranges.size(), back.ranges.size());
    for (std::size_t i = 0; i + 1 < scan.ranges.size(); ++i) CPPUNIT_ASSERT_EQUAL(scan.ranges[i], back.ranges[i]);
    CPPUNIT_ASSERT(std::isnan(back.ranges.back()));
    CPPUNIT_ASSERT(fromIdl(toIdl(LaserScan{})) == LaserScan{});
  }
  void odometryRoundTrip() {
    const OdometryReading odo{7, 12.5, {3.0, 4.0, -3.0}, 0.4, -0.1};
    CPPUNIT_ASSERT(fromIdl(toIdl(odo)) == odo);
  }
  void moduleStatusRoundTrip() {
    ModuleStatusInfo status{"Laser", ModuleRunState::Running, 1234, 5.5, {{"scans", 910}, {"dropped", 3}}, "boom"};
    CPPUNIT_ASSERT(fromIdl(toIdl(status)) == status);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CommonConvertTest);
