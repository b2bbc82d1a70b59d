// The RG Mapping Kernel module through the real server set (playback -> ScanMapper ->
// GatewayDetection -> kernel): the maps of the Intel, Freiburg 079 and Freiburg 101 logs end
// structurally consistent (references both ways, a gateway joins at most two regions, neutralised
// exactly when both sides are the same region, no empty region); on Intel, regions and paths are
// served, naming and merging work, the exported files exist, a restart by the operator resumes
// from the checkpoint with the same map, and a forced merge made before it is undone after it; and a kernel that lags far behind (small
// fetches) still ends with exactly the state the in-process chain gives (MappingPipeline), on
// Freiburg 079 with its dozens of pose revisions: the map does not depend on the modules' timing.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "core/logs/OpenLog.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "tests/eval/rooms/MappingPipeline.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

// The message of the ModuleFailedError a call ends in; "(accepted)" if it succeeded.
template <class F>
std::string failureOf(F&& call) {
  try {
    call();
  } catch (const ModuleFailedError& e) {
    return e.what();
  }
  return "(accepted)";
}

void assertContains(const std::string& message, const std::string& part) {
  CPPUNIT_ASSERT_MESSAGE("'" + part + "' not in: " + message, message.find(part) != std::string::npos);
}

std::string modelsFile() { return std::string(std::getenv("RGNAV_ROOT")) + "/config/gateways/gateway-hmms.txt"; }

// `kernelFetch`: records the kernel asks from each input per call.
std::vector<ClusterModule> mappingSet(const std::string& log, const std::string& kernelFetch = "100") {
  return {{"LogPlayback", playbackCommand(log), {"Laser", "Base"}},
          {"ScanMapper", {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
           {"ScanMapper"},
           {"LogPlayback"}},
          {"GatewayDetection",
           {TestCluster::program("rgnav-gatewaydetection"), "--config", TestCluster::moduleConfig("gatewaydetection"),
            "--models", modelsFile()},
           {"GatewayDetection"},
           {"LogPlayback"}},
          {"RGMappingKernel",
           {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel"),
            "--fetch", kernelFetch},
           {"RGMappingKernel"},
           {"ScanMapper", "GatewayDetection"}}};
}

// The kernel state of the in-process chain on every scan of `log`, with the modules' shipped
// parameters (as the server set).
RgMapState inProcessState(const std::string& log) {
  MappingPipeline pipeline(shippedPipelineConfig(), loadHmmModels(modelsFile()));
  const std::unique_ptr<LogSource> source = openLog(log);
  while (const std::optional<LogRecord> record = source->next())
    if (const auto* scan = std::get_if<LaserScan>(&*record)) pipeline.addScan(*scan);
  pipeline.finish();
  return pipeline.kernel().state();
}

// The kernel module's last checkpoint in `cluster`, serialised again.
std::string checkpointedState(const TestCluster& cluster) {
  const std::string file = cluster.dir() + "/run/state/RGMappingKernel/rgmap.state";
  return serializeRgMap(deserializeRgMap(readFile(file), readFile(file + ".scans")));
}

MapSummaryView waitForEnd(RgMappingKernelClient& kernel) {
  MapSummaryView summary;
  waitUntil(
      [&] {
        summary = kernel.summary();
        return summary.endOfData;
      },
      "the map to be finished", std::chrono::minutes(5), std::chrono::milliseconds(50));
  return summary;
}

// Every structural invariant of the issue, checked on what the module serves.
void checkInvariants(const std::vector<RegionSummaryView>& regions, const std::vector<GatewayView>& gateways) {
  std::map<RegionId, std::set<GatewayId>> byRegion;
  for (const RegionSummaryView& r : regions) {
    CPPUNIT_ASSERT_MESSAGE("empty region " + std::to_string(r.id.value()), r.scans > 0);
    byRegion[r.id] = std::set<GatewayId>(r.gateways.begin(), r.gateways.end());
  }
  for (const GatewayView& g : gateways) {
    for (const RegionId side : {g.sideA, g.sideB}) {
      if (side.isNone()) continue;
      CPPUNIT_ASSERT_MESSAGE("gateway " + std::to_string(g.id.value()) + " names unknown region", byRegion.count(side) == 1);
      CPPUNIT_ASSERT_MESSAGE("region does not list gateway " + std::to_string(g.id.value()), byRegion[side].count(g.id) == 1);
    }
    CPPUNIT_ASSERT_EQUAL(!g.sideA.isNone() && g.sideA == g.sideB, g.neutralised);
  }
  for (const auto& [region, listed] : byRegion)
    for (const GatewayId id : listed) {
      const auto g = std::find_if(gateways.begin(), gateways.end(), [&](const GatewayView& v) { return v.id == id; });
      CPPUNIT_ASSERT(g != gateways.end());
      CPPUNIT_ASSERT(g->sideA == region || g->sideB == region);
    }
}

}  // namespace

class RgMappingKernelIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMappingKernelIntegrationTest);
  CPPUNIT_TEST(testIntelMapQueriesExportAndResume);
  CPPUNIT_TEST(testFreiburgMapsAreConsistent);
  CPPUNIT_TEST(testLaggingKernelMapsAsTheInProcessChain);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testIntelMapQueriesExportAndResume() {
    TestCluster cluster(mappingSet(intelLog()), kFastBackoff);
    cluster.start();
    RgMappingKernelClient kernel(cluster.clientSettings());
    const MapSummaryView summary = waitForEnd(kernel);
    CPPUNIT_ASSERT_EQUAL(DataId(kIntelScans), summary.lastScan);
    CPPUNIT_ASSERT(summary.regions >= 3);
    CPPUNIT_ASSERT(summary.gateways >= 3);

    const std::vector<RegionSummaryView> regions = kernel.regions();
    const std::vector<GatewayView> gateways = kernel.gateways();
    CPPUNIT_ASSERT_EQUAL(summary.regions, regions.size());
    checkInvariants(regions, gateways);

    const RegionView first = kernel.region(regions.front().id);
    CPPUNIT_ASSERT(!first.lines.empty());
    CPPUNIT_ASSERT(first.areaM2 > 1.0);
    CPPUNIT_ASSERT(first.freespace.width > 0 && !first.freespace.bytes.empty());
    CPPUNIT_ASSERT_EQUAL(summary.current, kernel.currentRegion().summary.id);
    CPPUNIT_ASSERT_THROW(kernel.region(RegionId{100000}), NotAvailableError);

    // A path between two regions joined by a gateway.
    const GatewayView joined = *std::find_if(gateways.begin(), gateways.end(), [](const GatewayView& g) {
      return !g.sideA.isNone() && !g.sideB.isNone() && !g.neutralised;
    });
    const PathView path = kernel.findPath(joined.sideA, joined.crossingPoints[0], joined.sideB, joined.crossingPoints[1]);
    CPPUNIT_ASSERT(path.lengthM > 0.0 && path.costM >= path.lengthM - 1e-9);
    CPPUNIT_ASSERT(!kernel.graph().nodes.empty());

    kernel.nameRegion(joined.sideA, "start room");
    CPPUNIT_ASSERT_EQUAL(joined.sideA, kernel.regionByName("start room"));
    CPPUNIT_ASSERT_THROW(kernel.regionByName("nowhere"), NotAvailableError);
    CPPUNIT_ASSERT_THROW(kernel.mergeRegions(joined.sideA, joined.sideA), InvalidArgumentError);

    // Two regions with no gateway between them are refused through the wire unless forced.
    const auto joins = [&](RegionId a, RegionId b) {
      return std::any_of(gateways.begin(), gateways.end(), [&](const GatewayView& g) {
        return (g.sideA == a && g.sideB == b) || (g.sideA == b && g.sideB == a);
      });
    };
    std::optional<std::pair<RegionId, RegionId>> apart;
    for (const RegionSummaryView& a : regions)
      for (const RegionSummaryView& b : regions)
        if (!apart && a.id != b.id && !joins(a.id, b.id)) apart = std::pair(a.id, b.id);
    CPPUNIT_ASSERT_MESSAGE("Intel has regions with no gateway between them", apart.has_value());
    CPPUNIT_ASSERT_THROW(kernel.mergeRegions(apart->first, apart->second), InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(regions.size(), kernel.regions().size());

    // A 2D object named through the client library (and still named after the restart below).
    RegionView furnished;
    for (const RegionSummaryView& r : kernel.regions())
      if (furnished.objects.empty()) furnished = kernel.region(r.id);
    CPPUNIT_ASSERT(!furnished.objects.empty());
    const Pose2D object = furnished.objects.front().pose;
    kernel.nameObject(furnished.summary.id, {object.x, object.y}, "first object");
    CPPUNIT_ASSERT_EQUAL(std::string("first object"), kernel.region(furnished.summary.id).objects.front().name);
    CPPUNIT_ASSERT_EQUAL(furnished.summary.id, kernel.objectByName("first object").region);
    CPPUNIT_ASSERT_THROW(kernel.objectByName("nothing"), NotAvailableError);
    CPPUNIT_ASSERT_THROW(kernel.nameObject(RegionId{100000}, {0.0, 0.0}, "nothing"), InvalidArgumentError);

    // Exports go below the kernel's export root (by default <run dir>/exports), nowhere else.
    const std::string files = kernel.exportMap("maps", "intel", true);
    for (const char* suffix : {"intel.rgmap.json", "intel.rgmap.svg", "intel.rgmap.png", "intel.pgm", "intel.yaml"})
      CPPUNIT_ASSERT_MESSAGE(suffix, std::filesystem::exists(cluster.dir() + "/run/exports/maps/" + suffix));
    CPPUNIT_ASSERT_EQUAL(std::string("directory"), refusedField([&] { kernel.exportMap(cluster.dir() + "/out", "x", false); }));
    CPPUNIT_ASSERT_EQUAL(std::string("directory"), refusedField([&] { kernel.exportMap("../../out", "x", false); }));
    CPPUNIT_ASSERT_EQUAL(std::string("name"), refusedField([&] { kernel.exportMap("", "../x", false); }));
    CPPUNIT_ASSERT(!std::filesystem::exists(cluster.dir() + "/out"));
    // Exporting over existing files replaces them; a file the kernel cannot write is an error
    // that names the file and the cause, never a bare exception name.
    CPPUNIT_ASSERT_EQUAL(files, kernel.exportMap("maps", "intel", true));
    std::filesystem::create_directories(cluster.dir() + "/run/exports/maps/blocked.rgmap.json");
    const std::string blocked = failureOf([&] { kernel.exportMap("maps", "blocked", false); });
    assertContains(blocked, "RGMappingKernel.exportMap: ");
    assertContains(blocked, "/run/exports/maps/blocked.rgmap.json");
    assertContains(blocked, "Is a directory");

    // A module that is not registered is reported within the first-contact budget, naming the
    // name looked up and the naming service asked.
    ClientSettings shortFirstContact = cluster.clientSettings();
    shortFirstContact.firstContactBudget = std::chrono::milliseconds(300);
    ClientConnection unbound("NoSuchModule", shortFirstContact);
    try {
      unbound.invoke("ping", Idempotence::Idempotent,
                     [](CORBA::Object_ptr object, std::uint64_t) { object->_non_existent(); });
      CPPUNIT_FAIL("NoSuchModule answered");
    } catch (const ModuleUnavailableError& e) {
      assertContains(e.what(), "NoSuchModule.ping: no answer within 300 ms from RGNav/" + shortFirstContact.robot +
                                   "/NoSuchModule in the naming service at 127.0.0.1:" +
                                   std::to_string(cluster.namingPort()));
      assertContains(e.what(), "not bound");
    }

    // Hostile arguments are typed answers naming the field, and the kernel stays up.
    const double nan = std::nan("");
    CPPUNIT_ASSERT_EQUAL(std::string("start"), refusedField([&] {
      kernel.findPath(joined.sideA, {nan, 0.0}, joined.sideB, joined.crossingPoints[1]);
    }));
    CPPUNIT_ASSERT_EQUAL(std::string("maxCount"), refusedField([&] { kernel.eventsSince(0, 0); }));
    CPPUNIT_ASSERT_EQUAL(std::string("name"), refusedField([&] { kernel.nameRegion(joined.sideB, std::string(5000, 'x')); }));
    CPPUNIT_ASSERT_EQUAL(std::string("id"), refusedField([&] { kernel.region(RegionId{0}); }));

    // A repeated request ID acts once: the second call, for another region, answers as the first
    // did and names nothing.
    TypedConnection<RGNav::RGMappingKernel> raw("RGMappingKernel", cluster.clientSettings());
    const auto nameOnce = [&](RegionId region) {
      raw.call("nameRegion", [&](RGNav::RGMappingKernel_ptr k) { k->nameRegion(4242, region.value(), "named once"); });
    };
    nameOnce(joined.sideA);
    nameOnce(joined.sideB);
    CPPUNIT_ASSERT_EQUAL(joined.sideA, kernel.regionByName("named once"));
    kernel.nameRegion(joined.sideA, "start room");

    const RgMapEventBatch events = kernel.eventsSince(0, 100000);
    for (std::size_t i = 0; i < events.events.size(); ++i) CPPUNIT_ASSERT_EQUAL(RgMapEventId(i + 1), events.events[i].id);

    // Two regions with no gateway between them merged by force before the restart ...
    const RegionId forcedInto = kernel.mergeRegions(apart->first, apart->second, true);

    const auto old = cluster.describe("RGMappingKernel");
    cluster.watchdog().restartModule("RGMappingKernel");
    cluster.waitFor("RGMappingKernel", runningAgainAfter(old.pid), "restarted");
    const MapSummaryView resumed = waitForEnd(kernel);
    CPPUNIT_ASSERT(resumed == kernel.summary());
    CPPUNIT_ASSERT_EQUAL(summary.regions - 1, resumed.regions);
    // ... are apart again after it, with their gateway sides and names; a repeated request ID
    // answers as the first call did without undoing anything more.
    const auto unmergeOnce = [&] {
      return raw.call("unmergeRegions", [&](RGNav::RGMappingKernel_ptr k) { return RegionId(k->unmergeRegions(4343, forcedInto.value())); });
    };
    CPPUNIT_ASSERT_EQUAL(std::max(apart->first, apart->second), unmergeOnce());
    CPPUNIT_ASSERT_EQUAL(std::max(apart->first, apart->second), unmergeOnce());
    CPPUNIT_ASSERT_THROW(kernel.unmergeRegions(forcedInto), InvalidArgumentError);
    const MapSummaryView undone = kernel.summary();
    CPPUNIT_ASSERT_EQUAL(summary.regions, undone.regions);
    CPPUNIT_ASSERT_EQUAL(summary.gateways, undone.gateways);
    CPPUNIT_ASSERT(kernel.gateways() == gateways);
    CPPUNIT_ASSERT_EQUAL(joined.sideA, kernel.regionByName("start room"));
    CPPUNIT_ASSERT_EQUAL(furnished.summary.id, kernel.objectByName("first object").region);
  }

  void testFreiburgMapsAreConsistent() {
    for (const char* log : {"freiburg-079-corrected.log.gz", "freiburg-101-corrected.log.gz"}) {
      TestCluster cluster(mappingSet(TestCluster::shared(std::string("data/laser/corrected/") + log)), kFastBackoff);
      cluster.start();
      RgMappingKernelClient kernel(cluster.clientSettings());
      const MapSummaryView summary = waitForEnd(kernel);
      CPPUNIT_ASSERT_MESSAGE(log, summary.regions >= 2 && summary.gateways >= 2);
      checkInvariants(kernel.regions(), kernel.gateways());
    }
  }

  void testLaggingKernelMapsAsTheInProcessChain() {
    const std::string log = TestCluster::shared("data/laser/corrected/freiburg-079-corrected.log.gz");
    TestCluster cluster(mappingSet(log, "7"), kFastBackoff);
    cluster.start();
    RgMappingKernelClient kernel(cluster.clientSettings());
    waitForEnd(kernel);
    const RgMapState expected = inProcessState(log);
    CPPUNIT_ASSERT(expected.lastPoseRevision > 20);  // many revisions to apply in order
    CPPUNIT_ASSERT(checkpointedState(cluster) == serializeRgMap(expected));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMappingKernelIntegrationTest);
