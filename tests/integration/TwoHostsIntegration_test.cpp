// Two hosts on one machine: host A (127.0.0.1) runs the naming service and a playback, host B
// (127.0.0.2, a host of its own on loopback) runs its own watchdog and a second playback that
// registers in A's naming service and publishes B's address. Clients find both by name; each
// watchdog restarts only its own modules, and B's module comes back into A's naming service.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

class TwoHostsIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TwoHostsIntegrationTest);
  CPPUNIT_TEST(testModulesOfBothHostsAreFoundAndRecoverSeparately);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testModulesOfBothHostsAreFoundAndRecoverSeparately() {
    TestCluster hostA({{"LogPlayback", playbackCommand(intelLog()), {"Laser", "Base"}}}, kFastBackoff,
                      ClusterHost{"host-a", "127.0.0.1", 0});
    hostA.start();
    TestCluster hostB({{"LogPlaybackB", playbackCommand(intelLog(), {"--laser-object", "LaserB", "--base-object", "BaseB"}),
                        {"LaserB", "BaseB"}}},
                      kFastBackoff, ClusterHost{"host-b", "127.0.0.2", hostA.namingPort()});
    hostB.start();

    LaserClient laserA(hostA.clientSettings(), "Laser");
    LaserClient laserB(hostA.clientSettings(), "LaserB");
    CPPUNIT_ASSERT_EQUAL(kIntelScans, readAllScans(laserA).size());
    CPPUNIT_ASSERT_EQUAL(kIntelScans, readAllScans(laserB).size());
    CPPUNIT_ASSERT_EQUAL(static_cast<std::uint32_t>(hostB.describe("LogPlaybackB").pid), laserB.status().pid);

    const auto a = hostA.describe("LogPlayback");
    const auto b = hostB.describe("LogPlaybackB");
    ::kill(static_cast<pid_t>(b.pid), SIGKILL);
    hostB.waitFor("LogPlaybackB", runningAgainAfter(b.pid), "restarted by host B's watchdog");
    CPPUNIT_ASSERT_EQUAL(a.pid, hostA.describe("LogPlayback").pid);

    // A fresh client resolves B's module by name in A's naming service and reaches host B.
    LaserClient freshB(hostA.clientSettings(), "LaserB");
    CPPUNIT_ASSERT_EQUAL(DataId(5), freshB.scan(5).id);
    CPPUNIT_ASSERT_EQUAL(static_cast<std::uint32_t>(hostB.describe("LogPlaybackB").pid), freshB.status().pid);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(TwoHostsIntegrationTest);
