// Tests the global metric map on demand on the two-room tour: the map_server PGM + YAML load with
// the project's loader into the very grid that was built, occupied cells lie on the synthetic
// walls, free cells inside the floor, the rooms and the hallway are free, the gray values are
// map_server's, and bad requests are refused.
#include "core/rgmap/export/OccupancyMap.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"
#include "core/logs/LogTestFiles.h"
#include "core/raster/ImageFile.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"
#include "core/sim/world/MapServerYaml.h"

using namespace rgnav;

namespace {

double distanceToWall(const Eigen::Vector2d& p, const rgnav::testing::Wall& w) {
  const Eigen::Vector2d d = w.b - w.a;
  const double t = std::clamp((p - w.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (w.a + t * d - p).norm();
}

double distanceToWalls(const Eigen::Vector2d& p) {
  double best = 1e9;
  for (const rgnav::testing::Wall& w : rgnav::testing::hallwayWithTwoRooms().walls)
    best = std::min(best, distanceToWall(p, w));
  return best;
}

Cell cellAt(const OccupancyGrid& grid, double x, double y) {
  const auto c = grid.cellOf({x, y});
  return c ? grid.at(*c) : Cell::Unknown;
}

}  // namespace

class OccupancyMapTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(OccupancyMapTest);
  CPPUNIT_TEST(mapServerFilesLoadIntoTheSameGrid);
  CPPUNIT_TEST(occupiedCellsLieOnTheWalls);
  CPPUNIT_TEST(hallwayAndRoomsAreFree);
  CPPUNIT_TEST(grayValuesAreMapServers);
  CPPUNIT_TEST(badRequestsAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override {
    kernel_ = std::make_unique<RgMappingKernel>(rgnav::testing::twoRoomMap());
    grid_ = occupancyMapOf(kernel_->state());
  }

  void mapServerFilesLoadIntoTheSameGrid() {
    rgnav::testing::TempDir dir;
    const MapServerFiles files = exportOccupancyMap(dir.path(), "floor", kernel_->state());
    CPPUNIT_ASSERT_EQUAL(dir.file("floor.yaml"), files.yamlPath);
    CPPUNIT_ASSERT_EQUAL(dir.file("floor.pgm"), files.imagePath);
    const OccupancyGrid loaded = loadMapServerYaml(files.yamlPath);
    CPPUNIT_ASSERT_EQUAL(grid_.width(), loaded.width());
    CPPUNIT_ASSERT_EQUAL(grid_.height(), loaded.height());
    CPPUNIT_ASSERT_EQUAL(0.05, loaded.resolution());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(grid_.origin().x, loaded.origin().x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(grid_.origin().y, loaded.origin().y, 1e-9);
    CPPUNIT_ASSERT(grid_.cells() == loaded.cells());
    const std::string yaml = readCheckpoint(files.yamlPath).value();
    for (const char* key : {"image: floor.pgm\n", "resolution: 0.05\n", "origin: [", "negate: 0\n",
                            "occupied_thresh: 0.65\n", "free_thresh: 0.196\n"})
      CPPUNIT_ASSERT_MESSAGE(key, yaml.find(key) != std::string::npos);
  }

  void occupiedCellsLieOnTheWalls() {
    std::size_t occupied = 0;
    for (int row = 0; row < grid_.height(); ++row)
      for (int col = 0; col < grid_.width(); ++col) {
        const WorldPoint c = grid_.center({col, row});
        if (grid_.at({col, row}) == Cell::Occupied) {
          ++occupied;
          CPPUNIT_ASSERT(distanceToWalls({c.x, c.y}) < 0.05);
        } else if (grid_.at({col, row}) == Cell::Free) {
          CPPUNIT_ASSERT(c.x > 0.0 && c.x < 12.0 && c.y > 0.0 && c.y < 6.0);
        }
      }
    // Every stretch of wall the robot saw is there: the hallway's south wall and the rooms' walls.
    for (double x = 0.5; x < 12.0; x += 0.5)
      CPPUNIT_ASSERT(cellAt(grid_, x, 0.01) == Cell::Occupied || cellAt(grid_, x, -0.01) == Cell::Occupied);
    for (double y = 2.5; y < 6.0; y += 0.5)
      for (double x : {2.0, 6.0, 7.0, 11.0})
        CPPUNIT_ASSERT(cellAt(grid_, x + 0.01, y) == Cell::Occupied || cellAt(grid_, x - 0.01, y) == Cell::Occupied);
    CPPUNIT_ASSERT(occupied > 500);
  }

  void hallwayAndRoomsAreFree() {
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(1, 1), Eigen::Vector2d(6, 1), Eigen::Vector2d(11, 1),
                                     Eigen::Vector2d(4, 4), Eigen::Vector2d(9, 4), Eigen::Vector2d(4, 2)})
      CPPUNIT_ASSERT(cellAt(grid_, p.x(), p.y()) == Cell::Free);
    // Behind the walls nobody looked.
    CPPUNIT_ASSERT(cellAt(grid_, 1.0, 4.0) == Cell::Unknown);
    CPPUNIT_ASSERT(cellAt(grid_, 6.5, 4.0) == Cell::Unknown);
  }

  void grayValuesAreMapServers() {
    rgnav::testing::TempDir dir;
    const MapServerFiles files = exportOccupancyMap(dir.path(), "floor", kernel_->state());
    const cv::Mat image = readGrayImage(files.imagePath);
    std::size_t counts[256] = {};
    for (auto v = image.datastart; v != image.dataend; ++v) ++counts[*v];
    const std::size_t known = counts[kMapFreeGray] + counts[kMapOccupiedGray] + counts[kMapUnknownGray];
    CPPUNIT_ASSERT_EQUAL(image.total(), known);
    CPPUNIT_ASSERT(counts[kMapFreeGray] > 0 && counts[kMapOccupiedGray] > 0 && counts[kMapUnknownGray] > 0);
    // Image row 0 is the grid's top row.
    CPPUNIT_ASSERT_EQUAL(grid_.at({0, grid_.height() - 1}) == Cell::Unknown ? kMapUnknownGray
                         : grid_.at({0, grid_.height() - 1}) == Cell::Free ? kMapFreeGray
                                                                           : kMapOccupiedGray,
                         image.at<std::uint8_t>(0, 0));
  }

  void badRequestsAreRefused() {
    CPPUNIT_ASSERT_THROW(occupancyMapOf(RgMapState{}), NotAvailableError);
    CPPUNIT_ASSERT_THROW(occupancyMapOf(kernel_->state(), {0.0}), ConfigError);
    rgnav::testing::TempDir dir;
    CPPUNIT_ASSERT_THROW(writeMapServerMap(dir.path(), "", grid_), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(writeMapServerMap(dir.path(), "a/b", grid_), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(writeMapServerMap(dir.file("missing"), "floor", grid_), FileError);
  }

 private:
  std::unique_ptr<RgMappingKernel> kernel_;
  OccupancyGrid grid_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(OccupancyMapTest);
