// The CollisionAvoidance module's map frame from the mapping modules (servers/collisionavoidance/
// MapFrameSource.h) through real server sets: the simulator in real time on the office floor with
// its default odometry noise, starting at the main hallway's west end (the ScanMapper's map frame
// starts at the first scan's odometry pose, which the simulator starts at the true pose, so the map
// frame is close to the world frame), the ScanMapper, the Low-Level Drive and the CAM:
//  - pose source scanmapper: targets in the map frame down the hallway are driven to the end;
//  - pose source localization: the same with GatewayDetection, the RG Mapping Kernel building the
//    map online and the Localization module localizing in it from the first scan's odometry pose,
//    as in the navigating demo's set.
// Each time the drive is reported reached, the true pose is within 0.3 m of the last target, and
// the module read its frame from the source (health frame_refreshes, no pose_source error). Before
// the change, the module refused both pose sources and did not start.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <cstdio>

#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"
#include "core/config/ShippedConfig.h"
#include "tests/eval/crowd/TruePoseProbe.h"
#include "tests/support/WaitUntil.h"
#include "tests/support/cluster/TestCluster.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

std::vector<ClusterModule> poseSourceSet(const std::string& source) {
  std::vector<ClusterModule> modules{
      {"Simulator",
       {TestCluster::program("rgnav-sim"), "--world", shippedConfigFile("worlds/office.yaml"), "--config",
        shippedConfigFile("sim/default.yaml"), "--clock", "realtime", "--start", "1.5,7,0"},
       {"Laser", "Base", "GroundTruth"}},
      {"ScanMapper", {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
       {"ScanMapper"},
       {"Simulator"}},
      {"LowLevelDrive",
       {TestCluster::program("rgnav-lowleveldrive"), "--config", TestCluster::moduleConfig("lowleveldrive")},
       {"LowLevelDrive"},
       {"Simulator"}},
      {"CollisionAvoidance",
       {TestCluster::program("rgnav-collisionavoidance"), "--config", TestCluster::moduleConfig("collisionavoidance"),
        "--pose-source", source},
       {"CollisionAvoidance"},
       {"LowLevelDrive"}}};
  if (source == "localization") {
    modules.push_back({"GatewayDetection",
                       {TestCluster::program("rgnav-gatewaydetection"), "--config",
                        TestCluster::moduleConfig("gatewaydetection")},
                       {"GatewayDetection"},
                       {"Simulator"}});
    modules.push_back({"RGMappingKernel",
                       {TestCluster::program("rgnav-rgmappingkernel"), "--config",
                        TestCluster::moduleConfig("rgmappingkernel")},
                       {"RGMappingKernel"},
                       {"ScanMapper", "GatewayDetection"}});
    modules.push_back({"Localization",
                       {TestCluster::program("rgnav-localization"), "--config", TestCluster::moduleConfig("localization"),
                        "--start-at-odometry", "--mapped-scans-only"},
                       {"Localization"},
                       {"RGMappingKernel"}});
  }
  return modules;
}

}  // namespace

class PoseSourceIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PoseSourceIntegrationTest);
  CPPUNIT_TEST(drivesInTheScanMappersFrame);
  CPPUNIT_TEST(drivesInTheLocalizationsFrame);
  CPPUNIT_TEST_SUITE_END();

 public:
  void drivesInTheScanMappersFrame() { drivesDownTheHallway("scanmapper"); }
  void drivesInTheLocalizationsFrame() { drivesDownTheHallway("localization"); }

 private:
  static void drivesDownTheHallway(const std::string& source) {
    TestCluster cluster(poseSourceSet(source));
    cluster.start();
    CollisionAvoidanceClient cam(cluster.clientSettings());
    TruePoseProbe truth(cluster.clientSettings());
    const std::vector<TargetPose> targets{{{3.0, 7.0, 0.0}, RegionId(1)},
                                          {{5.0, 7.0, 0.0}, RegionId(1)},
                                          {{7.0, 7.0, 0.0}, RegionId(1)}};
    cam.followTargets(targets);
    const bool arrived = pollUntil([&] { return cam.driveStatus().phase == DrivePhase::Reached; },
                                   std::chrono::seconds(90), std::chrono::milliseconds(100));
    const TrueSample end = truth.latest();
    const ModuleStatusInfo status = cam.status();
    const double error = std::hypot(end.pose.x - 7.0, end.pose.y - 7.0);
    std::printf("\npose source %s: drive %s at true (%.3f, %.3f), %.3f m from the last target, %llu frame refreshes%s%s\n",
                source.c_str(), toString(cam.driveStatus().phase).c_str(), end.pose.x, end.pose.y, error,
                static_cast<unsigned long long>(status.counters.count("frame_refreshes")
                                                    ? status.counters.at("frame_refreshes")
                                                    : 0),
                status.lastError.empty() ? "" : ", last error: ", status.lastError.c_str());
    CPPUNIT_ASSERT_MESSAGE("the targets reached", arrived);
    CPPUNIT_ASSERT(error <= 0.3);
    CPPUNIT_ASSERT(status.counters.at("frame_refreshes") > 0);
    CPPUNIT_ASSERT(status.lastError.find("pose_source") == std::string::npos);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PoseSourceIntegrationTest);
