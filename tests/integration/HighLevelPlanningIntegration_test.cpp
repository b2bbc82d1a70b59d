// The High-Level Planning module in a small real set: the simulator in real time on the two-room
// world, the Low-Level Drive, the Collision Avoidance and the High-Level Planning module
// (NavigationSet.h), the RG Mapping Kernel holding the map of that world and the PathPlanning
// module (PlanningSet.h). No module reads the ground truth. A goTo task along the hallway is driven
// through the chain: the module is SIGKILLed while the task is active, and the restarted module
// carries the task on with the same drive request ID until it ends reached. The naming dialog asks about the
// kernel's current region, which has no name; the answer names that region in the kernel and
// ends the question. rgnav-nav lists the task as reached. Only the test reads the ground truth, to
// check that the robot stands at the goal.
#include <cppunit/extensions/HelperMacros.h>

#include <signal.h>

#include <cmath>
#include <cstdio>

#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "clientlibs/highlevelplanning/HighLevelPlanningClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "tests/integration/IntegrationHelpers.h"
#include "tests/integration/NavigationSet.h"
#include "tests/integration/PlanningSet.h"
#include "tests/integration/ToolRun.h"

using namespace rgnav;
using namespace rgnav::testing;

class HighLevelPlanningIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HighLevelPlanningIntegrationTest);
  CPPUNIT_TEST(drivesATaskAndAsksForNames);
  CPPUNIT_TEST_SUITE_END();

 public:
  void drivesATaskAndAsksForNames() {
    ScratchDir scratch("rgnav-hlp-set");
    PlanningSet set(kFastBackoff, motionAndTasks(scratch.path.string()));
    TestCluster& cluster = set.cluster();
    cluster.start();
    HighLevelPlanningClient planning(cluster.clientSettings());
    RgMappingKernelClient kernel(cluster.clientSettings());

    // A task along the hallway, 5 m east.
    const Task queued = planning.goTo(PlanGoal::at({6.0, 1.0}));
    CPPUNIT_ASSERT_EQUAL(TaskId{1}, queued.id);
    CPPUNIT_ASSERT(queued.state == TaskState::Queued || queued.state == TaskState::Active);
    CPPUNIT_ASSERT_EQUAL(queued.id, planning.goTo(PlanGoal::at({6.0, 1.0}), queued.request).id);  // a retry
    Task driving;
    waitUntil([&] {
      driving = planning.task(1);
      return driving.drive != 0 && driving.progress.find("driving") != std::string::npos;
    }, "the task to drive", std::chrono::seconds(30), std::chrono::milliseconds(50));
    CPPUNIT_ASSERT(driving.state == TaskState::Active);

    // Killed while it drives, the module resumes the task with its drive's request ID.
    const ModuleProcessInfo before = cluster.describe("HighLevelPlanning");
    ::kill(static_cast<pid_t>(before.pid), SIGKILL);
    cluster.waitFor("HighLevelPlanning", runningAgainAfter(before.pid), "the module to restart");
    const Task resumed = planning.task(1);
    CPPUNIT_ASSERT_EQUAL(driving.drive, resumed.drive);
    CPPUNIT_ASSERT(resumed.state == TaskState::Active || resumed.state == TaskState::Reached);

    Task done;
    waitUntil([&] {
      done = planning.task(1);
      return ended(done.state);
    }, "the task to end", std::chrono::seconds(45), std::chrono::milliseconds(100));
    // The test (not a module) checks where the robot truly stands.
    LaserClient laser(cluster.clientSettings());
    GroundTruthClient truth(cluster.clientSettings());
    const Pose2D end = truth.truePose(laser.latestId());
    const double missM = std::hypot(end.x - 6.0, end.y - 1.0);
    std::printf("\ntask 1 %s %s after %u drive(s), drive request %llu kept over the restart; true pose %.2f %.2f "
                "(%.2f m from the goal)\n",
                toString(done.state).c_str(), done.reason.c_str(), done.drives,
                static_cast<unsigned long long>(done.drive), end.x, end.y, missM);
    CPPUNIT_ASSERT_EQUAL(std::string("reached"), toString(done.state));
    CPPUNIT_ASSERT_EQUAL(driving.drive, done.drive);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{1}, done.drives);
    CPPUNIT_ASSERT(missM <= 0.5);

    // The naming dialog: a question about the kernel's current region, answered by name.
    const RegionId current = kernel.summary().current;
    CPPUNIT_ASSERT(!current.isNone());
    CPPUNIT_ASSERT(kernel.region(current).summary.name.empty());
    std::vector<NamingQuestion> questions;
    waitUntil([&] {
      questions = planning.questions();
      return !questions.empty();
    }, "a naming question", std::chrono::seconds(20), std::chrono::milliseconds(50));
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, questions.size());
    CPPUNIT_ASSERT_EQUAL(current, questions.front().region);
    CPPUNIT_ASSERT(questions.front().text.find("name this region?") != std::string::npos);
    planning.answer(questions.front().id, "hallway");
    CPPUNIT_ASSERT_EQUAL(std::string("hallway"), kernel.region(current).summary.name);
    CPPUNIT_ASSERT(planning.questions().empty());
    CPPUNIT_ASSERT_THROW(planning.answer(questions.front().id, "again"), NotAvailableError);
    std::printf("question %llu about region %llu answered: the kernel names it '%s'\n",
                static_cast<unsigned long long>(questions.front().id),
                static_cast<unsigned long long>(current.value()), kernel.region(current).summary.name.c_str());

    const auto [code, output] = runTool("rgnav-nav", 
        {"--naming", "127.0.0.1:" + std::to_string(cluster.namingPort()), "tasks"}, scratch.file("nav.log"));
    std::printf("rgnav-nav tasks: %s", output.c_str());
    CPPUNIT_ASSERT_EQUAL(0, code);
    CPPUNIT_ASSERT(output.find("task 1 goTo point 6.00 1.00: reached") != std::string::npos);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(HighLevelPlanningIntegrationTest);
