// Tests the IPA ground truth against gt_stats.tsv of the shared floor plans: on all ten
// benchmark maps the room count and the separator (door line) count must match, for the empty
// and the furnished map alike; every kept room has more than 100 px; door lines have a room on
// either side.
#include <cppunit/extensions/HelperMacros.h>

#include <fstream>
#include <map>
#include <sstream>

#include "core/logs/LogTestFiles.h"
#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/IpaGroundTruth.h"

using namespace rgnav;

namespace {

const char* kTestMaps[] = {"Freiburg52_scan", "Freiburg79_scan", "lab_a_scan", "lab_b_scan", "lab_c_scan",
                           "lab_intel",       "office_a",        "office_b",   "office_c",   "office_d"};

std::string benchmarkFile(const std::string& relative) {
  return rgnav::testing::sharedData("floorplans/ipa_room_segmentation/" + relative);
}

struct Stats {
  int rooms = 0;
  int separators = 0;
};

// map -> (gt_rooms(>100px), sep_blobs(>=5px)) from gt_stats.tsv.
std::map<std::string, Stats> readStats() {
  std::ifstream in(benchmarkFile("gt_stats.tsv"));
  CPPUNIT_ASSERT_MESSAGE("cannot open gt_stats.tsv", in.good());
  std::string line;
  std::getline(in, line);
  CPPUNIT_ASSERT_EQUAL(std::string("map\tWxH\tfree_m2\tgt_rooms(>100px)\tgt_specks(<=100px)\tsep_blobs(>=5px)"), line);
  std::map<std::string, Stats> stats;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name, size, freeArea, specks;
    Stats s;
    fields >> name >> size >> freeArea >> s.rooms >> specks >> s.separators;
    stats[name] = s;
  }
  return stats;
}

GroundTruth load(const std::string& map, const std::string& worldImage) {
  const OccupancyGrid grid = loadFloorPlan(benchmarkFile("test_maps/" + worldImage));
  return loadIpaGroundTruth(benchmarkFile("test_maps/" + map + "_gt_segmentation.png"),
                            benchmarkFile("test_maps/" + map + ".png"), grid);
}

}  // namespace

class IpaGroundTruthTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(IpaGroundTruthTest);
  CPPUNIT_TEST(countsMatchGtStatsOnAllTenMaps);
  CPPUNIT_TEST(furnishedMapSharesTheGroundTruth);
  CPPUNIT_TEST(doorLinesJoinRooms);
  CPPUNIT_TEST(mismatchedImagesAreErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void countsMatchGtStatsOnAllTenMaps() {
    const std::map<std::string, Stats> stats = readStats();
    for (const std::string map : kTestMaps) {
      const GroundTruth truth = load(map, map + ".png");
      CPPUNIT_ASSERT_MESSAGE(map, stats.count(map) == 1);
      CPPUNIT_ASSERT_EQUAL_MESSAGE(map + " rooms", stats.at(map).rooms, truth.roomCount);
      CPPUNIT_ASSERT_EQUAL_MESSAGE(map + " separators", std::size_t(stats.at(map).separators), truth.doors.size());
      std::vector<int> area(static_cast<std::size_t>(truth.roomCount));
      for (const int label : truth.labels) {
        CPPUNIT_ASSERT(label >= -1 && label < truth.roomCount);
        if (label >= 0) ++area[static_cast<std::size_t>(label)];
      }
      for (const int pixels : area) CPPUNIT_ASSERT_MESSAGE(map, pixels > 100);
    }
  }

  void furnishedMapSharesTheGroundTruth() {
    const GroundTruth empty = load("office_b", "office_b.png");
    const GroundTruth furnished = load("office_b", "office_b_furnitures.png");
    CPPUNIT_ASSERT(empty.labels == furnished.labels);
    CPPUNIT_ASSERT_EQUAL(empty.doors.size(), furnished.doors.size());
  }

  // Every separator is a doorway or region border with a different room on either side, except
  // the blobs that run along walls of lab_b_scan (8) and the L-shaped one of lab_intel (1); see
  // IpaGroundTruth.h.
  void doorLinesJoinRooms() {
    const std::map<std::string, std::size_t> alongWalls{{"lab_b_scan", 8}, {"lab_intel", 1}};
    for (const std::string map : kTestMaps) {
      const GroundTruth truth = load(map, map + ".png");
      std::size_t joining = 0;
      for (const DoorLine& door : truth.doors) {
        joining += door.roomA >= 0 && door.roomB >= 0 && door.roomA != door.roomB;
        const double length = std::hypot(door.b.x - door.a.x, door.b.y - door.a.y);
        CPPUNIT_ASSERT_MESSAGE(map + " door line length " + std::to_string(length), length > 0.5 && length < 7.0);
      }
      const std::size_t odd = alongWalls.count(map) ? alongWalls.at(map) : 0;
      CPPUNIT_ASSERT_EQUAL_MESSAGE(map, truth.doors.size() - odd, joining);
    }
  }

  void mismatchedImagesAreErrors() {
    const OccupancyGrid other = loadFloorPlan(benchmarkFile("test_maps/office_d.png"));
    CPPUNIT_ASSERT_THROW(loadIpaGroundTruth(benchmarkFile("test_maps/office_a_gt_segmentation.png"),
                                            benchmarkFile("test_maps/office_a.png"), other),
                         InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(loadIpaGroundTruth(benchmarkFile("test_maps/nothing_gt_segmentation.png"),
                                            benchmarkFile("test_maps/office_d.png"), other),
                         FileError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(IpaGroundTruthTest);
