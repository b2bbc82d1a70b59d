// Tests the incremental region line map: a synthetic room seen from many poses collapses to its
// walls with the support counted; real Intel scans give a plausible, compact map.
#include "core/lines/RegionLineMap.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>

#include "core/lines/testing/SyntheticScan.h"
#include "core/logs/LogTestFiles.h"
#include "core/logs/OpenLog.h"

using rgnav::Pose2D;
using rgnav::RegionLineMap;

class RegionLineMapTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionLineMapTest);
  CPPUNIT_TEST(syntheticRoomCollapsesToItsWalls);
  CPPUNIT_TEST(realIntelScansGiveCompactMap);
  CPPUNIT_TEST_SUITE_END();

 public:
  void syntheticRoomCollapsesToItsWalls() {
    // A 6 x 4 m room with a 1 x 0.6 m cabinet; 12 noisy scans from different poses.
    auto walls = rgnav::testing::boxWalls({0, 0}, 0.0, 6.0, 4.0);
    const auto cabinet = rgnav::testing::boxWalls({1.5, 1.0}, 0.0, 1.0, 0.6);
    walls.insert(walls.end(), cabinet.begin(), cabinet.end());
    RegionLineMap map;
    std::size_t points = 0;
    for (int k = 0; k < 12; ++k) {
      const Pose2D pose{-2.0 + 0.3 * k, -1.0 + 0.1 * k, 0.5 * k};
      rgnav::testing::ScanSpec spec;
      spec.noiseSigmaM = 0.005;
      spec.seed = unsigned(k + 1);
      const auto scan = rgnav::testing::syntheticScan(walls, pose, spec);
      points +=
          std::size_t(std::count_if(scan.ranges.begin(), scan.ranges.end(), [](float r) { return std::isfinite(r); }));
      map.addScan(scan, pose);
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(12), map.scanCount());
    CPPUNIT_ASSERT_EQUAL(points, map.pointCount());
    // The four room walls and the cabinet's visible faces; nothing else.
    CPPUNIT_ASSERT(map.lines().size() >= 6 && map.lines().size() <= 8);
    std::size_t support = 0;
    for (const auto& line : map.lines()) support += line.support();
    CPPUNIT_ASSERT_EQUAL(map.segmentCount(), support);
    // Each room wall is one line seen in several scans.
    for (const auto& w : rgnav::testing::boxWalls({0, 0}, 0.0, 6.0, 4.0)) {
      const auto on = std::count_if(map.lines().begin(), map.lines().end(), [&](const auto& line) {
        const Eigen::Vector2d d = (w.b - w.a).normalized();
        const auto off = [&](const Eigen::Vector2d& p) {
          return std::fabs(d.x() * (p - w.a).y() - d.y() * (p - w.a).x());
        };
        return off(line.start) < 0.01 && off(line.end) < 0.01 && line.length() > 1.0 && line.support() >= 3;
      });
      CPPUNIT_ASSERT_EQUAL(std::ptrdiff_t(1), on);
    }
  }

  void realIntelScansGiveCompactMap() {
    // Intel Research Lab, corrected keyframes 215-244 (a corridor corner and a small room, the
    // robot turning in place twice), placed at their corrected poses.
    const auto log = rgnav::openLog(rgnav::testing::sharedData("laser/corrected/intel-corrected.log.gz"));
    RegionLineMap map;
    while (auto record = log->next()) {
      const auto* scan = std::get_if<rgnav::LaserScan>(&*record);
      if (scan == nullptr || scan->id < 215) continue;
      if (scan->id > 244) break;
      map.addScan(*scan, scan->sensorPose);
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(30), map.scanCount());
    CPPUNIT_ASSERT(map.pointCount() > 4000);
    CPPUNIT_ASSERT(map.lines().size() >= 20);
    CPPUNIT_ASSERT(map.lines().size() * 20 <= map.pointCount());
    CPPUNIT_ASSERT(map.segmentCount() > 2 * map.lines().size());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RegionLineMapTest);
