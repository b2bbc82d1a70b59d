// Tests the route planner on the kernel's map of a hallway with two rooms behind doors
// (ExportedFloor.h): a route from the hallway into a room passes the room's door through its
// middle, and its targets are spaced and labelled; goals by region ID, region name and object
// name; typed refusals for goals outside the map or in an obstacle and for far starts; a start
// just outside the map is placed in it, and a start in a pocket of free cells cut off from the rest
// is placed where it leads on; a gateway outside the RG graph joins its regions, but not through a
// wall, nor at one crossing point in the wall between two rooms.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/lines/ScanPoints.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/CellPoints.h"
#include "core/nav/planning/KernelPlanningMap.h"
#include "core/nav/planning/RoutePlanner.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using Eigen::Vector2d;
using rgnav::NoPathError;
using rgnav::Plan;
using rgnav::PlanGoal;
using rgnav::Pose2D;
using rgnav::RegionId;
using rgnav::RoutePlanner;

class RoutePlannerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RoutePlannerTest);
  CPPUNIT_TEST(aRouteIntoARoomPassesItsDoor);
  CPPUNIT_TEST(freespaceStackedWithoutAnEventIsPlannedOn);
  CPPUNIT_TEST(goalsByRegionAndByName);
  CPPUNIT_TEST(anObjectGoalFacesTheObject);
  CPPUNIT_TEST(badGoalsAndStartsAreTypedNoPath);
  CPPUNIT_TEST(aStartJustOutsideIsPlacedInTheNearestRegion);
  CPPUNIT_TEST(aStartInACutOffPocketIsPlacedWhereItLeadsOn);
  CPPUNIT_TEST(aGatewayWithAnUnknownSideStillJoinsItsRegions);
  CPPUNIT_TEST(noPassageThroughAWall);
  CPPUNIT_TEST(noJumpAtACrossingPointInAWall);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override {
    kernel_ = std::make_unique<rgnav::RgMappingKernel>(rgnav::testing::twoRoomMap());
    planner_.setMap(rgnav::planningMapOf(*kernel_));
  }

  void aRouteIntoARoomPassesItsDoor() {
    const Plan plan = planner_.plan({1.0, 1.0, 0.0}, PlanGoal::at({9.0, 4.5}));
    CPPUNIT_ASSERT(plan.startRegion != plan.goalRegion);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), plan.route.size());  // both crossing points of door 12
    CPPUNIT_ASSERT(plan.route[0].gateway == plan.route[1].gateway);
    // Through the door at x in [8.55, 9.45], y = 2.
    bool throughDoor = false;
    for (std::size_t i = 1; i < plan.path.size(); ++i) {
      const Vector2d a = plan.path[i - 1], b = plan.path[i];
      if ((a.y() - 2.0) * (b.y() - 2.0) <= 0.0 && a.y() != b.y()) {
        const double x = a.x() + (2.0 - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
        throughDoor = throughDoor || (x > 8.55 && x < 9.45);
      }
    }
    CPPUNIT_ASSERT(throughDoor);
    // Through the middle of the door's gateway points, whatever the crossing points' offsets.
    const auto views = rgnav::gatewayViews(*kernel_);
    const auto door = std::find_if(views.begin(), views.end(), [&](const auto& g) { return g.id == plan.route[0].gateway; });
    const Vector2d middle = 0.5 * (door->gatewayPoints[0] + door->gatewayPoints[1]);
    CPPUNIT_ASSERT(std::any_of(plan.path.begin(), plan.path.end(), [&](const Vector2d& p) { return (p - middle).norm() < 1e-9; }));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(rgnav::polylineLength(plan.path), plan.lengthM, 1e-9);
    CPPUNIT_ASSERT(plan.lengthM >= (Vector2d(9.0, 4.5) - Vector2d(1.0, 1.0)).norm());
    CPPUNIT_ASSERT(plan.lengthM < 13.0);
    // Targets 0.5 to 2 m apart, the goal last and in the goal's region.
    Vector2d previous(1.0, 1.0);
    for (const auto& t : plan.targets) {
      const double gap = (Vector2d(t.pose.x, t.pose.y) - previous).norm();
      CPPUNIT_ASSERT(gap <= 2.0 + 1e-9);
      previous = {t.pose.x, t.pose.y};
    }
    CPPUNIT_ASSERT((previous - Vector2d(9.0, 4.5)).norm() < 1e-9);
    CPPUNIT_ASSERT(plan.targets.back().region == plan.goalRegion);
    CPPUNIT_ASSERT(plan.targets.front().region == plan.startRegion);
  }

  void goalsByRegionAndByName() {
    const Plan toPoint = planner_.plan({1.0, 1.0, 0.0}, PlanGoal::at({4.0, 4.0}));
    const Plan byId = planner_.plan({1.0, 1.0, 0.0}, PlanGoal::inRegion(toPoint.goalRegion));
    CPPUNIT_ASSERT(byId.goalRegion == toPoint.goalRegion);
    kernel_->nameRegion(toPoint.goalRegion, "lab");
    planner_.setMap(rgnav::planningMapOf(*kernel_));
    const Plan byName = planner_.plan({1.0, 1.0, 0.0}, PlanGoal::inRegionNamed("lab"));
    CPPUNIT_ASSERT(byName.goalRegion == toPoint.goalRegion);
    CPPUNIT_ASSERT_THROW(planner_.plan({1.0, 1.0, 0.0}, PlanGoal::inRegionNamed("kitchen")), NoPathError);
    CPPUNIT_ASSERT_THROW(planner_.plan({1.0, 1.0, 0.0}, PlanGoal::inRegion(RegionId{99})), NoPathError);
  }

  void anObjectGoalFacesTheObject() {
    const auto inputs = rgnav::testing::twoRoomTour(rgnav::testing::hallwayWithTwoRoomsAndCabinet()).inputs();
    rgnav::RgMappingKernel kernel = rgnav::testing::mapped(inputs, inputs.size());
    const Vector2d cabinet = rgnav::testing::cabinetCentre();
    RoutePlanner planner;
    planner.setMap(rgnav::planningMapOf(kernel));
    const Plan room = planner.plan({1.0, 1.0, 0.0}, PlanGoal::at({4.0, 4.0}));
    const Pose2D frame = kernel.state().regions.at(room.goalRegion).frame;
    const Pose2D local = rgnav::between(frame, {cabinet.x(), cabinet.y(), 0.0});
    kernel.nameObject(room.goalRegion, {local.x, local.y}, "files");
    planner.setMap(rgnav::planningMapOf(kernel));
    const Plan plan = planner.plan({1.0, 1.0, 0.0}, PlanGoal::atObject("files"));
    const auto& goal = plan.targets.back().pose;
    const Vector2d toObject = cabinet - Vector2d(goal.x, goal.y);
    CPPUNIT_ASSERT(toObject.norm() < 1.5);  // in front of the 0.7 x 1.2 m cabinet
    CPPUNIT_ASSERT(std::abs(rgnav::normalizeAngle(std::atan2(toObject.y(), toObject.x()) - goal.theta)) < 0.3);
    CPPUNIT_ASSERT_THROW(planner.plan({1.0, 1.0, 0.0}, PlanGoal::atObject("piano")), NoPathError);
  }

  void badGoalsAndStartsAreTypedNoPath() {
    assertNoPath({1.0, 1.0, 0.0}, PlanGoal::at({50.0, 50.0}), "outside every region");
    assertNoPath({1.0, 1.0, 0.0}, PlanGoal::at({1.0, 1.9}), "obstacle");  // 0.1 m from the hallway wall
    assertNoPath({1.0, -5.0, 0.0}, PlanGoal::at({9.0, 4.5}), "start");
    CPPUNIT_ASSERT_THROW(planner_.plan({1.0, 1.0, 0.0}, PlanGoal::at({NAN, 1.0})), rgnav::InvalidArgumentError);
  }

  // Door 12 as the kernel holds it before it knows the room behind it: out of the RG graph, one
  // side unknown. Its crossing points still lie in the hallway's and the room's free cells.
  void aGatewayWithAnUnknownSideStillJoinsItsRegions() {
    const Plan before = planner_.plan({1.0, 1.0, 0.0}, PlanGoal::at({9.0, 4.5}));
    const rgnav::GatewayId door = before.route.front().gateway;
    rgnav::PlanningMap map = rgnav::planningMapOf(*kernel_);
    for (auto& g : map.gateways)
      if (g.id == door) g.sideB = RegionId{};
    rgnav::GraphView graph;
    std::vector<std::size_t> index(map.graph.nodes.size());
    for (std::size_t i = 0; i < map.graph.nodes.size(); ++i)
      if (map.graph.nodes[i].gateway != door) {
        index[i] = graph.nodes.size();
        graph.nodes.push_back(map.graph.nodes[i]);
      }
    for (auto e : map.graph.edges)
      if (map.graph.nodes[e.from].gateway != door && map.graph.nodes[e.to].gateway != door) {
        e.from = index[e.from];
        e.to = index[e.to];
        graph.edges.push_back(e);
      }
    map.graph = graph;
    map.revision += 1;
    planner_.setMap(map);
    const Plan plan = planner_.plan({1.0, 1.0, 0.0}, PlanGoal::at({9.0, 4.5}));
    CPPUNIT_ASSERT(plan.goalRegion == before.goalRegion);
    CPPUNIT_ASSERT(std::any_of(plan.route.begin(), plan.route.end(), [&](const auto& n) { return n.gateway == door; }));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(before.lengthM, plan.lengthM, 0.5);
  }

  // Scans stacked into the current region grow its freespace without a kernel event: the map comes
  // with the same revision and a changed region summary, and the planner plans on the new freespace
  // instead of the grid it built before.
  void freespaceStackedWithoutAnEventIsPlannedOn() {
    const Vector2d goal(9.0, 4.5);
    rgnav::PlanningMap full = rgnav::planningMapOf(*kernel_);
    const std::vector<rgnav::RegionId> at = planner_.regionsAt(goal);
    CPPUNIT_ASSERT(!at.empty());
    rgnav::PlanningMap cut = full;
    for (rgnav::RegionView& region : cut.regions) {
      if (region.summary.id != at.front()) continue;
      const rgnav::FreespaceBitmap& had = region.freespace;
      rgnav::FreespaceBitmap less =
          rgnav::FreespaceBitmap::allOccupied(had.resolutionM, had.originM, had.width, had.height);
      for (int row = 0; row < had.height; ++row)
        for (int col = 0; col < had.width; ++col)
          if (had.isFree(col, row) &&
              (rgnav::transformPoint(region.summary.frame, had.cellCenter(col, row)) - goal).norm() > 1.5)
            less.setFree(col, row);
      region.freespace = less;
      region.summary.scans -= 1;  // the scan that saw the rest is not stacked yet
    }
    planner_.setMap(cut);
    CPPUNIT_ASSERT_THROW(planner_.plan({1.0, 1.0, 0.0}, PlanGoal::at(goal)), rgnav::NoPathError);
    planner_.setMap(full);  // the same revision
    CPPUNIT_ASSERT(planner_.plan({1.0, 1.0, 0.0}, PlanGoal::at(goal)).lengthM > 0.0);
  }

  // A detected gateway no region has taken in yet, with its crossing points in the two rooms on
  // either side of the wall between them (x in [6, 7]): the straight line between them crosses
  // the wall, so the route from room to room still goes through the hallway.
  void noPassageThroughAWall() {
    rgnav::PlanningMap map = rgnav::planningMapOf(*kernel_);
    rgnav::GatewayView fake;
    fake.id = rgnav::GatewayId{999};
    fake.gatewayPoints = {{6.5, 3.5}, {6.5, 4.5}};
    fake.crossingPoints = {{5.5, 4.0}, {7.5, 4.0}};
    map.gateways.push_back(fake);
    map.revision += 1;
    planner_.setMap(map);
    const Plan plan = planner_.plan({4.0, 4.0, 0.0}, PlanGoal::at({9.0, 4.0}));
    CPPUNIT_ASSERT(std::none_of(plan.route.begin(), plan.route.end(), [&](const auto& n) { return n.gateway == fake.id; }));
    CPPUNIT_ASSERT(plan.lengthM > 7.0);  // down through door 11, along the hallway, up through door 12
  }

  // A detected gateway no region has taken in, with one crossing point in the wall between the two
  // rooms (x in [6, 7]) that snaps into both (the snap reaching 1 m here): the rooms are not joined
  // there, the route still goes through the hallway.
  void noJumpAtACrossingPointInAWall() {
    rgnav::RoutePlannerConfig config;
    config.crossingSnapM = 1.0;
    RoutePlanner planner(config);
    rgnav::PlanningMap map = rgnav::planningMapOf(*kernel_);
    rgnav::GatewayView fake;
    fake.id = rgnav::GatewayId{999};
    fake.gatewayPoints = {{6.5, 3.5}, {6.5, 4.5}};
    fake.crossingPoints = {{6.5, 4.0}};
    map.gateways.push_back(fake);
    planner.setMap(map);
    const Plan plan = planner.plan({4.0, 4.0, 0.0}, PlanGoal::at({9.0, 4.0}));
    CPPUNIT_ASSERT(std::none_of(plan.route.begin(), plan.route.end(), [&](const auto& n) { return n.gateway == fake.id; }));
    CPPUNIT_ASSERT(plan.lengthM > 7.0);
  }

  // At the hallway's south wall, off its free cells: placed on the nearest free cell. 0.3 m behind
  // that wall: the hop would cross it, so the start lies in no region.
  void aStartJustOutsideIsPlacedInTheNearestRegion() {
    const Plan plan = planner_.plan({1.0, 0.1, 0.0}, PlanGoal::at({3.0, 1.0}));
    CPPUNIT_ASSERT((plan.path.front() - Vector2d(1.0, 0.1)).norm() < 1e-12);
    const double hop = (plan.path[1] - Vector2d(1.0, 0.1)).norm();
    CPPUNIT_ASSERT(hop > 0.0 && hop < 0.3);
    assertNoPath({1.0, -0.3, 0.0}, PlanGoal::at({3.0, 1.0}), "outside every region");
  }

  // The hallway's line map with a 0.8 m box of walls around (5, 1), open by 0.3 m to the west: the
  // box's middle is free (0.4 m from its walls), but the inflation closes the gap, so no path
  // leaves it (as where a robot pushed into a wall corner stands on a sliver of a region's free
  // cells). The start there is placed on the nearest cell that leads on, straight out through the
  // gap; a goal in the same pocket is planned to directly.
  void aStartInACutOffPocketIsPlacedWhereItLeadsOn() {
    const Vector2d pocket(5.0, 1.0);
    rgnav::PlanningMap map = rgnav::planningMapOf(*kernel_);
    const std::vector<RegionId> in = planner_.regionsAt(pocket);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), in.size());
    const std::vector<std::pair<Vector2d, Vector2d>> box{{{4.6, 0.6}, {5.4, 0.6}},  {{5.4, 0.6}, {5.4, 1.4}},
                                                         {{5.4, 1.4}, {4.6, 1.4}},  {{4.6, 1.4}, {4.6, 1.15}},
                                                         {{4.6, 0.85}, {4.6, 0.6}}};
    for (auto& region : map.regions)
      if (region.summary.id == in.front()) {
        const Pose2D toRegion = rgnav::inverse(region.summary.frame);
        for (const auto& [a, b] : box)
          region.lines.push_back({rgnav::transformPoint(toRegion, a), rgnav::transformPoint(toRegion, b)});
      }
    map.revision += 1;
    planner_.setMap(map);
    CPPUNIT_ASSERT(planner_.regionsAt(pocket) == in);  // free, in the hallway's free cells

    const Plan plan = planner_.plan({pocket.x(), pocket.y(), 0.0}, PlanGoal::at({9.0, 4.5}));
    CPPUNIT_ASSERT((plan.path.front() - pocket).norm() < 1e-12);
    const Vector2d placed = plan.path[1];
    CPPUNIT_ASSERT(placed.x() < 4.6);  // out through the gap, not over the box's walls
    CPPUNIT_ASSERT(std::abs(placed.y() - 1.0) < 0.15);
    CPPUNIT_ASSERT((placed - pocket).norm() < 1.0);

    const Plan inside = planner_.plan({pocket.x(), pocket.y(), 0.0}, PlanGoal::at({5.05, 1.05}));
    CPPUNIT_ASSERT((inside.path.front() - pocket).norm() < 1e-12);
    CPPUNIT_ASSERT(inside.lengthM < 0.1);
  }

 private:
  void assertNoPath(const Pose2D& start, const PlanGoal& goal, const std::string& reason) {
    try {
      planner_.plan(start, goal);
      CPPUNIT_FAIL("planned where no path exists (" + reason + ")");
    } catch (const NoPathError& e) {
      CPPUNIT_ASSERT_MESSAGE(e.what(), std::string(e.what()).find(reason) != std::string::npos);
    }
  }

  std::unique_ptr<rgnav::RgMappingKernel> kernel_;
  RoutePlanner planner_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(RoutePlannerTest);
