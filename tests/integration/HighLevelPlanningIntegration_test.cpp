// The High-Level Planning module in a small real set: the simulator in real time on the two-room
// world (tests/worlds/hallway_two_rooms.yaml) with noiseless odometry (so the odometry frame, the
// Collision Avoidance's map frame with pose source "odometry", is the world frame), the Low-Level
// Drive, the RG Mapping Kernel holding the map of that world (twoRoomMap(), loaded from a
// checkpoint), the PathPlanning and Collision Avoidance modules, and the High-Level Planning
// module. No module reads the ground truth. A goTo task along the hallway is driven through the
// chain: the module is SIGKILLed while the task is active, and the restarted module carries the
// task on with the same drive request ID until it ends reached. The naming dialog asks about the
// kernel's current region, which has no name; the answer names that region in the kernel and
// ends the question. rgnav-nav lists the task as reached.
#include <cppunit/extensions/HelperMacros.h>

#include <signal.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "clientlibs/highlevelplanning/HighLevelPlanningClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/common/AtomicFile.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "tests/integration/IntegrationHelpers.h"
#include "tests/support/WaitUntil.h"
#include "watchdog/Spawn.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

const char* const kNoiselessSimulation =
    "odometry: {alpha1: 0, alpha2: 0, alpha3: 0, alpha4: 0}\n"
    "laser: {range_noise_sigma_m: 0}\n";

std::vector<ClusterModule> navigationSet(const std::string& simulationConfig) {
  const std::string world = std::filesystem::absolute("tests/worlds/hallway_two_rooms.yaml").string();
  return {{"Simulator",
           {TestCluster::program("rgnav-sim"), "--world", world, "--config", simulationConfig, "--clock", "realtime",
            "--start", "1,1,0"},
           {"Laser", "Base", "GroundTruth"}},
          {"LowLevelDrive",
           {TestCluster::program("rgnav-lowleveldrive"), "--config", TestCluster::moduleConfig("lowleveldrive")},
           {"LowLevelDrive"},
           {"Simulator"}},
          {"RGMappingKernel",
           {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
           {"RGMappingKernel"}},
          {"PathPlanning",
           {TestCluster::program("rgnav-pathplanning"), "--config", TestCluster::moduleConfig("pathplanning")},
           {"PathPlanning"},
           {"RGMappingKernel"}},
          {"CollisionAvoidance",
           {TestCluster::program("rgnav-collisionavoidance"), "--config",
            TestCluster::moduleConfig("collisionavoidance"), "--pose-source", "odometry"},
           {"CollisionAvoidance"},
           {"Simulator", "LowLevelDrive", "PathPlanning"}},
          {"HighLevelPlanning",
           {TestCluster::program("rgnav-highlevelplanning"), "--config",
            TestCluster::moduleConfig("highlevelplanning"), "--pose-source", "scanmapper"},
           {"HighLevelPlanning"},
           {"RGMappingKernel", "CollisionAvoidance"}}};
}

// Runs rgnav-nav with `args` until it ends; its exit status and output (stdout and stderr).
std::pair<int, std::string> runNavTool(const std::vector<std::string>& args, const std::string& logFile) {
  SpawnSpec spec;
  spec.argv = {TestCluster::program("rgnav-nav")};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.logFile = logFile;
  spec.parentDeathSignal = SIGKILL;
  const pid_t pid = spawnProcess(spec);
  int status = 0;
  try {
    waitUntil([&] { return ::waitpid(pid, &status, WNOHANG) != 0; }, "rgnav-nav to end", std::chrono::seconds(30),
              std::chrono::milliseconds(20));
  } catch (...) {
    discardChild(pid);
    throw;
  }
  std::ifstream log(logFile);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1,
          std::string(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>())};
}

}  // namespace

class HighLevelPlanningIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HighLevelPlanningIntegrationTest);
  CPPUNIT_TEST(drivesATaskAndAsksForNames);
  CPPUNIT_TEST_SUITE_END();

 public:
  void drivesATaskAndAsksForNames() {
    ScratchDir scratch("rgnav-hlp-set");
    const std::string simulation = scratch.file("noiseless.yaml");
    std::ofstream(simulation) << kNoiselessSimulation;
    TestCluster cluster(navigationSet(simulation), kFastBackoff);
    const RgMappingKernel map = twoRoomMap();
    const std::string kernelState = cluster.dir() + "/run/state/RGMappingKernel";
    std::filesystem::create_directories(kernelState);
    writeFileAtomically(kernelState + "/rgmap.state", serializeRgMap(map.state()));
    writeFileAtomically(kernelState + "/rgmap.state.scans", scanJournalLines(map.state()));
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
    std::printf("\ntask 1 %s %s after %u drive(s), drive request %llu kept over the restart\n",
                toString(done.state).c_str(), done.reason.c_str(), done.drives,
                static_cast<unsigned long long>(done.drive));
    CPPUNIT_ASSERT_EQUAL(std::string("reached"), toString(done.state));
    CPPUNIT_ASSERT_EQUAL(driving.drive, done.drive);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{1}, done.drives);

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

    const auto [code, output] = runNavTool(
        {"--naming", "127.0.0.1:" + std::to_string(cluster.namingPort()), "tasks"}, scratch.file("nav.log"));
    std::printf("rgnav-nav tasks: %s", output.c_str());
    CPPUNIT_ASSERT_EQUAL(0, code);
    CPPUNIT_ASSERT(output.find("task 1 goTo point 6.00 1.00: reached") != std::string::npos);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(HighLevelPlanningIntegrationTest);
