// The CollisionAvoidance module through the real server set (issue "Motion"): the simulator in real
// time on the office floor (no people), the Low-Level Drive, the CAM on the simulator's true pose,
// and a PathPlanning module whose kernel has no map. Given targets down the main hallway are
// driven to the end: the CAM reports them reached and the true pose is within 0.3 m of the last;
// the same request sent again answers that drive and starts none; a drive to a goal waits for the
// planner (no map yet) without failing and is cancelled to idle, after which the module reads no
// scans; no targets is refused naming "targets".
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <cstdio>

#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"
#include "tests/eval/crowd/CrowdSet.h"
#include "tests/eval/crowd/TruePoseProbe.h"
#include "tests/support/WaitUntil.h"

using namespace rgnav;
using namespace rgnav::testing;

class CollisionAvoidanceIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CollisionAvoidanceIntegrationTest);
  CPPUNIT_TEST(drivesGivenTargetsAndWaitsForThePlanner);
  CPPUNIT_TEST_SUITE_END();

 public:
  void drivesGivenTargetsAndWaitsForThePlanner() {
    CrowdSetOptions options;
    options.world = "config/worlds/office.yaml";
    options.simConfig = "config/sim/default.yaml";
    options.start = {1.5, 7.0, 0.0};
    options.people = 0;
    CrowdSet set(options, nullptr);
    set.start();
    CollisionAvoidanceClient cam(set.cluster().clientSettings());
    TruePoseProbe truth(set.cluster().clientSettings());
    CPPUNIT_ASSERT(cam.driveStatus().phase == DrivePhase::Idle);

    const std::vector<TargetPose> targets{{{3.0, 7.0, 0.0}, RegionId(1)},
                                          {{5.0, 7.0, 0.0}, RegionId(1)},
                                          {{7.0, 7.0, 0.0}, RegionId(1)}};
    const auto begin = std::chrono::steady_clock::now();
    const DriveProgress started = cam.followTargets(targets);
    CPPUNIT_ASSERT(started.request != 0);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t(3), started.targetCount);
    const bool arrived = pollUntil([&] { return cam.driveStatus().phase == DrivePhase::Reached; },
                                   std::chrono::seconds(60), std::chrono::milliseconds(100));
    const TrueSample end = truth.latest();
    const DriveProgress reached = cam.driveStatus();
    std::printf("\ndrive %s after %.1f s at true (%.3f, %.3f, %.3f), target %u of %u, %.2f m left %s\n",
                toString(reached.phase).c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), end.pose.x,
                end.pose.y, end.pose.theta, reached.targetIndex, reached.targetCount, reached.distanceLeftM,
                reached.reason.c_str());
    CPPUNIT_ASSERT_MESSAGE("the targets reached", arrived);
    const double error = std::hypot(end.pose.x - 7.0, end.pose.y - 7.0);
    std::printf("\n3 targets over 5.5 m reached: true pose %.3f m from the last, %llu chains sent\n", error,
                static_cast<unsigned long long>(reached.chainsSent));
    CPPUNIT_ASSERT(error <= 0.3);
    CPPUNIT_ASSERT(reached.chainsSent > 0);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t(3), reached.targetIndex);

    // A retry of the request answers the drive it started and starts none.
    const DriveProgress again = cam.followTargets(targets, started.request);
    CPPUNIT_ASSERT_EQUAL(started.request, again.request);
    CPPUNIT_ASSERT(again.phase == DrivePhase::Reached);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(1), cam.status().counters.at("drives"));

    // No map in the kernel: the drive waits for the planner, then is cancelled.
    const DriveProgress toGoal = cam.driveTo(PlanGoal::at({20.0, 7.0}));
    CPPUNIT_ASSERT(toGoal.phase == DrivePhase::Planning);
    waitUntil([&] { return cam.status().lastError.find("planner") != std::string::npos; },
              "the CAM to report the planner without a map");
    CPPUNIT_ASSERT(cam.driveStatus().phase == DrivePhase::Planning);
    cam.cancel();
    CPPUNIT_ASSERT(cam.driveStatus().phase == DrivePhase::Idle);

    // Idle, it reads no scans (a lock-step simulator, as in the demo, is not paced by it): at most
    // the one that applies the cancel while the simulator makes five more.
    const std::uint64_t scansRead = cam.status().counters.at("scans");
    const DataId scanNow = truth.latest().scan;
    waitUntil([&] { return truth.latest().scan >= scanNow + 5; }, "five more scans");
    CPPUNIT_ASSERT(cam.status().counters.at("scans") <= scansRead + 1);

    try {
      cam.followTargets({});
      CPPUNIT_FAIL("no targets accepted");
    } catch (const BadArgumentError& e) {
      CPPUNIT_ASSERT_EQUAL(std::string("targets"), e.field());
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CollisionAvoidanceIntegrationTest);
