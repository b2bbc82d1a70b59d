// TaskCheckpoint: a queue with tasks in every state, questions and answered requests reads back as
// it was written (so a restarted module resumes its active task with the same drive request ID and
// does not ask again); damaged texts are FormatErrors.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "servers/highlevelplanning/TaskCheckpoint.h"

using namespace rgnav;

namespace {

RegionSummaryView unnamed(std::uint64_t id) {
  RegionSummaryView r;
  r.id = RegionId(id);
  return r;
}

HighLevelPlanningState sample() {
  HighLevelPlanningState state;
  state.queue.goTo(PlanGoal::inRegionNamed("kitchen"), 101);
  state.queue.goTo(PlanGoal::at({1.0 / 3.0, -2.0}), 102);
  state.queue.explore(103);
  state.queue.goTo(PlanGoal::atObject("closet"), 104);
  state.queue.startNext();
  state.queue.finish(TaskState::Blocked, "no path: unknown region kitchen");
  state.queue.cancel(4, "cancelled on request");
  state.queue.startNext();
  state.queue.setProgress(0xfedcba9876543210ULL, 2, 0.1, "driving to point 0.33 -2.00: driving");
  state.dialog.observe(RegionId(3), {0.5, 0.25}, {unnamed(3), unnamed(5)});
  state.dialog.observe(RegionId(5), {4.0, 1.0}, {unnamed(3), unnamed(5)});
  state.dialog.answered(1);
  state.requests.add(900, 4);
  state.requests.add(901, 1);
  return state;
}

}  // namespace

class TaskCheckpointTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TaskCheckpointTest);
  CPPUNIT_TEST(roundTrips);
  CPPUNIT_TEST(damagedTextIsRefused);
  CPPUNIT_TEST(answeredRequestsAreBounded);
  CPPUNIT_TEST_SUITE_END();

 public:
  void roundTrips() {
    const HighLevelPlanningState state = sample();
    const std::string text = serializeTasks(state);
    const HighLevelPlanningState back = deserializeTasks(text, "tasks.state");
    CPPUNIT_ASSERT_EQUAL(text, serializeTasks(back));
    CPPUNIT_ASSERT_EQUAL(TaskId{5}, back.queue.nextId());
    const Task* active = back.queue.active();
    CPPUNIT_ASSERT(active != nullptr);
    CPPUNIT_ASSERT_EQUAL(TaskId{2}, active->id);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0xfedcba9876543210ULL}, active->drive);
    CPPUNIT_ASSERT_EQUAL(1.0 / 3.0, active->goal.point.x());
    CPPUNIT_ASSERT_EQUAL(0.1, active->distanceLeftM);
    CPPUNIT_ASSERT(back.queue.find(1)->state == TaskState::Blocked);
    CPPUNIT_ASSERT_EQUAL(std::string("no path: unknown region kitchen"), back.queue.find(1)->reason);
    CPPUNIT_ASSERT(back.queue.find(4)->goal.kind == PlanGoal::Kind::Object);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{104}, back.queue.find(4)->request);
    CPPUNIT_ASSERT(back.dialog.waiting() == state.dialog.waiting());
    CPPUNIT_ASSERT_EQUAL(QuestionId{3}, back.dialog.nextId());
    CPPUNIT_ASSERT(back.dialog.asked() == state.dialog.asked());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{4}, *back.requests.find(900));
    CPPUNIT_ASSERT(back.requests.find(902) == nullptr);
  }

  void damagedTextIsRefused() {
    const std::string text = serializeTasks(sample());
    CPPUNIT_ASSERT_THROW(deserializeTasks(text.substr(0, text.size() / 2), "tasks.state"), FormatError);
    CPPUNIT_ASSERT_THROW(deserializeTasks("{\"format\": \"rgnav-drive\", \"version\": 1}", "tasks.state"), FormatError);
    std::string badState = text;
    badState.replace(badState.find("\"state\":"), 9, "\"state\":9");
    CPPUNIT_ASSERT_THROW(deserializeTasks(badState, "tasks.state"), FormatError);
    std::string badNext = text;
    badNext.replace(badNext.find("\"nextTask\":5"), 12, "\"nextTask\":3");
    CPPUNIT_ASSERT_THROW(deserializeTasks(badNext, "tasks.state"), FormatError);
  }

  void answeredRequestsAreBounded() {
    AnsweredRequests requests;
    for (std::uint64_t r = 1; r <= AnsweredRequests::kKept + 1; ++r) requests.add(r, r * 10);
    CPPUNIT_ASSERT(requests.find(1) == nullptr);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{20}, *requests.find(2));
    CPPUNIT_ASSERT_EQUAL(AnsweredRequests::kKept, requests.answers.size());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TaskCheckpointTest);
