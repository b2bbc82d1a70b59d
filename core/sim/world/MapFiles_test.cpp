// Tests the map loaders: floor-plan images (threshold 250, row flip, resolution, origin) and
// ROS map_server YAML files (trinary thresholds, negate, PGM and PNG images, strict keys,
// missing images).
#include <cppunit/extensions/HelperMacros.h>

#include "core/logs/LogTestFiles.h"
#include "core/raster/ImageFile.h"
#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/MapServerYaml.h"

using namespace rgnav;
using rgnav::testing::TempDir;
using rgnav::testing::writeFile;

namespace {

// 4 x 2 pixels, top row 0 249 250 255, bottom row 205 254 100 0.
cv::Mat sample() { return (cv::Mat_<std::uint8_t>(2, 4) << 0, 249, 250, 255, 205, 254, 100, 0); }

const char* kMapYaml = R"(image: map.pgm
resolution: 0.1
origin: [-1.5, 2.0, 0.0]
negate: 0
occupied_thresh: 0.65
free_thresh: 0.196
)";

std::string edited(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  CPPUNIT_ASSERT(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

template <typename Error>
void expectError(const std::string& yaml, const std::vector<std::string>& mentions) {
  try {
    loadMapServerYaml(yaml);
    CPPUNIT_FAIL("no error for " + yaml);
  } catch (const Error& e) {
    for (const std::string& m : mentions) {
      CPPUNIT_ASSERT_MESSAGE(std::string(e.what()) + " lacks " + m, std::string(e.what()).find(m) != std::string::npos);
    }
  }
}

}  // namespace

class MapFilesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(MapFilesTest);
  CPPUNIT_TEST(floorPlanThresholdAndFlip);
  CPPUNIT_TEST(realFloorPlanGeometry);
  CPPUNIT_TEST(mapServerTrinaryWithPgm);
  CPPUNIT_TEST(mapServerNegateWithPng);
  CPPUNIT_TEST(mapServerBadFilesAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void floorPlanThresholdAndFlip() {
    TempDir dir;
    writeImage(dir.file("plan.png"), sample());
    const OccupancyGrid grid = loadFloorPlan(dir.file("plan.png"), 0.1, {1.0, 2.0});
    CPPUNIT_ASSERT_EQUAL(4, grid.width());
    CPPUNIT_ASSERT_EQUAL(2, grid.height());
    // Image row 0 (top) is grid row 1.
    const Cell expected[2][4] = {{Cell::Occupied, Cell::Free, Cell::Occupied, Cell::Occupied},
                                 {Cell::Occupied, Cell::Occupied, Cell::Free, Cell::Free}};
    for (int row = 0; row < 2; ++row) {
      for (int col = 0; col < 4; ++col) CPPUNIT_ASSERT(grid.at({col, row}) == expected[row][col]);
    }
    CPPUNIT_ASSERT(grid.cellOf({1.05, 2.15}) == (CellIndex{0, 1}));
    CPPUNIT_ASSERT_THROW(loadFloorPlan(dir.file("plan.png"), 0.0), InvalidArgumentError);
  }

  void realFloorPlanGeometry() {
    const OccupancyGrid grid =
        loadFloorPlan(rgnav::testing::sharedData("floorplans/ipa_room_segmentation/test_maps/office_d.png"));
    CPPUNIT_ASSERT_EQUAL(1122, grid.width());
    CPPUNIT_ASSERT_EQUAL(661, grid.height());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.05, grid.resolution(), 1e-12);
    const auto free = std::count(grid.cells().begin(), grid.cells().end(), Cell::Free);
    // gt_stats.tsv: 882 m^2 free.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(882.0, double(free) * 0.05 * 0.05, 1.0);
  }

  void mapServerTrinaryWithPgm() {
    TempDir dir;
    writeImage(dir.file("map.pgm"), sample());
    writeFile(dir.file("map.yaml"), std::string(kMapYaml) + "mode: trinary\n");
    const OccupancyGrid grid = loadMapServerYaml(dir.file("map.yaml"));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, grid.resolution(), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-1.5, grid.origin().x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, grid.origin().y, 1e-12);
    // p = (255 - gray) / 255: 0 -> 1 occupied, 249 -> 0.024 free, 205 -> 0.196 unknown, 100 -> 0.61 unknown.
    const Cell top[4] = {Cell::Occupied, Cell::Free, Cell::Free, Cell::Free};
    const Cell bottom[4] = {Cell::Unknown, Cell::Free, Cell::Unknown, Cell::Occupied};
    for (int col = 0; col < 4; ++col) {
      CPPUNIT_ASSERT(grid.at({col, 1}) == top[col]);
      CPPUNIT_ASSERT(grid.at({col, 0}) == bottom[col]);
    }
  }

  void mapServerNegateWithPng() {
    TempDir dir;
    writeImage(dir.file("map.png"), sample());
    writeFile(dir.file("map.yaml"), edited(edited(kMapYaml, "map.pgm", "map.png"), "negate: 0", "negate: true"));
    const OccupancyGrid grid = loadMapServerYaml(dir.file("map.yaml"));
    // p = gray / 255: 0 free, 255 occupied.
    CPPUNIT_ASSERT(grid.at({0, 1}) == Cell::Free);
    CPPUNIT_ASSERT(grid.at({3, 1}) == Cell::Occupied);
  }

  void mapServerBadFilesAreTypedErrors() {
    TempDir dir;
    writeImage(dir.file("map.pgm"), sample());
    const std::string yaml = dir.file("map.yaml");
    writeFile(yaml, std::string(kMapYaml) + "colour: red\n");
    expectError<ConfigError>(yaml, {yaml, "colour", "unknown key"});
    writeFile(yaml, edited(kMapYaml, "resolution: 0.1\n", ""));
    expectError<ConfigError>(yaml, {yaml, "resolution", "missing"});
    writeFile(yaml, edited(kMapYaml, "0.0]", "0.5]"));
    expectError<ConfigError>(yaml, {yaml, "origin"});
    writeFile(yaml, edited(kMapYaml, "free_thresh: 0.196", "free_thresh: 0.7"));
    expectError<ConfigError>(yaml, {yaml, "free_thresh"});
    writeFile(yaml, std::string(kMapYaml) + "mode: scale\n");
    expectError<ConfigError>(yaml, {yaml, "mode"});
    writeFile(yaml, edited(kMapYaml, "negate: 0", "negate: 2"));
    expectError<ConfigError>(yaml, {yaml, "negate"});
    writeFile(yaml, std::string(kMapYaml) + "resolution: [1\n");
    expectError<ConfigError>(yaml, {yaml, "YAML"});
    writeFile(yaml, edited(kMapYaml, "map.pgm", "gone.pgm"));
    expectError<FileError>(yaml, {yaml, "image", dir.file("gone.pgm")});
    expectError<FileError>(dir.file("nothing.yaml"), {dir.file("nothing.yaml")});
    writeFile(dir.file("map.pgm"), "P5\n4 2\n255\n");
    writeFile(yaml, kMapYaml);
    expectError<FormatError>(yaml, {dir.file("map.pgm")});
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(MapFilesTest);
