// The drive checkpoint reads back exactly what was written (every field, numbers to the bit), and
// a damaged or foreign text is a FormatError, not a drive.
#include <cppunit/extensions/HelperMacros.h>

#include "servers/collisionavoidance/DriveCheckpoint.h"

using namespace rgnav;

class DriveCheckpointTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DriveCheckpointTest);
  CPPUNIT_TEST(roundTrip);
  CPPUNIT_TEST(damagedTextIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void roundTrip() {
    DriveRecord d;
    d.progress.request = 0xfeedbeefcafe0001ULL;
    d.progress.phase = DrivePhase::Waiting;
    d.progress.hasGoal = true;
    d.progress.goal = PlanGoal::at({1.0 / 3.0, -2.75});
    d.progress.plan = 41;
    d.progress.targetIndex = 1;
    d.progress.distanceLeftM = 0.1 + 0.2;
    d.progress.chainsSent = 99;
    d.progress.replans = 2;
    d.targets = {{{1.0, 2.0, 0.1}, RegionId(3)}, {{1.0 / 3.0, -2.75, -1.0 / 7.0}, RegionId(4)}};
    d.progress.targetCount = 2;
    const DriveRecord back = deserializeDrive(serializeDrive(d), "test");
    CPPUNIT_ASSERT_EQUAL(d.progress.request, back.progress.request);
    CPPUNIT_ASSERT_EQUAL(toString(d.progress.phase), toString(back.progress.phase));
    CPPUNIT_ASSERT(back.progress.hasGoal);
    CPPUNIT_ASSERT(back.progress.goal.point == d.progress.goal.point);
    CPPUNIT_ASSERT_EQUAL(d.progress.plan, back.progress.plan);
    CPPUNIT_ASSERT_EQUAL(d.progress.targetIndex, back.progress.targetIndex);
    CPPUNIT_ASSERT_EQUAL(d.progress.targetCount, back.progress.targetCount);
    CPPUNIT_ASSERT_EQUAL(d.progress.distanceLeftM, back.progress.distanceLeftM);
    CPPUNIT_ASSERT_EQUAL(d.progress.chainsSent, back.progress.chainsSent);
    CPPUNIT_ASSERT_EQUAL(d.progress.replans, back.progress.replans);
    CPPUNIT_ASSERT(d.targets == back.targets);
  }

  void damagedTextIsRefused() {
    const std::string text = serializeDrive(DriveRecord{});
    CPPUNIT_ASSERT_THROW(deserializeDrive(text.substr(0, text.size() / 2), "half"), FormatError);
    CPPUNIT_ASSERT_THROW(deserializeDrive(R"({"format": "rgnav-plans", "version": 1})", "foreign"), FormatError);
    std::string badPhase = text;
    badPhase.replace(badPhase.find("\"phase\":0"), 9, "\"phase\":17");
    CPPUNIT_ASSERT_THROW(deserializeDrive(badPhase, "phase"), FormatError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(DriveCheckpointTest);
