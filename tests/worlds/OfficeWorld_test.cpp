// Tests the office floor the project ships (config/worlds/office.yaml) as its header describes it:
// at least 12 rooms besides the hallway pieces, every room with a door of 0.8 to 1.0 m onto a
// hallway; a 2 m X-crossing with four hallway branches and a 2 m L-turn, both labelled in the
// ground truth; furniture the 0.40 m laser plane cuts and furniture above it; door frames,
// posters and door plates for the camera; and the simulator's room tour, from its default start
// and from the main hallway's west end, visits every region in lock-step without a collision.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>

#include "core/sim/GroundTruthTour.h"
#include "core/sim/TourRun.h"
#include "core/sim/world/VectorWorldGroundTruth.h"
#include "core/sim/world/VectorWorldRaster.h"
#include "core/sim/world/VectorWorldYaml.h"

using namespace rgnav;

namespace {

std::string officePath() {
  const char* root = std::getenv("RGNAV_ROOT");
  return (root != nullptr ? std::string(root) + "/" : std::string()) + "config/worlds/office.yaml";
}

struct Office {
  VectorWorld world;
  OccupancyGrid grid;
  GroundTruth truth;
};

const Office& office() {
  static const Office loaded = [] {
    Office o{loadVectorWorld(officePath()), {}, {}};
    o.grid = rasterize(o.world);
    o.truth = groundTruthOf(o.world, o.grid);
    return o;
  }();
  return loaded;
}

bool isHallway(const std::string& name) { return name.rfind("hallway", 0) == 0; }

int roomNamed(const std::string& name) {
  const auto& rooms = office().world.rooms;
  for (std::size_t i = 0; i < rooms.size(); ++i)
    if (rooms[i].name == name) return static_cast<int>(i);
  CPPUNIT_FAIL("no room named " + name);
  return -1;
}

std::string nameAt(WorldPoint p) {
  const int room = office().truth.roomAt(p);
  return room < 0 ? std::string("(none)") : office().world.rooms[static_cast<std::size_t>(room)].name;
}

WorldPoint centroid(const RoomPolygon& room) {
  WorldPoint c;
  for (const WorldPoint& v : room.polygon) {
    c.x += v.x / static_cast<double>(room.polygon.size());
    c.y += v.y / static_cast<double>(room.polygon.size());
  }
  return c;
}

WorldPoint along(WorldPoint p, WorldPoint dir, double s) { return {p.x + s * dir.x, p.y + s * dir.y}; }

// How far the laser plane is free from p in direction dir (unit), up to `limit`.
double freeRun(WorldPoint p, WorldPoint dir, double limit = 20.0) {
  const OccupancyGrid& grid = office().grid;
  const double step = grid.resolution() / 4.0;
  double s = 0.0;
  while (s < limit) {
    const auto cell = grid.cellOf(along(p, dir, s + step));
    if (!cell || grid.blocked(*cell)) break;
    s += step;
  }
  return s;
}

// The narrowest free width across a hallway branch leaving `center` in direction `dir`, sampled
// from `from` to `to` metres out.
double branchWidth(WorldPoint center, WorldPoint dir, double from, double to) {
  const WorldPoint across{-dir.y, dir.x};
  const WorldPoint back{-across.x, -across.y};
  double narrowest = 1e9;
  for (double s = from; s <= to; s += 0.1) {
    const WorldPoint p = along(center, dir, s);
    narrowest = std::min(narrowest, freeRun(p, across) + freeRun(p, back));
  }
  return narrowest;
}

const WorldPoint kEast{1, 0}, kWest{-1, 0}, kNorth{0, 1}, kSouth{0, -1};

void expectCompleteTour(const Tour& plan, const TourRunResult& run, const std::string& what) {
  const auto rooms = static_cast<std::size_t>(office().truth.roomCount);
  CPPUNIT_ASSERT_MESSAGE(what + ": unreachable rooms", plan.unreachableRooms.empty());
  CPPUNIT_ASSERT_EQUAL_MESSAGE(what + ": planned visits", rooms, plan.visits.size());
  CPPUNIT_ASSERT_EQUAL_MESSAGE(what + ": rooms visited", rooms, run.roomsVisited.size());
  CPPUNIT_ASSERT_EQUAL_MESSAGE(what + ": rooms entered", rooms, run.roomsEntered.size());
  CPPUNIT_ASSERT_MESSAGE(what + ": visits given up", run.roomsMissed.empty());
  CPPUNIT_ASSERT_MESSAGE(what + ": finished", run.finished);
  CPPUNIT_ASSERT_EQUAL_MESSAGE(what + ": collisions", std::uint64_t{0}, run.collisions);
  CPPUNIT_ASSERT_MESSAGE(what + ": scans", run.scans > 1000);
}

}  // namespace

class OfficeWorldTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(OfficeWorldTest);
  CPPUNIT_TEST(hasADozenRoomsEachWithADoorOntoAHallway);
  CPPUNIT_TEST(everyRegionHasCellsToScore);
  CPPUNIT_TEST(hallwaysCrossInAnXCrossing);
  CPPUNIT_TEST(mainHallwayEndsInAnLTurn);
  CPPUNIT_TEST(furnitureIsCutByTheLaserPlaneAndAboveIt);
  CPPUNIT_TEST(cameraSeesDoorFramesPostersAndDoorPlates);
  CPPUNIT_TEST(roomTourVisitsEveryRoomWithoutCollision);
  CPPUNIT_TEST(roomTourFromTheHallwayVisitsEveryRoom);
  CPPUNIT_TEST_SUITE_END();

 public:
  void hasADozenRoomsEachWithADoorOntoAHallway() {
    const Office& o = office();
    CPPUNIT_ASSERT_EQUAL(static_cast<int>(o.world.rooms.size()), o.truth.roomCount);
    std::set<std::string> names;
    std::set<int> rooms;
    for (std::size_t i = 0; i < o.world.rooms.size(); ++i) {
      CPPUNIT_ASSERT_MESSAGE("unnamed room", !o.world.rooms[i].name.empty());
      CPPUNIT_ASSERT_MESSAGE("duplicate " + o.world.rooms[i].name, names.insert(o.world.rooms[i].name).second);
      if (!isHallway(o.world.rooms[i].name)) rooms.insert(static_cast<int>(i));
    }
    CPPUNIT_ASSERT_MESSAGE("at least 12 rooms besides the hallway", rooms.size() >= 12);

    CPPUNIT_ASSERT_EQUAL(o.world.doors.size(), o.truth.doors.size());
    std::set<int> withDoor;
    for (std::size_t i = 0; i < o.world.doors.size(); ++i) {
      const Door& door = o.world.doors[i];
      const DoorLine& line = o.truth.doors[i];
      const std::string which = "door " + std::to_string(i);
      CPPUNIT_ASSERT_MESSAGE(which + " width", door.width >= 0.8 - 1e-9 && door.width <= 1.0 + 1e-9);
      CPPUNIT_ASSERT_MESSAGE(which + " frame", door.frameWidth > door.width && door.frameHeight >= 2.0);
      CPPUNIT_ASSERT_MESSAGE(which + " open", door.open);
      CPPUNIT_ASSERT_MESSAGE(which + " joins two regions", line.roomA >= 0 && line.roomB >= 0 && line.roomA != line.roomB);
      const std::string a = o.world.rooms[static_cast<std::size_t>(line.roomA)].name;
      const std::string b = o.world.rooms[static_cast<std::size_t>(line.roomB)].name;
      CPPUNIT_ASSERT_MESSAGE(which + " leads from a room onto a hallway: " + a + " / " + b, isHallway(a) != isHallway(b));
      withDoor.insert(isHallway(a) ? line.roomB : line.roomA);
    }
    CPPUNIT_ASSERT_MESSAGE("every room has a door", withDoor == rooms);
  }

  void everyRegionHasCellsToScore() {
    const Office& o = office();
    std::vector<int> cells(static_cast<std::size_t>(o.truth.roomCount), 0);
    for (const int label : o.truth.labels)
      if (label >= 0) ++cells[static_cast<std::size_t>(label)];
    const double cellArea = o.grid.resolution() * o.grid.resolution();
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string& name = o.world.rooms[i].name;
      CPPUNIT_ASSERT_MESSAGE(name + " has under 3 m2 of free cells", cells[i] * cellArea >= 3.0);
      if (!isHallway(name)) CPPUNIT_ASSERT_MESSAGE(name + " is smaller than 3 x 4 m", cells[i] * cellArea >= 10.0);
    }
  }

  void hallwaysCrossInAnXCrossing() {
    const WorldPoint c = centroid(office().world.rooms[static_cast<std::size_t>(roomNamed("hallway_crossing"))]);
    CPPUNIT_ASSERT_EQUAL(std::string("hallway_crossing"), nameAt(c));
    const std::pair<WorldPoint, std::string> branches[] = {
        {kWest, "hallway_west"}, {kEast, "hallway_east"}, {kSouth, "hallway_south"}, {kNorth, "hallway_north"}};
    for (const auto& [dir, name] : branches) {
      CPPUNIT_ASSERT_EQUAL(name, nameAt(along(c, dir, 1.5)));
      CPPUNIT_ASSERT_MESSAGE(name + " is a branch at least 4 m long", freeRun(c, dir) >= 4.0);
      const double width = branchWidth(c, dir, 1.5, 3.5);
      CPPUNIT_ASSERT_MESSAGE(name + " is " + std::to_string(width) + " m wide", width >= 1.9 && width <= 2.1);
    }
  }

  void mainHallwayEndsInAnLTurn() {
    const WorldPoint c = centroid(office().world.rooms[static_cast<std::size_t>(roomNamed("hallway_turn"))]);
    CPPUNIT_ASSERT_EQUAL(std::string("hallway_turn"), nameAt(c));
    CPPUNIT_ASSERT_EQUAL(std::string("hallway_east"), nameAt(along(c, kWest, 1.5)));
    CPPUNIT_ASSERT_EQUAL(std::string("hallway_wing"), nameAt(along(c, kNorth, 1.5)));
    for (const WorldPoint& open : {kWest, kNorth}) {
      CPPUNIT_ASSERT(freeRun(c, open) >= 4.0);
      const double width = branchWidth(c, open, 1.5, 3.5);
      CPPUNIT_ASSERT_MESSAGE(std::to_string(width) + " m wide", width >= 1.9 && width <= 2.1);
    }
    for (const WorldPoint& closed : {kEast, kSouth}) CPPUNIT_ASSERT(freeRun(c, closed) <= 1.1);
  }

  void furnitureIsCutByTheLaserPlaneAndAboveIt() {
    const VectorWorld& world = office().world;
    int cut = 0, above = 0;
    const auto count = [&](double elevation, double height) {
      if (elevation <= kLaserPlaneHeight && elevation + height >= kLaserPlaneHeight) ++cut;
      else if (elevation > kLaserPlaneHeight) ++above;
    };
    for (const Box& box : world.boxes) count(box.elevation, box.height);
    for (const Cylinder& cylinder : world.cylinders) count(cylinder.elevation, cylinder.height);
    CPPUNIT_ASSERT_MESSAGE("legs, panels, cabinets at the laser plane", cut >= 50);
    CPPUNIT_ASSERT_MESSAGE("desk tops and seats above it", above >= 20);

    VectorWorld bare = world;
    bare.boxes.clear();
    bare.cylinders.clear();
    const OccupancyGrid walls = rasterize(bare);
    std::size_t furniture = 0;
    for (std::size_t i = 0; i < walls.cells().size(); ++i)
      furniture += walls.cells()[i] == Cell::Free && office().grid.cells()[i] != Cell::Free;
    CPPUNIT_ASSERT_MESSAGE("the laser sees furniture", furniture * 0.05 * 0.05 >= 10.0);
  }

  void cameraSeesDoorFramesPostersAndDoorPlates() {
    const VectorWorld& world = office().world;
    CPPUNIT_ASSERT_EQUAL(2 * world.doors.size(), doorFrames(world).size());
    std::multiset<std::string> labels;
    for (const Rectangle3D& r : world.rectangles) labels.insert(r.label);
    CPPUNIT_ASSERT(labels.count("poster") >= 4);
    CPPUNIT_ASSERT(labels.count("whiteboard") >= 1);
    CPPUNIT_ASSERT_EQUAL(world.doors.size(), labels.count("door_plate"));
  }

  void roomTourVisitsEveryRoomWithoutCollision() {
    const Office& o = office();
    const RoomTour tour = driveRoomTour(o.grid, o.truth, SimulationConfig{}, [](const SimulationStep&) {});
    expectCompleteTour(tour.plan, tour.run, "tour from the default start");
  }

  void roomTourFromTheHallwayVisitsEveryRoom() {
    const Office& o = office();
    const Pose2D start{1.5, 7.0, 0.0};  // the main hallway's west end, as the YAML header suggests
    CPPUNIT_ASSERT_EQUAL(std::string("hallway_west"), nameAt({start.x, start.y}));
    const Tour plan = planTour(o.grid, o.truth, start);
    Simulation simulation(o.grid, SimulationConfig{}, start);
    TourDriver driver(plan, PurePursuitConfig{});
    const TourRunResult run = runTour(simulation, driver, o.truth, [](const SimulationStep&) {}, kRoomTourMaxSeconds);
    expectCompleteTour(plan, run, "tour from the hallway");
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(OfficeWorldTest);
