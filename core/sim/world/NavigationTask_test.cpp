// Tests navigation tasks in map_server YAML files: start, goal and the reference path length
// read from the extra keys, a map without them has no task, malformed or half tasks are
// ConfigErrors naming the key, and all 150 BARN worlds load with their benchmark task.
#include <cppunit/extensions/HelperMacros.h>

#include <filesystem>

#include "core/logs/LogTestFiles.h"
#include "core/raster/ImageFile.h"
#include "core/sim/world/MapServerYaml.h"

using namespace rgnav;
using rgnav::testing::TempDir;
using rgnav::testing::writeFile;

namespace {

// A 4 x 2 m free map at 0.1 m: x from -1.5 to 2.5, y from 2 to 4.
const char* kMapYaml = R"(image: map.png
resolution: 0.1
origin: [-1.5, 2.0, 0.0]
occupied_thresh: 0.65
free_thresh: 0.196
)";

std::string writeMap(TempDir& dir, const std::string& extra) {
  writeImage(dir.file("map.png"), cv::Mat(20, 40, CV_8UC1, cv::Scalar(255)));
  writeFile(dir.file("map.yaml"), std::string(kMapYaml) + extra);
  return dir.file("map.yaml");
}

void expectConfigError(const std::string& yaml, const std::string& mention) {
  try {
    loadMapServerWorld(yaml);
    CPPUNIT_FAIL("no error for a task that mentions " + mention);
  } catch (const ConfigError& e) {
    CPPUNIT_ASSERT_MESSAGE(e.what(), std::string(e.what()).find(mention) != std::string::npos);
  }
}

}  // namespace

class NavigationTaskTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(NavigationTaskTest);
  CPPUNIT_TEST(taskKeysMakeATask);
  CPPUNIT_TEST(aPlainMapHasNoTask);
  CPPUNIT_TEST(badTasksAreConfigErrors);
  CPPUNIT_TEST(barnWorldsLoadWithTheirTask);
  CPPUNIT_TEST_SUITE_END();

 public:
  void taskKeysMakeATask() {
    TempDir dir;
    const MapServerWorld world =
        loadMapServerWorld(writeMap(dir, "start: [-1.0, 2.5, 1.57]\ngoal: [2.0, 3.5]\nreference_path_length_m: 3.4\n"));
    CPPUNIT_ASSERT(world.task.has_value());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-1.0, world.task->start.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.5, world.task->start.y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.57, world.task->start.theta, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, world.task->goal.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.5, world.task->goal.y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.4, world.task->referencePathLength.value_or(0.0), 1e-12);
    CPPUNIT_ASSERT(!world.task->obstacleCount);
    CPPUNIT_ASSERT_EQUAL(40, world.grid.width());
  }

  void aPlainMapHasNoTask() {
    TempDir dir;
    CPPUNIT_ASSERT(!loadMapServerWorld(writeMap(dir, "")).task);
  }

  void badTasksAreConfigErrors() {
    TempDir dir;
    expectConfigError(writeMap(dir, "start: [0, 3, 0]\n"), "goal");
    expectConfigError(writeMap(dir, "goal: [0, 3]\n"), "start");
    expectConfigError(writeMap(dir, "start: [0, 3]\ngoal: [0, 3]\n"), "start");
    expectConfigError(writeMap(dir, "start: [0, 3, 0]\ngoal: [0, 3, 1]\n"), "goal");
    expectConfigError(writeMap(dir, "start: [0, 3, 0]\ngoal: [9, 3]\n"), "goal");
    expectConfigError(writeMap(dir, "start: [0, 1, 0]\ngoal: [0, 3]\n"), "start");
    expectConfigError(writeMap(dir, "start: [0, 3, 0]\ngoal: [0, 3.5]\nreference_path_length_m: 0\n"),
                      "reference_path_length_m");
    expectConfigError(writeMap(dir, "reference_path_length_m: 2\n"), "reference_path_length_m");
    expectConfigError(writeMap(dir, "start: [0, 3, 0]\ngoal: [0, 3.5]\ncylinders: -1\n"), "cylinders");
    // The map alone is checked with its task keys too.
    CPPUNIT_ASSERT_THROW(loadMapServerYaml(writeMap(dir, "start: [0, 3, 0]\n")), ConfigError);
  }

  void barnWorldsLoadWithTheirTask() {
    int worlds = 0;
    for (const auto& entry : std::filesystem::directory_iterator(rgnav::testing::sharedData("planning/barn"))) {
      if (entry.path().extension() != ".yaml") continue;
      ++worlds;
      const std::string name = entry.path().string();
      const MapServerWorld world = loadMapServerWorld(name);
      CPPUNIT_ASSERT_MESSAGE(name, world.task.has_value());
      CPPUNIT_ASSERT_DOUBLES_EQUAL(-2.0, world.task->start.x, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, world.task->start.y, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(1.57, world.task->start.theta, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(13.0, world.task->goal.y, 1e-12);
      // Reference paths run from start to goal through the field: at least the 10 m between.
      CPPUNIT_ASSERT(world.task->referencePathLength.value_or(0.0) >= 10.0);
      CPPUNIT_ASSERT(world.task->obstacleCount.value_or(0) > 0);
      CPPUNIT_ASSERT(world.grid.at(*world.grid.cellOf({-2.0, 3.0})) == Cell::Free);
    }
    CPPUNIT_ASSERT_EQUAL(150, worlds);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(NavigationTaskTest);
