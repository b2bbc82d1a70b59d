// The Localization module through a real server set: the simulator in lock-step on its room tour
// of the office floor, the RG Mapping Kernel holding the map of the tour's first part (mapped in
// process at the true poses, so in the world frame, and loaded from a checkpoint placed in the
// kernel's state directory, as in PlanningSet.h), and the Localization module. Without particles
// the module answers NotLocalized; after setPose at the robot's true pose its estimate of every
// scan follows the simulated robot within a bound (ground truth is read by the test only). After
// a SIGKILL the restarted module resumes its particle set from its checkpoint: without a new
// setPose it goes on localizing, as well as before. Bad arguments (a NaN pose, a negative or NaN
// sigma, ID 0, count 0) are refused naming the field, and the kernel takes a traversal report for
// a gateway of its map once per request and refuses one for a gateway it does not have.
#include <cppunit/extensions/HelperMacros.h>

#include <signal.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

#include "Localization.hh"
#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "clientlibs/localization/LocalizationClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/common/AtomicFile.h"
#include "core/config/ShippedConfig.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/SimulationConfigYaml.h"
#include "core/sim/TourRun.h"
#include "tests/eval/rooms/MappingPipeline.h"
#include "tests/integration/IntegrationHelpers.h"
#include "tests/support/WaitUntil.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

constexpr std::uint64_t kSeed = 3;
constexpr double kMappedSeconds = 300.0;  // of the tour: the robot stays in this part while the test runs
constexpr DataId kFollowedScans = 400;    // 40 s of the tour
// Bounds on the estimate's error: the map is exact, the odometry noise the simulator's default.
constexpr double kMaxTransErrM = 0.3, kMaxRotErrRad = 0.15, kMeanTransErrM = 0.1;

SimulationConfig simulation() {
  SimulationConfig config = loadSimulationConfig(shippedConfigFile("sim/default.yaml"));
  config.seed = kSeed;
  return config;
}

// The kernel's checkpoint (map and scan journal) of the tour's first kMappedSeconds, mapped at
// the true poses; and the number of its regions. Made once for the tests.
struct OfficeMap {
  std::string state, journal;
  std::size_t regions = 0;
  std::vector<GatewayView> gateways;
};

const OfficeMap& officeMap() {
  static const OfficeMap map = [] {
    const LoadedWorld world = loadWorld(shippedConfigFile("worlds/office.yaml"));
    MappingPipeline pipeline(shippedPipelineConfig(), std::nullopt);
    driveRoomTour(
        world.grid, *world.truth, simulation(),
        [&](const SimulationStep& s) {
          if (s.scan) pipeline.addScanAt(*s.scan, s.truePose);
        },
        kMappedSeconds);
    pipeline.finish();
    const RgMapState& state = pipeline.kernel().state();
    return OfficeMap{serializeRgMap(state), scanJournalLines(state), state.regions.size(),
                     gatewayViews(pipeline.kernel())};
  }();
  return map;
}

std::unique_ptr<TestCluster> localizationSet() {
  const std::string world = shippedConfigFile("worlds/office.yaml");
  auto cluster = std::make_unique<TestCluster>(std::vector<ClusterModule>{
      {"Simulator",
       {TestCluster::program("rgnav-sim"), "--world", world, "--config", shippedConfigFile("sim/default.yaml"),
        "--clock", "lockstep", "--tour", "--seed", std::to_string(kSeed)},
       {"Laser", "Base", "GroundTruth"}},
      {"RGMappingKernel",
       {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
       {"RGMappingKernel"}},
      {"Localization",
       {TestCluster::program("rgnav-localization"), "--config", TestCluster::moduleConfig("localization"),
        "--checkpoint-interval", "0.2"},
       {"Localization"},
       {"Simulator", "RGMappingKernel"},
       "max_restarts: 10"}});
  const std::string dir = cluster->dir() + "/run/state/RGMappingKernel";
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir + "/rgmap.state", officeMap().state);
  writeFileAtomically(dir + "/rgmap.state.scans", officeMap().journal);
  return cluster;
}

void waitForMap(LocalizationClient& localization) {
  waitUntil([&] { return localization.filterState().mapRegions == officeMap().regions; },
            "the module's copy of the kernel's map", std::chrono::seconds(60), std::chrono::milliseconds(50));
}

// The module never advances the lock-step simulator (the mapping chain does in the demo): the test
// pulls the scans up to `scan` itself, as a consumer that has every scan, and waits for the module.
void waitForScan(LaserClient& laser, LocalizationClient& localization, DataId scan, const std::string& what) {
  waitUntil(
      [&] {
        for (DataId latest = laser.latestId(); latest < scan; latest = laser.latestId()) laser.scansSince(latest, 1);
        return localization.filterState().lastScan >= scan;
      },
      what, std::chrono::seconds(180), std::chrono::milliseconds(50));
}

// The estimates of scans first..last (every 5th) against the true poses; fails beyond the bounds.
void expectFollows(LocalizationClient& localization, GroundTruthClient& truth, DataId first, DataId last,
                   const std::string& what) {
  double sum = 0.0, worst = 0.0, worstRot = 0.0;
  std::size_t n = 0;
  for (DataId id = first; id <= last; id += 5) {
    const ScanEstimate e = localization.estimateByScan(id);
    const Pose2D t = truth.truePose(id);
    CPPUNIT_ASSERT_EQUAL(id, e.scanId);
    CPPUNIT_ASSERT(e.estimate.scanId <= id);
    const double err = std::hypot(e.estimate.mapPose.x - t.x, e.estimate.mapPose.y - t.y);
    const double rot = std::abs(normalizeAngle(e.estimate.mapPose.theta - t.theta));
    sum += err;
    worst = std::max(worst, err);
    worstRot = std::max(worstRot, rot);
    ++n;
  }
  std::cout << "\nlocalization " << what << ": scans " << first << ".." << last << " trans_err_m mean " << sum / n
            << " max " << worst << " rot_err_rad max " << worstRot << std::endl;
  CPPUNIT_ASSERT_MESSAGE(what, worst < kMaxTransErrM);
  CPPUNIT_ASSERT_MESSAGE(what, worstRot < kMaxRotErrRad);
  CPPUNIT_ASSERT_MESSAGE(what, sum / n < kMeanTransErrM);
}

}  // namespace

class LocalizationIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LocalizationIntegrationTest);
  CPPUNIT_TEST(testFollowsTheRobotAndResumesAfterAKill);
  CPPUNIT_TEST(testBadArgumentsAndTraversalReports);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testFollowsTheRobotAndResumesAfterAKill() {
    const std::unique_ptr<TestCluster> cluster = localizationSet();
    cluster->start();
    LocalizationClient localization(cluster->clientSettings());
    GroundTruthClient truth(cluster->clientSettings());
    LaserClient laser(cluster->clientSettings());
    waitForMap(localization);
    CPPUNIT_ASSERT_THROW(localization.latestEstimate(), NotLocalizedError);
    CPPUNIT_ASSERT_THROW(localization.particles(10), NotLocalizedError);

    laser.scansSince(0, 1);  // the first scan
    const DataId start = laser.latestId();
    localization.setPose(truth.truePose(start), {0.1, 0.1, 0.05});
    waitForScan(laser, localization, start + kFollowedScans, "the module to localize the first scans");
    expectFollows(localization, truth, start + 20, start + kFollowedScans, "after setPose");
    const ParticleSnapshotView snapshot = localization.particles(50);
    CPPUNIT_ASSERT(snapshot.total >= 100 && snapshot.particles.size() == std::min<std::size_t>(50, snapshot.total));
    CPPUNIT_ASSERT(snapshot.particles.front().particle.weight >= snapshot.particles.back().particle.weight);

    // Kill it once it has checkpointed a later update than the first (the writes are paced by how
    // long they take, CheckpointPacer.h: the test goes on pulling scans meanwhile).
    waitUntil(
        [&] {
          laser.scansSince(laser.latestId(), 1);
          return localization.status().counters["checkpoint_scan"] > start + 100;
        },
        "a checkpoint after the first 100 scans", std::chrono::seconds(60), std::chrono::milliseconds(5));
    const std::uint64_t checkpointed = localization.status().counters["checkpoint_scan"];
    const ModuleProcessInfo before = cluster->describe("Localization");
    const DataId killedAt = localization.filterState().lastScan;
    CPPUNIT_ASSERT_EQUAL(0, ::kill(static_cast<pid_t>(before.pid), SIGKILL));
    cluster->waitFor("Localization", runningAgainAfter(before.pid), "the restart", std::chrono::seconds(30));
    // Without its checkpoint the restarted module would hold no particles and take no scans.
    waitForScan(laser, localization, killedAt + 200, "the restarted module to localize on");
    CPPUNIT_ASSERT(localization.filterState().initialised);
    const std::uint64_t resumedAfter = localization.status().counters["resumed_after_scan"];
    std::cout << "localization: checkpointed scan " << checkpointed << ", killed after scan " << killedAt
              << ", resumed after scan " << resumedAfter << std::endl;
    // The last checkpoint before the kill (it may have written a later one than the test saw).
    CPPUNIT_ASSERT(resumedAfter >= checkpointed && resumedAfter <= killedAt);
    expectFollows(localization, truth, killedAt + 20, killedAt + 200, "after the restart");
  }

  void testBadArgumentsAndTraversalReports() {
    const std::unique_ptr<TestCluster> cluster = localizationSet();
    cluster->start();
    LocalizationClient localization(cluster->clientSettings());
    waitForMap(localization);
    TypedConnection<RGNav::Localization> raw("Localization", cluster->clientSettings());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto setPose = [&](const RGNav::Pose2D& pose, const RGNav::PoseSigma& sigma) {
      return refusedField([&] {
        raw.call("setPose", [&](RGNav::Localization_ptr l) { l->setPose(pose, sigma, 0); });
      });
    };
    const RGNav::Pose2D good{2.0, 7.0, 0.0};
    CPPUNIT_ASSERT_EQUAL(std::string("mapPose"), setPose({nan, 7.0, 0.0}, {0.1, 0.1, 0.1}));
    CPPUNIT_ASSERT_EQUAL(std::string("mapPose"), setPose({2.0, 7.0, std::numeric_limits<double>::infinity()}, {0.1, 0.1, 0.1}));
    CPPUNIT_ASSERT_EQUAL(std::string("sigma.x"), setPose(good, {-0.1, 0.1, 0.1}));
    CPPUNIT_ASSERT_EQUAL(std::string("sigma.y"), setPose(good, {0.1, -1e-9, 0.1}));
    CPPUNIT_ASSERT_EQUAL(std::string("sigma.theta"), setPose(good, {0.1, 0.1, nan}));
    CPPUNIT_ASSERT_EQUAL(std::string("scanId"), refusedField([&] {
                           raw.call("estimateByScan", [](RGNav::Localization_ptr l) { l->estimateByScan(0); });
                         }));
    CPPUNIT_ASSERT_EQUAL(std::string("maxCount"), refusedField([&] {
                           raw.call("particles", [](RGNav::Localization_ptr l) { delete l->particles(0); });
                         }));
    // None of them set particles; a pose outside every region is NotAvailable.
    CPPUNIT_ASSERT(!localization.filterState().initialised);
    CPPUNIT_ASSERT_THROW(localization.setPose({-50.0, -50.0, 0.0}, {0.1, 0.1, 0.1}), NotAvailableError);
    CPPUNIT_ASSERT(!localization.filterState().initialised);
    localization.relocalize();
    CPPUNIT_ASSERT(localization.filterState().initialised);

    // The kernel counts a traversal of a gateway between two of its regions, and refuses others.
    RgMappingKernelClient kernel(cluster->clientSettings());
    const GatewayView* door = nullptr;
    for (const GatewayView& g : officeMap().gateways)
      if (!g.neutralised && !g.sideA.isNone() && !g.sideB.isNone() && g.sideA != g.sideB) door = &g;
    CPPUNIT_ASSERT(door != nullptr);
    TypedConnection<RGNav::RGMappingKernel> rawKernel("RGMappingKernel", cluster->clientSettings());
    for (int twice = 0; twice < 2; ++twice)  // one request ID: counted once
      rawKernel.call("reportTraversal", [&](RGNav::RGMappingKernel_ptr k) {
        k->reportTraversal(77, door->id.value(), door->sideA.value(), door->sideB.value(), 12);
      });
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(1), kernel.status().counters["traversals_reported"]);
    kernel.reportTraversal(door->id, door->sideB, door->sideA, 13);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(2), kernel.status().counters["traversals_reported"]);
    CPPUNIT_ASSERT_THROW(kernel.reportTraversal(GatewayId(100000), door->sideA, door->sideB, 12), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(kernel.reportTraversal(door->id, door->sideA, door->sideA, 12), InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(2), kernel.status().counters["traversals_reported"]);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LocalizationIntegrationTest);
