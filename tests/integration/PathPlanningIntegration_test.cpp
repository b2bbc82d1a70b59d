// The PathPlanning module through a real server set (PlanningSet.h: the kernel holding the
// two-room map): a plan from the hallway into room 2 with its targets and route, served again as
// the last plan and by ID; a plan to a region by ID; typed NoPath for a goal outside every region
// and for a start far from every region; bad arguments refused naming the field; and a door
// reported blocked raises its learned cost in the kernel by the fixed length (thesis 5.4), once
// per request ID, and gives a new plan. The module fetches each region from the kernel once while
// no event changes it: neither a second plan on the same revision nor a learned door cost fetches
// any again.
// rgnav-plan plans through the module and offline on the kernel's exported map, both ending at
// the goal, and draws the path into its SVG and PNG.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "clientlibs/pathplanning/PathPlanningClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/testing/SamePlan.h"
#include "tests/integration/PlanningSet.h"
#include "tests/integration/ToolRun.h"
#include "tests/support/WaitUntil.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

const Pose2D kHallway{1.0, 1.0, 0.0};
const Eigen::Vector2d kRoom2{9.0, 4.0};

// The learned cost of gateway `door`'s edge in the kernel's graph.
double doorCost(RgMappingKernelClient& kernel, GatewayId door) {
  for (const GraphEdgeView& e : kernel.graph().edges)
    if (e.gateway == door) return e.costM;
  CPPUNIT_FAIL("gateway " + std::to_string(door.value()) + " has no edge");
  return 0.0;
}

template <class F>
std::string noPathReason(F&& call) {
  try {
    call();
  } catch (const NoPathError& e) {
    return e.what();
  }
  return "(planned)";
}

}  // namespace

class PathPlanningIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PathPlanningIntegrationTest);
  CPPUNIT_TEST(plansServesAndRefuses);
  CPPUNIT_TEST_SUITE_END();

 public:
  void plansServesAndRefuses() {
    PlanningSet set;
    set.cluster().start();
    PathPlanningClient planning(set.cluster().clientSettings());
    RgMappingKernelClient kernel(set.cluster().clientSettings());

    const PlanRecord first = planning.plan(kHallway, PlanGoal::at(kRoom2));
    CPPUNIT_ASSERT_EQUAL(PlanId(1), first.id);
    CPPUNIT_ASSERT(first.request != 0);
    CPPUNIT_ASSERT(!first.plan.targets.empty());
    const TargetPose& last = first.plan.targets.back();
    CPPUNIT_ASSERT((Eigen::Vector2d(last.pose.x, last.pose.y) - kRoom2).norm() < 1e-6);
    CPPUNIT_ASSERT(last.region == first.plan.goalRegion);
    CPPUNIT_ASSERT(first.plan.startRegion != first.plan.goalRegion);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), first.plan.route.size());  // through door 12, one crossing point each side
    CPPUNIT_ASSERT(first.plan.lengthM >= (kRoom2 - Eigen::Vector2d(kHallway.x, kHallway.y)).norm());
    CPPUNIT_ASSERT_EQUAL(kernel.summary().lastEvent, first.plan.mapRevision);
    CPPUNIT_ASSERT_EQUAL(std::string(), planDifference(first, planning.lastPlan()));
    CPPUNIT_ASSERT_EQUAL(std::string(), planDifference(first, planning.planById(1)));

    const std::uint64_t regions = kernel.summary().regions;
    CPPUNIT_ASSERT_EQUAL(regions, planning.status().counters.at("regions_fetched"));

    const PlanRecord byRegion = planning.plan(kHallway, PlanGoal::inRegion(first.plan.goalRegion));
    CPPUNIT_ASSERT_EQUAL(PlanId(2), byRegion.id);
    CPPUNIT_ASSERT(byRegion.plan.goalRegion == first.plan.goalRegion);

    const std::string outside = noPathReason([&] { planning.plan(kHallway, PlanGoal::at({50.0, 50.0})); });
    CPPUNIT_ASSERT_MESSAGE(outside, outside.find("outside every region") != std::string::npos);
    const std::string farStart = noPathReason([&] { planning.plan({1.0, -20.0, 0.0}, PlanGoal::at(kRoom2)); });
    CPPUNIT_ASSERT_MESSAGE(farStart, farStart != "(planned)");
    CPPUNIT_ASSERT_EQUAL(PlanId(2), planning.lastPlan().id);  // no plan was made for either

    const double nan = std::numeric_limits<double>::quiet_NaN();
    try {
      planning.plan({nan, 1.0, 0.0}, PlanGoal::at(kRoom2));
      CPPUNIT_FAIL("a NaN start was accepted");
    } catch (const BadArgumentError& e) {
      CPPUNIT_ASSERT_EQUAL(std::string("start"), e.field());
    }
    CPPUNIT_ASSERT_THROW(planning.planById(999), NotAvailableError);
    CPPUNIT_ASSERT_THROW(planning.replanDoorBlocked(GatewayId(999)), BadArgumentError);

    const GatewayId door = first.plan.route.front().gateway;
    const double before = doorCost(kernel, door);
    const PlanRecord replanned = planning.replanDoorBlocked(door);
    CPPUNIT_ASSERT_EQUAL(PlanId(3), replanned.id);
    CPPUNIT_ASSERT(replanned.plan.mapRevision > byRegion.plan.mapRevision);
    CPPUNIT_ASSERT(replanned.plan.goalRegion == first.plan.goalRegion);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(before + 30.0, doorCost(kernel, door), 1e-9);  // door_blocked_m
    const ModuleStatusInfo status = planning.status();
    CPPUNIT_ASSERT_EQUAL(regions, status.counters.at("regions_fetched"));
    CPPUNIT_ASSERT_EQUAL(replanned.plan.mapRevision, status.counters.at("map_revision"));
    // The kernel acts once per request ID: found open (back to the base cost), then found blocked
    // twice under one request ID (once more would be another 30 m).
    kernel.reportDoorState(door, true, 77);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(before, doorCost(kernel, door), 1e-9);
    kernel.reportDoorState(door, false, 78);
    kernel.reportDoorState(door, false, 78);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(before + 30.0, doorCost(kernel, door), 1e-9);

    kernel.exportMap("", "two-room", false);
    const std::string dir = set.cluster().dir();
    const std::vector<std::string> trip{"--from", "1,1", "--to", "9,4"};
    for (const std::vector<std::string>& where :
         {std::vector<std::string>{"--naming", "127.0.0.1:" + std::to_string(set.cluster().namingPort())},
          std::vector<std::string>{"--map", dir + "/run/exports/two-room.rgmap.json"}}) {
      std::vector<std::string> args = where;
      args.insert(args.end(), trip.begin(), trip.end());
      args.insert(args.end(), {"--svg", dir + "/plan.svg", "--png", dir + "/plan.png"});
      const auto [code, output] = runTool("rgnav-plan", args, dir + "/plan-" + where.front().substr(2) + ".log");
      CPPUNIT_ASSERT_EQUAL_MESSAGE(output, 0, code);
      CPPUNIT_ASSERT_MESSAGE(output, output.find("plan ") == 0);
      CPPUNIT_ASSERT_MESSAGE(output, output.find("x=9.000 y=4.000") != std::string::npos);
      std::ifstream svg(dir + "/plan.svg");
      const std::string picture{std::istreambuf_iterator<char>(svg), std::istreambuf_iterator<char>()};
      CPPUNIT_ASSERT(picture.find("<g class=\"plan-path\">") != std::string::npos);
      CPPUNIT_ASSERT(std::filesystem::file_size(dir + "/plan.png") > 0);
      std::filesystem::remove(dir + "/plan.svg");
      std::filesystem::remove(dir + "/plan.png");
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PathPlanningIntegrationTest);
