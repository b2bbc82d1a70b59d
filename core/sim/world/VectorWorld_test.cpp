// Tests vector worlds: the YAML schema (every element kind), rasterization at the laser plane
// (doors as openings, closed doors, furniture below / through / above the plane, low walls),
// 3D rectangles and door frames, room-polygon ground truth, floor-plan base layers, and typed
// errors for bad keys, bad references and missing images.
#include <cppunit/extensions/HelperMacros.h>

#include "core/logs/LogTestFiles.h"
#include "core/raster/ImageFile.h"
#include "core/sim/world/VectorWorldGroundTruth.h"
#include "core/sim/world/VectorWorldRaster.h"
#include "core/sim/world/VectorWorldYaml.h"

using namespace rgnav;
using rgnav::testing::TempDir;
using rgnav::testing::writeFile;

namespace {

// Two rooms of 5 x 4 m side by side, joined by an open door in the partition; a closed door in
// the south wall of the east room; furniture in the west room.
const char* kWorld = R"(resolution: 0.05
size: [10.4, 4.4]
walls:
  - {name: south, from: [0.2, 0.2], to: [10.2, 0.2], thickness: 0.2}
  - {name: north, from: [0.2, 4.2], to: [10.2, 4.2], thickness: 0.2}
  - {name: west, from: [0.2, 0.2], to: [0.2, 4.2], thickness: 0.2}
  - {name: east, from: [10.2, 0.2], to: [10.2, 4.2], thickness: 0.2}
  - {name: partition, from: [5.2, 0.2], to: [5.2, 4.2], thickness: 0.1, height: 2.4}
  - {name: kerb, from: [1.0, 3.0], to: [3.0, 3.0], thickness: 0.1, height: 0.3}
doors:
  - {wall: partition, offset: 2.0, width: 1.0, frame_width: 1.2, frame_height: 2.1}
  - {wall: south, center: [8.0, 0.25], width: 0.9, open: false}
boxes:
  - {center: [2.0, 1.0], size: [1.0, 0.6], height: 1.8}
  - {center: [3.5, 1.0], size: [1.2, 0.8], height: 0.05, elevation: 0.7}
  - {center: [2.0, 2.0], size: [0.4, 0.4], height: 0.2}
  - {center: [4.0, 2.4], size: [0.6, 0.2], yaw: 0.7853981633974483, height: 1.0}
cylinders:
  - {center: [1.0, 2.0], radius: 0.15, height: 0.9}
  - {center: [3.0, 2.0], radius: 0.15, height: 0.3, elevation: 1.0}
rectangles3d:
  - {label: poster, wall: north, side: right, offset: 2.0, width: 0.6, height: 0.8, elevation: 1.2}
  - {label: whiteboard, corners: [[1, 1, 1], [2, 1, 1], [2, 1, 2], [1, 1, 2]]}
rooms:
  - {name: west, polygon: [[0.3, 0.3], [5.15, 0.3], [5.15, 4.1], [0.3, 4.1]]}
  - {name: east, polygon: [[5.25, 0.3], [10.1, 0.3], [10.1, 4.1], [5.25, 4.1]]}
)";

bool occupied(const OccupancyGrid& grid, double x, double y) { return grid.blocked(*grid.cellOf({x, y})); }

std::string edited(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  CPPUNIT_ASSERT_MESSAGE(from, at != std::string::npos);
  return text.replace(at, from.size(), to);
}

template <typename Error>
void expectError(const std::string& yamlText, const std::vector<std::string>& mentions) {
  TempDir dir;
  const std::string path = dir.file("world.yaml");
  writeFile(path, yamlText);
  try {
    loadVectorWorld(path);
    CPPUNIT_FAIL("no error for:\n" + yamlText);
  } catch (const Error& e) {
    const std::string what = e.what();
    CPPUNIT_ASSERT_MESSAGE(what + " lacks the path", what.find(path) != std::string::npos);
    for (const std::string& m : mentions) CPPUNIT_ASSERT_MESSAGE(what + " lacks " + m, what.find(m) != std::string::npos);
  }
}

VectorWorld loaded(const std::string& text) {
  TempDir dir;
  writeFile(dir.file("world.yaml"), text);
  return loadVectorWorld(dir.file("world.yaml"));
}

}  // namespace

class VectorWorldTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(VectorWorldTest);
  CPPUNIT_TEST(loadsEveryElement);
  CPPUNIT_TEST(rasterizesWallsAndDoors);
  CPPUNIT_TEST(onlyFurnitureThroughTheLaserPlaneCounts);
  CPPUNIT_TEST(rectanglesAndDoorFrames);
  CPPUNIT_TEST(roomGroundTruth);
  CPPUNIT_TEST(floorPlanBaseLayer);
  CPPUNIT_TEST(badWorldsAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void loadsEveryElement() {
    const VectorWorld world = loaded(kWorld);
    CPPUNIT_ASSERT_EQUAL(std::size_t(6), world.walls.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), world.doors.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), world.boxes.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), world.cylinders.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), world.rectangles.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), world.rooms.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(10.4, world.max.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.5, world.walls[0].height, 1e-12);  // default
    const Door& closed = world.doors[1];
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), closed.wall);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.8, closed.offset, 1e-9);  // centre projected onto the wall
    CPPUNIT_ASSERT(!closed.open);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.9, closed.frameWidth, 1e-12);   // defaults to the width
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.10, closed.frameHeight, 1e-12);
    CPPUNIT_ASSERT(world.doors[0].open);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.7, world.boxes[1].elevation, 1e-12);
  }

  void rasterizesWallsAndDoors() {
    const OccupancyGrid grid = rasterize(loaded(kWorld));
    CPPUNIT_ASSERT_EQUAL(208, grid.width());
    CPPUNIT_ASSERT_EQUAL(88, grid.height());
    CPPUNIT_ASSERT(occupied(grid, 5.0, 0.2));   // south wall
    CPPUNIT_ASSERT(occupied(grid, 0.12, 4.28));  // the closed outer corner (square wall ends)
    CPPUNIT_ASSERT(occupied(grid, 5.0, 0.29));   // the wall face lies on a cell boundary
    CPPUNIT_ASSERT(!occupied(grid, 5.0, 0.31));
    // Partition: solid, open door between y = 1.7 and 2.7 (offset 2.0 from y = 0.2).
    CPPUNIT_ASSERT(occupied(grid, 5.2, 1.0));
    CPPUNIT_ASSERT(occupied(grid, 5.2, 3.5));
    for (double y = 1.75; y < 2.66; y += 0.05) CPPUNIT_ASSERT(!occupied(grid, 5.2, y));
    CPPUNIT_ASSERT(occupied(grid, 5.2, 1.6));
    CPPUNIT_ASSERT(occupied(grid, 5.2, 2.8));
    // Closed door in the south wall: still blocked.
    CPPUNIT_ASSERT(occupied(grid, 8.0, 0.2));
    // A wall of 0.3 m stays below the laser plane.
    CPPUNIT_ASSERT(!occupied(grid, 2.0, 3.0));
    // Cells outside the walls but inside the extent are free.
    CPPUNIT_ASSERT(!occupied(grid, 10.37, 2.0));
  }

  void onlyFurnitureThroughTheLaserPlaneCounts() {
    const VectorWorld world = loaded(kWorld);
    const OccupancyGrid grid = rasterize(world);
    CPPUNIT_ASSERT(occupied(grid, 2.0, 1.0));   // cabinet, 1.8 m high
    CPPUNIT_ASSERT(occupied(grid, 2.45, 1.25));
    CPPUNIT_ASSERT(!occupied(grid, 2.6, 1.0));
    CPPUNIT_ASSERT(!occupied(grid, 3.5, 1.0));  // table top at 0.7 m
    CPPUNIT_ASSERT(!occupied(grid, 2.0, 2.0));  // 0.2 m box below the plane
    CPPUNIT_ASSERT(occupied(grid, 1.0, 2.0));   // bin through the plane
    CPPUNIT_ASSERT(occupied(grid, 1.12, 2.0));
    CPPUNIT_ASSERT(!occupied(grid, 1.2, 2.0));
    CPPUNIT_ASSERT(!occupied(grid, 3.0, 2.0));  // lamp hanging at 1.0 m
    // Rotated box (45 degrees): its ends lie on the diagonal.
    CPPUNIT_ASSERT(occupied(grid, 4.0 + 0.2, 2.4 + 0.2));
    CPPUNIT_ASSERT(!occupied(grid, 4.0 + 0.25, 2.4 - 0.25));
    // With the plane at 1.5 m the bin, the low box and the rotated box drop out, the cabinet stays.
    const OccupancyGrid high = rasterize(world, 1.5);
    CPPUNIT_ASSERT(occupied(high, 2.0, 1.0));
    CPPUNIT_ASSERT(!occupied(high, 1.0, 2.0));
    CPPUNIT_ASSERT(!occupied(high, 4.0, 2.4));
  }

  void rectanglesAndDoorFrames() {
    const VectorWorld world = loaded(kWorld);
    // Poster on the south face of the north wall (right of west->east), centred at x = 2.2.
    const Rectangle3D& poster = world.rectangles[0];
    CPPUNIT_ASSERT_EQUAL(std::string("poster"), poster.label);
    CPPUNIT_ASSERT((poster.corners[0] - Eigen::Vector3d(1.9, 4.1, 1.2)).norm() < 1e-9);
    CPPUNIT_ASSERT((poster.corners[2] - Eigen::Vector3d(2.5, 4.1, 2.0)).norm() < 1e-9);
    CPPUNIT_ASSERT((world.rectangles[1].corners[3] - Eigen::Vector3d(1, 1, 2)).norm() < 1e-12);
    const std::vector<Rectangle3D> frames = doorFrames(world);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), frames.size());
    const Rectangle3D& frame = frames[0];  // partition door; the partition runs south->north, left is west
    CPPUNIT_ASSERT_EQUAL(std::string("door_frame"), frame.label);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.2, (frame.corners[1] - frame.corners[0]).norm(), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.1, (frame.corners[2] - frame.corners[1]).norm(), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.15, frame.corners[0].x(), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.25, frames[1].corners[0].x(), 1e-9);
  }

  void roomGroundTruth() {
    const VectorWorld world = loaded(kWorld);
    const OccupancyGrid grid = rasterize(world);
    const GroundTruth truth = groundTruthOf(world, grid);
    CPPUNIT_ASSERT_EQUAL(2, truth.roomCount);
    CPPUNIT_ASSERT_EQUAL(0, truth.roomOf(*grid.cellOf({1.0, 3.5})));
    CPPUNIT_ASSERT_EQUAL(1, truth.roomOf(*grid.cellOf({8.0, 2.0})));
    CPPUNIT_ASSERT_EQUAL(-1, truth.roomOf(*grid.cellOf({2.0, 1.0})));  // under the cabinet
    CPPUNIT_ASSERT_EQUAL(-1, truth.roomOf(*grid.cellOf({5.2, 2.2})));  // in the doorway
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), truth.doors.size());
    const DoorLine& inner = truth.doors[0];  // partition runs south->north: west is left
    CPPUNIT_ASSERT_EQUAL(0, inner.roomA);
    CPPUNIT_ASSERT_EQUAL(1, inner.roomB);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.7, inner.a.y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.7, inner.b.y, 1e-9);
    const DoorLine& outer = truth.doors[1];  // south wall: the east room on the left, outside on the right
    CPPUNIT_ASSERT_EQUAL(1, outer.roomA);
    CPPUNIT_ASSERT_EQUAL(-1, outer.roomB);
  }

  void floorPlanBaseLayer() {
    TempDir dir;
    cv::Mat plan(20, 40, CV_8UC1, cv::Scalar(255));
    plan.row(0).setTo(0);  // top row: a wall
    writeImage(dir.file("plan.png"), plan);
    writeFile(dir.file("world.yaml"), R"(resolution: 0.1
floor_plan: {image: plan.png, origin: [-1, -1]}
cylinders: [{center: [1.0, 0.0], radius: 0.1, height: 1.0}]
)");
    const VectorWorld world = loadVectorWorld(dir.file("world.yaml"));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, world.max.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, world.max.y, 1e-12);
    const OccupancyGrid grid = rasterize(world);
    CPPUNIT_ASSERT_EQUAL(40, grid.width());
    CPPUNIT_ASSERT(occupied(grid, 0.0, 0.95));   // the image's top row
    CPPUNIT_ASSERT(occupied(grid, 1.0, 0.0));    // the cylinder
    CPPUNIT_ASSERT(!occupied(grid, -0.5, 0.0));

    writeFile(dir.file("world.yaml"), "floor_plan: {image: missing.png}\n");
    try {
      loadVectorWorld(dir.file("world.yaml"));
      CPPUNIT_FAIL("no error for a missing floor plan image");
    } catch (const FileError& e) {
      const std::string what = e.what();
      CPPUNIT_ASSERT_MESSAGE(what, what.find(dir.file("world.yaml")) != std::string::npos);
      CPPUNIT_ASSERT_MESSAGE(what, what.find("floor_plan.image") != std::string::npos);
      CPPUNIT_ASSERT_MESSAGE(what, what.find(dir.file("missing.png")) != std::string::npos);
    }
  }

  void badWorldsAreTypedErrors() {
    const std::string world = kWorld;
    expectError<ConfigError>(world + "lights: []\n", {"lights", "unknown key"});
    expectError<ConfigError>(edited(world, "thickness: 0.2}", "thicknes: 0.2}"), {"walls[0].thicknes", "unknown key"});
    expectError<ConfigError>(edited(world, "thickness: 0.2}", "thickness: -0.2}"), {"walls[0].thickness"});
    expectError<ConfigError>(edited(world, "{wall: partition", "{wall: partishun"), {"doors[0].wall", "partishun"});
    expectError<ConfigError>(edited(world, "offset: 2.0, width: 1.0", "offset: 3.8, width: 1.0"), {"doors[0].width"});
    expectError<ConfigError>(edited(world, "center: [8.0, 0.25]", "center: [8.0, 1.25]"), {"doors[1].center"});
    expectError<ConfigError>(edited(world, "frame_width: 1.2", "frame_width: 0.8"), {"doors[0].frame_width"});
    expectError<ConfigError>(edited(world, "side: right", "side: up"), {"rectangles3d[0].side"});
    expectError<ConfigError>(edited(world, "[1, 1, 2]]}", "]}"), {"rectangles3d[1].corners"});
    expectError<ConfigError>(edited(world, "[5.15, 4.1], [0.3, 4.1]]}", "]}"), {"rooms[0].polygon"});
    expectError<ConfigError>(edited(world, "size: [10.4, 4.4]", "bounds: {min: [0, 0], max: [10, 4]}\nsize: [1, 1]"),
                             {"exactly one of"});
    expectError<ConfigError>(edited(world, "size: [10.4, 4.4]", "bounds: {min: [0, 0], max: [-1, 4]}"), {"bounds.max"});
    expectError<ConfigError>(edited(world, "name: east,", "name: west,"), {"walls[3].name", "duplicate"});
    expectError<ConfigError>(edited(world, "height: 1.8}", "height: tall}"), {"boxes[0].height"});
    expectError<ConfigError>(edited(world, "open: false", "open: maybe"), {"doors[1].open"});
    expectError<ConfigError>(world + "walls: []\n", {"walls"});
    expectError<ConfigError>("size: [1, 1]\nwalls: [{from: [0, 0], to: [1, 1]\n", {"YAML syntax error"});
    expectError<ConfigError>("size: [1, 1]\nwalls: [{from: [0, 0], to: [0, 0], thickness: 0.1}]\n", {"walls[0].to"});
    expectError<FileError>("floor_plan: {image: /nonexistent/plan.png}\n", {"/nonexistent/plan.png"});
    CPPUNIT_ASSERT_THROW(loadVectorWorld("/nonexistent/world.yaml"), FileError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(VectorWorldTest);
