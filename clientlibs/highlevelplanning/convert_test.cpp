// Round trips of the HighLevelPlanning.idl conversions: every task kind and state, a task with
// every field set, a naming question, and an unknown kind or state from the wire.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/highlevelplanning/convert.h"
#include "core/common/Errors.h"

using namespace rgnav;

class HighLevelPlanningConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HighLevelPlanningConvertTest);
  CPPUNIT_TEST(kindsAndStatesRoundTrip);
  CPPUNIT_TEST(taskRoundTrips);
  CPPUNIT_TEST(questionRoundTrips);
  CPPUNIT_TEST(unknownKindOrStateIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void kindsAndStatesRoundTrip() {
    for (TaskKind kind : {TaskKind::GoTo, TaskKind::Explore, TaskKind::Stop})
      CPPUNIT_ASSERT_EQUAL(toString(kind), toString(fromIdl(toIdl(kind))));
    for (TaskState state : {TaskState::Queued, TaskState::Active, TaskState::Reached, TaskState::Blocked,
                            TaskState::Cancelled, TaskState::Done})
      CPPUNIT_ASSERT_EQUAL(toString(state), toString(fromIdl(toIdl(state))));
  }

  void taskRoundTrips() {
    Task t;
    t.id = 12;
    t.request = 0xfedcba9876543210ULL;
    t.kind = TaskKind::GoTo;
    t.goal = PlanGoal::atObject("closet");
    t.state = TaskState::Blocked;
    t.reason = "no path: unknown object closet";
    t.progress = "driving to closet";
    t.drive = 0x0123456789abcdefULL;
    t.drives = 3;
    t.distanceLeftM = 2.0 / 3.0;
    const Task back = fromIdl(toIdl(t));
    CPPUNIT_ASSERT_EQUAL(t.id, back.id);
    CPPUNIT_ASSERT_EQUAL(t.request, back.request);
    CPPUNIT_ASSERT(back.kind == t.kind);
    CPPUNIT_ASSERT(back.goal.kind == t.goal.kind);
    CPPUNIT_ASSERT_EQUAL(t.goal.name, back.goal.name);
    CPPUNIT_ASSERT(back.state == t.state);
    CPPUNIT_ASSERT_EQUAL(t.reason, back.reason);
    CPPUNIT_ASSERT_EQUAL(t.progress, back.progress);
    CPPUNIT_ASSERT_EQUAL(t.drive, back.drive);
    CPPUNIT_ASSERT_EQUAL(t.drives, back.drives);
    CPPUNIT_ASSERT_EQUAL(t.distanceLeftM, back.distanceLeftM);
    t.goal = PlanGoal::at({1.0 / 3.0, -7.25});
    CPPUNIT_ASSERT(fromIdl(toIdl(t)).goal.point == t.goal.point);
  }

  void questionRoundTrips() {
    const NamingQuestion q{7, RegionId(42), {1.0 / 3.0, -2.5}, "name this region? (region 42)"};
    CPPUNIT_ASSERT(fromIdl(toIdl(q)) == q);
  }

  void unknownKindOrStateIsRefused() {
    RGNav::TaskInfo info = toIdl(Task{});
    info.state = static_cast<RGNav::TaskState>(42);
    CPPUNIT_ASSERT_THROW(fromIdl(info), InvalidArgumentError);
    info = toIdl(Task{});
    info.kind = static_cast<RGNav::TaskKind>(42);
    CPPUNIT_ASSERT_THROW(fromIdl(info), InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(HighLevelPlanningConvertTest);
