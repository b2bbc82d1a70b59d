// Round trips of every Trajectory.idl / LowLevelDrive.idl conversion: a whole chain (straight,
// arc, clothoid) segment by segment, limits, every drive state, the drive report with its loop
// periods (milliseconds on the wire); segments that do not join are refused on the way in.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/lowleveldrive/convert.h"
#include "core/common/Errors.h"

using namespace rgnav;

namespace {

DriveChain threeSegmentChain() {
  const TrajectorySegment straight{{1.0, -2.0, 0.25}, 1.5, 0.0, 0.0};
  const TrajectorySegment clothoid{straight.end(), 0.8, 0.0, 1.25};
  const TrajectorySegment arc{clothoid.end(), 1.1, clothoid.curvatureAt(0.8), 0.0};
  return DriveChain{17, TrajectoryChain({straight, clothoid, arc}), 0.35, 1234.567891, 0.51};
}

}  // namespace

class LowLevelDriveConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LowLevelDriveConvertTest);
  CPPUNIT_TEST(chainRoundTripKeepsEverySegment);
  CPPUNIT_TEST(segmentsThatDoNotJoinAreRefused);
  CPPUNIT_TEST(limitsRoundTrip);
  CPPUNIT_TEST(everyStateRoundTrips);
  CPPUNIT_TEST(reportRoundTripWithMilliseconds);
  CPPUNIT_TEST_SUITE_END();

 public:
  void chainRoundTripKeepsEverySegment() {
    const DriveChain chain = threeSegmentChain();
    const RGNav::DriveChain wire = toIdl(chain);
    CPPUNIT_ASSERT_EQUAL(CORBA::ULong(3), wire.segments.length());
    const DriveChain back = fromIdl(wire);
    CPPUNIT_ASSERT_EQUAL(chain.id, back.id);
    CPPUNIT_ASSERT(chain.chain.segments() == back.chain.segments());
    CPPUNIT_ASSERT_EQUAL(chain.chain.length(), back.chain.length());
    CPPUNIT_ASSERT_EQUAL(chain.startSpeed, back.startSpeed);
    CPPUNIT_ASSERT_EQUAL(chain.cruiseSpeed, back.cruiseSpeed);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(chain.startTime, back.startTime, 1e-6);
  }

  void segmentsThatDoNotJoinAreRefused() {
    RGNav::DriveChain wire = toIdl(threeSegmentChain());
    wire.segments[1].start.x += 0.01;  // a 1 cm gap after the straight
    CPPUNIT_ASSERT_THROW(fromIdl(wire), InvalidArgumentError);
    wire = toIdl(threeSegmentChain());
    wire.segments[2].length = -1.0;
    CPPUNIT_ASSERT_THROW(fromIdl(wire), InvalidArgumentError);
  }

  void limitsRoundTrip() {
    const MotionLimits limits{0.9, 0.4, 0.6, 1.2, 2.5, 0.7};
    const MotionLimits back = fromIdl(toIdl(limits));
    CPPUNIT_ASSERT_EQUAL(limits.maxVelocity, back.maxVelocity);
    CPPUNIT_ASSERT_EQUAL(limits.maxAcceleration, back.maxAcceleration);
    CPPUNIT_ASSERT_EQUAL(limits.maxDeceleration, back.maxDeceleration);
    CPPUNIT_ASSERT_EQUAL(limits.maxRotationalVelocity, back.maxRotationalVelocity);
    CPPUNIT_ASSERT_EQUAL(limits.maxRotationalAcceleration, back.maxRotationalAcceleration);
    CPPUNIT_ASSERT_EQUAL(limits.maxLateralAcceleration, back.maxLateralAcceleration);
  }

  void everyStateRoundTrips() {
    for (DriveState state : {DriveState::Idle, DriveState::Tracking, DriveState::Settling, DriveState::Braking})
      CPPUNIT_ASSERT(state == fromIdl(toIdl(state)));
    CPPUNIT_ASSERT(RGNav::DRIVE_BRAKING == toIdl(DriveState::Braking));
    CPPUNIT_ASSERT_THROW(fromIdl(static_cast<RGNav::DriveState>(9)), InvalidArgumentError);
  }

  void reportRoundTripWithMilliseconds() {
    DriveReport report;
    report.drive = {DriveState::Tracking, 42, 1.75, 2.5, {3.0, 4.0, -0.5}, -0.012, false};
    report.loopPeriodLastSeconds = 0.0512;
    report.loopPeriodP99Seconds = 0.0537;
    report.commandsSent = 901;
    const RGNav::DriveReport wire = toIdl(report);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(51.2, wire.loopPeriodLastMs, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(53.7, wire.loopPeriodP99Ms, 1e-9);
    const DriveReport back = fromIdl(wire);
    CPPUNIT_ASSERT(back.drive.state == DriveState::Tracking);
    CPPUNIT_ASSERT_EQUAL(report.drive.chainId, back.drive.chainId);
    CPPUNIT_ASSERT_EQUAL(report.drive.progress, back.drive.progress);
    CPPUNIT_ASSERT_EQUAL(report.drive.remainingSeconds, back.drive.remainingSeconds);
    CPPUNIT_ASSERT(report.drive.reference == back.drive.reference);
    CPPUNIT_ASSERT_EQUAL(report.drive.lateralError, back.drive.lateralError);
    CPPUNIT_ASSERT_EQUAL(report.drive.chainFinished, back.drive.chainFinished);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(report.loopPeriodLastSeconds, back.loopPeriodLastSeconds, 1e-15);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(report.loopPeriodP99Seconds, back.loopPeriodP99Seconds, 1e-15);
    CPPUNIT_ASSERT_EQUAL(report.commandsSent, back.commandsSent);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LowLevelDriveConvertTest);
