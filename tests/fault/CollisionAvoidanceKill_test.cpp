// Killing the motion modules while the robot drives (issue "Motion"): the Collision Avoidance
// drives given targets down the office's main hallway (the simulator in real time, no people, the
// CAM on the true pose). The CAM is SIGKILLed while the robot runs: the Low-Level Drive finishes
// the chain it has and the robot stands; the CAM the watchdog restarts resumes the same drive
// from its checkpoint (same request, the targets it had not passed). Then the Low-Level Drive is
// SIGKILLed while the robot runs: within the Base's command timeout (0.5 s) plus braking the robot
// stands or is driven by the restarted drive, through which the CAM drives on. The drive ends reached with the true
// pose within 0.3 m of the last target, having been one drive throughout.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include <cmath>
#include <cstdio>

#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"
#include "clientlibs/lowleveldrive/LowLevelDriveClient.h"
#include "tests/eval/crowd/CrowdSet.h"
#include "tests/eval/crowd/TruePoseProbe.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

// The robot's true speed between two scans at least 0.1 s apart.
double trueSpeed(TruePoseProbe& truth) {
  const TrueSample a = truth.latest();
  TrueSample b = a;
  waitUntil([&] { return (b = truth.latest()).scan > a.scan; }, "a new scan", std::chrono::seconds(5),
            std::chrono::milliseconds(10));
  return std::hypot(b.pose.x - a.pose.x, b.pose.y - a.pose.y) / (0.1 * double(b.scan - a.scan));
}

}  // namespace

class CollisionAvoidanceKillTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CollisionAvoidanceKillTest);
  CPPUNIT_TEST(driveSurvivesKillsOfBothModules);
  CPPUNIT_TEST_SUITE_END();

 public:
  void driveSurvivesKillsOfBothModules() {
    CrowdSetOptions options;
    options.world = "config/worlds/office.yaml";
    options.simConfig = "config/sim/default.yaml";
    options.start = {1.5, 7.0, 0.0};
    options.people = 0;
    options.setYaml = kFastBackoff;
    CrowdSet set(options, nullptr);
    set.start();
    TestCluster& cluster = set.cluster();
    CollisionAvoidanceClient cam(cluster.clientSettings());
    TruePoseProbe truth(cluster.clientSettings());

    std::vector<TargetPose> targets;
    for (double x = 3.0; x <= 29.0; x += 2.0) targets.push_back({{x, 7.0, 0.0}, RegionId(1)});
    const DriveProgress started = cam.followTargets(targets);

    // The CAM killed while the robot runs: the robot comes to a stand on the drive's last chain
    // or is driven on by the restarted CAM, which resumes the same drive.
    waitUntil([&] { return truth.latest().pose.x > 6.0 && trueSpeed(truth) > 0.5; }, "the robot to run",
              std::chrono::seconds(30), std::chrono::milliseconds(50));
    const ModuleProcessInfo avoidance = cluster.describe("CollisionAvoidance");
    ::kill(static_cast<pid_t>(avoidance.pid), SIGKILL);
    cluster.waitFor("CollisionAvoidance", [&](const ModuleProcessInfo& m) {
      return m.state == ProcessState::Running && m.pid != avoidance.pid;
    }, "restarted");
    const DriveProgress resumed = cam.driveStatus();
    std::printf("\nCollisionAvoidance pid %lld killed at x=%.2f: restarted as pid %lld, drive %s at target %u of %u\n",
                static_cast<long long>(avoidance.pid), truth.latest().pose.x,
                static_cast<long long>(cluster.describe("CollisionAvoidance").pid), toString(resumed.phase).c_str(),
                resumed.targetIndex, resumed.targetCount);
    CPPUNIT_ASSERT_EQUAL(started.request, resumed.request);
    CPPUNIT_ASSERT(resumed.active());
    CPPUNIT_ASSERT(resumed.targetIndex > 0);  // the targets passed before the kill stay passed

    // The drive killed while the robot runs: it stands within the command timeout plus braking.
    waitUntil([&] { return truth.latest().pose.x > 16.0 && trueSpeed(truth) > 0.5; }, "the robot to run again",
              std::chrono::seconds(60), std::chrono::milliseconds(50));
    const ModuleProcessInfo drive = cluster.describe("LowLevelDrive");
    const double speed = trueSpeed(truth);
    const TrueSample killedAt = truth.latest();
    ::kill(static_cast<pid_t>(drive.pid), SIGKILL);
    // Stands, or is driven again by the restarted drive (commanded by a live module), within the
    // command timeout plus braking.
    LowLevelDriveClient restarted(cluster.clientSettings());
    std::string how;
    TrueSample safe = killedAt;
    waitUntil([&] {
      safe = truth.latest();
      if (trueSpeed(truth) < 0.02) {
        how = "stood";
        return true;
      }
      const ModuleProcessInfo now = cluster.describe("LowLevelDrive");
      if (now.state != ProcessState::Running || now.pid == drive.pid) return false;
      try {
        if (restarted.driveStatus().commandsSent > 0) {
          how = "was driven by the restarted drive";
          return true;
        }
      } catch (const ModuleUnavailableError&) {
      }
      return false;
    }, "the robot to stand or be driven again", std::chrono::seconds(10), std::chrono::milliseconds(10));
    const double safeAfter = 0.1 * double(safe.scan - killedAt.scan);
    const double bound = 0.5 + speed / 0.5 + 0.3;
    std::printf("LowLevelDrive pid %lld killed at %.2f m/s: the robot %s %.1f s (simulated) later (bound %.1f s)\n",
                static_cast<long long>(drive.pid), speed, how.c_str(), safeAfter, bound);
    CPPUNIT_ASSERT(safeAfter <= bound);

    waitUntil([&] { return cam.driveStatus().phase == DrivePhase::Reached; }, "the drive to be reached",
              std::chrono::seconds(90), std::chrono::milliseconds(100));
    const TrueSample end = truth.latest();
    const DriveProgress reached = cam.driveStatus();
    const double error = std::hypot(end.pose.x - targets.back().pose.x, end.pose.y - targets.back().pose.y);
    std::printf("drive %llu reached after both kills: true pose %.3f m from the last target, %llu chains\n",
                static_cast<unsigned long long>(reached.request), error,
                static_cast<unsigned long long>(reached.chainsSent));
    CPPUNIT_ASSERT_EQUAL(started.request, reached.request);
    CPPUNIT_ASSERT(error <= 0.3);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CollisionAvoidanceKillTest);
