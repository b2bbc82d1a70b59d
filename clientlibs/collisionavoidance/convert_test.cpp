// Round trips of the CollisionAvoidance.idl conversions: every drive state, a drive's status with
// every field set, and an unknown state from the wire.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/collisionavoidance/convert.h"
#include "core/common/Errors.h"

using namespace rgnav;

class CollisionAvoidanceConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CollisionAvoidanceConvertTest);
  CPPUNIT_TEST(phasesRoundTrip);
  CPPUNIT_TEST(progressRoundTrips);
  CPPUNIT_TEST(unknownStateIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void phasesRoundTrip() {
    for (DrivePhase phase : {DrivePhase::Idle, DrivePhase::Planning, DrivePhase::Driving, DrivePhase::Waiting,
                             DrivePhase::Blocked, DrivePhase::Replanning, DrivePhase::Reached, DrivePhase::Failed})
      CPPUNIT_ASSERT_EQUAL(toString(phase), toString(fromIdl(toIdl(phase))));
  }

  void progressRoundTrips() {
    DriveProgress p;
    p.request = 0xabcdef0123456789ULL;
    p.phase = DrivePhase::Replanning;
    p.hasGoal = true;
    p.goal = PlanGoal::inRegionNamed("office_07");
    p.plan = 17;
    p.targetIndex = 3;
    p.targetCount = 9;
    p.distanceLeftM = 1.0 / 3.0;
    p.chainsSent = 1234567890123ULL;
    p.replans = 4;
    p.reason = "door 5 blocked";
    const DriveProgress back = fromIdl(toIdl(p));
    CPPUNIT_ASSERT_EQUAL(p.request, back.request);
    CPPUNIT_ASSERT_EQUAL(toString(p.phase), toString(back.phase));
    CPPUNIT_ASSERT_EQUAL(p.hasGoal, back.hasGoal);
    CPPUNIT_ASSERT(back.goal.kind == p.goal.kind);
    CPPUNIT_ASSERT_EQUAL(p.goal.name, back.goal.name);
    CPPUNIT_ASSERT_EQUAL(p.plan, back.plan);
    CPPUNIT_ASSERT_EQUAL(p.targetIndex, back.targetIndex);
    CPPUNIT_ASSERT_EQUAL(p.targetCount, back.targetCount);
    CPPUNIT_ASSERT_EQUAL(p.distanceLeftM, back.distanceLeftM);
    CPPUNIT_ASSERT_EQUAL(p.chainsSent, back.chainsSent);
    CPPUNIT_ASSERT_EQUAL(p.replans, back.replans);
    CPPUNIT_ASSERT_EQUAL(p.reason, back.reason);
  }

  void unknownStateIsRefused() {
    RGNav::AvoidanceStatus info = toIdl(DriveProgress{});
    info.state = static_cast<RGNav::AvoidanceState>(42);
    CPPUNIT_ASSERT_THROW(fromIdl(info), InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CollisionAvoidanceConvertTest);
