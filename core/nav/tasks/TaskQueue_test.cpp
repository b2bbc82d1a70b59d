// TaskQueue: IDs in order, one active task at a time first in first out, cancel of queued, active
// and ended tasks, stop cancelling everything, outcomes, repeated requests, bad goals, the bound on
// ended tasks, and a restored queue.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/nav/tasks/TaskQueue.h"

using namespace rgnav;

class TaskQueueTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TaskQueueTest);
  CPPUNIT_TEST(tasksRunOneAtATimeInOrder);
  CPPUNIT_TEST(cancelQueuedActiveAndEnded);
  CPPUNIT_TEST(stopCancelsEverything);
  CPPUNIT_TEST(repeatedRequestChangesNothing);
  CPPUNIT_TEST(badGoalsAreRefused);
  CPPUNIT_TEST(finishNeedsAnActiveTaskAndAnOutcome);
  CPPUNIT_TEST(oldEndedTasksAreForgotten);
  CPPUNIT_TEST(restoredQueueGoesOn);
  CPPUNIT_TEST_SUITE_END();

 public:
  void tasksRunOneAtATimeInOrder() {
    TaskQueue queue;
    CPPUNIT_ASSERT(queue.startNext() == nullptr);
    CPPUNIT_ASSERT_EQUAL(TaskId{1}, queue.goTo(PlanGoal::inRegionNamed("kitchen"), 11).id);
    CPPUNIT_ASSERT_EQUAL(TaskId{2}, queue.explore(12).id);
    CPPUNIT_ASSERT_EQUAL(TaskId{3}, queue.goTo(PlanGoal::at({1.0, 2.0}), 13).id);
    CPPUNIT_ASSERT(queue.active() == nullptr);
    CPPUNIT_ASSERT_EQUAL(TaskId{1}, queue.startNext()->id);
    CPPUNIT_ASSERT_EQUAL(TaskId{1}, queue.startNext()->id);  // still the active one
    CPPUNIT_ASSERT(queue.find(2)->state == TaskState::Queued);
    queue.setProgress(77, 1, 3.5, "driving to kitchen");
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{77}, queue.active()->drive);
    CPPUNIT_ASSERT_EQUAL(3.5, queue.active()->distanceLeftM);
    queue.finish(TaskState::Reached);
    CPPUNIT_ASSERT(queue.find(1)->state == TaskState::Reached);
    CPPUNIT_ASSERT_EQUAL(0.0, queue.find(1)->distanceLeftM);
    CPPUNIT_ASSERT(queue.active() == nullptr);
    CPPUNIT_ASSERT_EQUAL(TaskId{2}, queue.startNext()->id);
    CPPUNIT_ASSERT(queue.startNext()->kind == TaskKind::Explore);
    queue.finish(TaskState::Done);
    CPPUNIT_ASSERT_EQUAL(TaskId{3}, queue.startNext()->id);
    queue.finish(TaskState::Blocked, "no path: goal inside an obstacle");
    CPPUNIT_ASSERT_EQUAL(std::string("no path: goal inside an obstacle"), queue.find(3)->reason);
    CPPUNIT_ASSERT(queue.startNext() == nullptr);
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, queue.tasks().size());
  }

  void cancelQueuedActiveAndEnded() {
    TaskQueue queue;
    queue.goTo(PlanGoal::at({1.0, 0.0}), 1);
    queue.goTo(PlanGoal::at({2.0, 0.0}), 2);
    queue.goTo(PlanGoal::at({3.0, 0.0}), 3);
    queue.startNext();
    CPPUNIT_ASSERT(queue.cancel(2, "user").state == TaskState::Cancelled);
    CPPUNIT_ASSERT(queue.cancel(1, "user").state == TaskState::Cancelled);
    CPPUNIT_ASSERT(queue.active() == nullptr);
    CPPUNIT_ASSERT_EQUAL(TaskId{3}, queue.startNext()->id);  // the cancelled one is skipped
    queue.finish(TaskState::Reached);
    CPPUNIT_ASSERT(queue.cancel(3, "late").state == TaskState::Reached);  // ended: as it is
    CPPUNIT_ASSERT_EQUAL(std::string(), queue.find(3)->reason);
    CPPUNIT_ASSERT_THROW(queue.cancel(9, "user"), NotAvailableError);
  }

  void stopCancelsEverything() {
    TaskQueue queue;
    queue.explore(1);
    queue.goTo(PlanGoal::atObject("closet"), 2);
    queue.startNext();
    const Task stop = queue.stop(3);
    CPPUNIT_ASSERT(stop.kind == TaskKind::Stop);
    CPPUNIT_ASSERT(stop.state == TaskState::Done);
    CPPUNIT_ASSERT_EQUAL(TaskId{3}, stop.id);
    for (TaskId id : {TaskId{1}, TaskId{2}}) {
      CPPUNIT_ASSERT(queue.find(id)->state == TaskState::Cancelled);
      CPPUNIT_ASSERT_EQUAL(std::string("cancelled by stop task 3"), queue.find(id)->reason);
    }
    CPPUNIT_ASSERT(queue.startNext() == nullptr);
    queue.goTo(PlanGoal::at({0.0, 0.0}), 4);  // a task after the stop runs
    CPPUNIT_ASSERT_EQUAL(TaskId{4}, queue.startNext()->id);
  }

  void repeatedRequestChangesNothing() {
    TaskQueue queue;
    queue.goTo(PlanGoal::at({1.0, 0.0}), 42);
    queue.startNext();
    CPPUNIT_ASSERT_EQUAL(TaskId{1}, queue.goTo(PlanGoal::at({1.0, 0.0}), 42).id);
    const Task stop = queue.stop(43);
    queue.goTo(PlanGoal::at({5.0, 0.0}), 44);
    CPPUNIT_ASSERT_EQUAL(stop.id, queue.stop(43).id);  // the retried stop cancels no new task
    CPPUNIT_ASSERT(queue.find(3)->state == TaskState::Queued);
    CPPUNIT_ASSERT_EQUAL(TaskId{4}, queue.nextId());
    CPPUNIT_ASSERT(queue.byRequest(0) == nullptr);
  }

  void badGoalsAreRefused() {
    TaskQueue queue;
    CPPUNIT_ASSERT_THROW(queue.goTo(PlanGoal::at({std::nan(""), 0.0}), 1), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(queue.goTo(PlanGoal::inRegionNamed(""), 2), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(queue.goTo(PlanGoal::atObject(""), 3), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(queue.goTo(PlanGoal::inRegion(RegionId{}), 4), InvalidArgumentError);
    CPPUNIT_ASSERT(queue.tasks().empty());
    CPPUNIT_ASSERT_EQUAL(TaskId{1}, queue.nextId());
  }

  void finishNeedsAnActiveTaskAndAnOutcome() {
    TaskQueue queue;
    CPPUNIT_ASSERT_THROW(queue.finish(TaskState::Reached), InvalidArgumentError);
    queue.explore(1);
    queue.startNext();
    CPPUNIT_ASSERT_THROW(queue.finish(TaskState::Queued), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(queue.finish(TaskState::Cancelled), InvalidArgumentError);
    CPPUNIT_ASSERT(queue.active() != nullptr);
  }

  void oldEndedTasksAreForgotten() {
    TaskQueue queue(2);
    for (std::uint64_t r = 1; r <= 4; ++r) queue.goTo(PlanGoal::at({double(r), 0.0}), r);
    queue.startNext();
    queue.finish(TaskState::Reached);
    queue.cancel(3, "user");
    queue.startNext();
    queue.finish(TaskState::Reached);  // three ended: task 1 is forgotten
    CPPUNIT_ASSERT(queue.find(1) == nullptr);
    CPPUNIT_ASSERT(queue.find(2) != nullptr && queue.find(3) != nullptr);
    CPPUNIT_ASSERT(queue.find(4)->state == TaskState::Queued);  // a waiting task is never forgotten
  }

  void restoredQueueGoesOn() {
    TaskQueue queue;
    queue.goTo(PlanGoal::at({1.0, 0.0}), 1);
    queue.explore(2);
    queue.startNext();
    queue.setProgress(99, 2, 1.0, "driving");
    TaskQueue restored(queue.tasks(), queue.nextId());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{99}, restored.active()->drive);
    CPPUNIT_ASSERT_EQUAL(TaskId{3}, restored.goTo(PlanGoal::at({0.0, 1.0}), 3).id);
    std::vector<Task> twoActive = queue.tasks();
    twoActive[1].state = TaskState::Active;
    CPPUNIT_ASSERT_THROW(TaskQueue(twoActive, 3), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(TaskQueue(queue.tasks(), 2), InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TaskQueueTest);
