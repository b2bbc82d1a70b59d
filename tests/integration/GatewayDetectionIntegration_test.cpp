// The GatewayDetection module through the real server set on the Intel log: the event buffer
// by ID (consecutive IDs, every gateway detected before it is updated or traversed, doors and
// hallway gateways, traversals), lookups by ID with typed errors, and a restart by the operator
// that resumes from the checkpoint with the very same events and gateways.
#include <cppunit/extensions/HelperMacros.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "clientlibs/gatewaydetection/GatewayDetectionClient.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

std::vector<GatewayEvent> allEvents(GatewayDetectionClient& detection) {
  std::vector<GatewayEvent> events;
  waitUntil(
      [&] {
        GatewayEventBatch batch = detection.eventsSince(events.empty() ? 0 : events.back().id, 50);
        for (GatewayEvent& e : batch.events) events.push_back(std::move(e));
        return batch.events.empty() && batch.endOfData;
      },
      "the gateway events to end", std::chrono::seconds(120));
  return events;
}

}  // namespace

class GatewayDetectionIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GatewayDetectionIntegrationTest);
  CPPUNIT_TEST(testEventsLookupsAndResume);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testEventsLookupsAndResume() {
    const std::string models = std::string(std::getenv("RGNAV_ROOT")) + "/config/gateways/gateway-hmms.txt";
    TestCluster cluster({{"LogPlayback", playbackCommand(intelLog()), {"Laser", "Base"}},
                         {"GatewayDetection",
                          {TestCluster::program("rgnav-gatewaydetection"), "--config",
                           TestCluster::moduleConfig("gatewaydetection"), "--models", models},
                          {"GatewayDetection"},
                          {"LogPlayback"}}},
                        kFastBackoff);
    cluster.start();
    GatewayDetectionClient detection(cluster.clientSettings());
    CPPUNIT_ASSERT(detection.detectsHallways());
    const std::vector<GatewayEvent> events = allEvents(detection);
    CPPUNIT_ASSERT_EQUAL(DataId(kIntelScans), detection.lastProcessedScan());

    std::set<DetectorGatewayId> detected;
    std::size_t traversals = 0, passages = 0, hallways = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
      const GatewayEvent& e = events[i];
      CPPUNIT_ASSERT_EQUAL(GatewayEventId(i + 1), e.id);
      if (e.kind == GatewayEventKind::Detected) {
        CPPUNIT_ASSERT(detected.insert(e.gateway.id).second);
        (e.gateway.kind == GatewayKind::NarrowPassage ? passages : hallways) += 1;
      } else {
        CPPUNIT_ASSERT(detected.count(e.gateway.id) == 1);
        traversals += e.kind == GatewayEventKind::Traversed;
      }
    }
    CPPUNIT_ASSERT(passages >= 3);
    CPPUNIT_ASSERT(hallways >= 1);
    CPPUNIT_ASSERT(traversals >= 3);

    const std::vector<GatewayRecord> gateways = detection.gateways();
    CPPUNIT_ASSERT_EQUAL(detected.size(), gateways.size());
    CPPUNIT_ASSERT(detection.gateway(gateways.back().id) == gateways.back());
    CPPUNIT_ASSERT_THROW(detection.gateway(DetectorGatewayId(gateways.back().id.value() + 1000)), NotAvailableError);

    CPPUNIT_ASSERT(std::filesystem::exists(cluster.dir() + "/run/state/GatewayDetection/gateways.state"));
    const auto old = cluster.describe("GatewayDetection");
    cluster.watchdog().restartModule("GatewayDetection");
    cluster.waitFor("GatewayDetection", runningAgainAfter(old.pid), "restarted");
    CPPUNIT_ASSERT(allEvents(detection) == events);
    CPPUNIT_ASSERT(detection.gateways() == gateways);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(GatewayDetectionIntegrationTest);
