// A region name survives a SIGKILL of the RG Mapping Kernel at once after nameRegion answered
// (found by the navigation fault test's review, issue "Exploration, tasks and the navigating
// demo"): the High-Level Planning module ends a naming question once the kernel has answered, and
// nobody asks again, so a name the kernel answered for must be in the checkpoint a restart loads.
// The kernel holds the two-room map (twoRoomMap(), loaded from a checkpoint); each round names a
// region and kills the kernel by the PID the watchdog reports as soon as the call returns; the
// restarted kernel must find the region by that name.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include <filesystem>
#include <string>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/common/AtomicFile.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

class KernelNameKillTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(KernelNameKillTest);
  CPPUNIT_TEST(aNameAnsweredSurvivesAKill);
  CPPUNIT_TEST_SUITE_END();

 public:
  void aNameAnsweredSurvivesAKill() {
    TestCluster cluster(
        {{"RGMappingKernel",
          {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
          {"RGMappingKernel"}}},
        kFastBackoff);
    const RgMappingKernel map = twoRoomMap();
    const std::string state = cluster.dir() + "/run/state/RGMappingKernel";
    std::filesystem::create_directories(state);
    writeFileAtomically(state + "/rgmap.state", serializeRgMap(map.state()));
    writeFileAtomically(state + "/rgmap.state.scans", scanJournalLines(map.state()));
    cluster.start();
    RgMappingKernelClient kernel(cluster.clientSettings());
    const RegionId region = map.state().regions.begin()->first;
    for (int round = 1; round <= 5; ++round) {
      const std::string name = "room " + std::to_string(round);
      const ModuleProcessInfo before = cluster.waitFor("RGMappingKernel", isRunning, "running");
      kernel.nameRegion(region, name);
      CPPUNIT_ASSERT_EQUAL(0, ::kill(static_cast<pid_t>(before.pid), SIGKILL));
      cluster.waitFor("RGMappingKernel", runningAgainAfter(before.pid), "restarted");
      CPPUNIT_ASSERT_EQUAL_MESSAGE(name + " after the kill of round " + std::to_string(round), region.value(),
                                   kernel.regionByName(name).value());
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(KernelNameKillTest);
