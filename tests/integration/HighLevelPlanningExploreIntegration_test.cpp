// The High-Level Planning module's explore task in a real set that knows nothing at the start: the
// simulator in real time on the two-room world, the ScanMapper and the GatewayDetection module
// (NavigationSet.h), the RG Mapping Kernel building the map online and the PathPlanning module
// (PlanningSet.h), the Low-Level Drive, the Collision Avoidance and the High-Level Planning module
// with the ScanMapper's pose (NavigationSet.h). The explore task (RG exploration, thesis chapter 7)
// drives the robot from the hallway through a door: it ends done with the hallway and at least one
// room in the kernel's map, a naming question asked about each region the robot was in, and no
// drive running. No module reads the ground truth.
#include <cppunit/extensions/HelperMacros.h>

#include <cstdio>

#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"
#include "clientlibs/highlevelplanning/HighLevelPlanningClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "tests/integration/IntegrationHelpers.h"
#include "tests/integration/NavigationSet.h"
#include "tests/integration/PlanningSet.h"
#include "tests/support/WaitUntil.h"

using namespace rgnav;
using namespace rgnav::testing;

class HighLevelPlanningExploreIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HighLevelPlanningExploreIntegrationTest);
  CPPUNIT_TEST(exploresTheTwoRoomWorld);
  CPPUNIT_TEST_SUITE_END();

 public:
  void exploresTheTwoRoomWorld() {
    ScratchDir scratch("rgnav-hlp-explore");
    std::vector<ClusterModule> modules = mappingModules();
    for (std::vector<ClusterModule> more : {planningModules(), motionAndTasks(scratch.path.string())})
      modules.insert(modules.end(), more.begin(), more.end());
    for (ClusterModule& module : modules)
      if (module.name == "RGMappingKernel") module.after = {"ScanMapper", "GatewayDetection"};  // it follows them
    TestCluster cluster(modules, kFastBackoff);
    cluster.start();
    HighLevelPlanningClient planning(cluster.clientSettings());
    RgMappingKernelClient kernel(cluster.clientSettings());
    CollisionAvoidanceClient avoidance(cluster.clientSettings());

    const Task explore = planning.explore();
    Task done;
    std::string shown;
    waitUntil([&] {
      done = planning.task(explore.id);
      if (done.progress != shown) std::printf("\n%s", done.progress.c_str());
      shown = done.progress;
      return ended(done.state);
    }, "the exploration to end", std::chrono::seconds(180), std::chrono::milliseconds(200));
    const MapSummaryView map = kernel.summary();
    const std::vector<NamingQuestion> questions = planning.questions();
    std::printf("\nexplore task %s %s after %u drives: regions=%zu gateways=%zu questions=%zu\n",
                toString(done.state).c_str(), done.reason.c_str(), done.drives, map.regions, map.gateways,
                questions.size());
    CPPUNIT_ASSERT_EQUAL(std::string("done"), toString(done.state));
    CPPUNIT_ASSERT(done.drives >= 2);
    CPPUNIT_ASSERT(map.regions >= 2);
    CPPUNIT_ASSERT(map.gateways >= 1);
    CPPUNIT_ASSERT(questions.size() >= 2);
    CPPUNIT_ASSERT(!avoidance.driveStatus().active());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(HighLevelPlanningExploreIntegrationTest);
