// Tests the incremental region line map: a synthetic room seen from many poses collapses to its
// walls with the support counted; real Intel scans give a plausible, compact map; the map equals
// merging all lines again after each scan (3.1.1 on the whole map) on synthetic scans and is
// equivalent on real ones; the merge work per scan, counted as merge candidates, does not grow
// with the region; a non-finite pose is a typed error.
#include "core/lines/RegionLineMap.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <limits>

#include "core/common/Errors.h"
#include "core/lines/testing/SyntheticHallway.h"
#include "core/lines/testing/SyntheticScan.h"
#include "core/logs/LogTestFiles.h"
#include "core/logs/OpenLog.h"

using rgnav::LaserScan;
using rgnav::LineSegment;
using rgnav::Pose2D;
using rgnav::RegionLineMap;

namespace {

// The scans of a synthetic room (6 x 4 m with a cabinet) from 12 noisy poses.
std::vector<LaserScan> roomScans() {
  auto walls = rgnav::testing::boxWalls({0, 0}, 0.0, 6.0, 4.0);
  const auto cabinet = rgnav::testing::boxWalls({1.5, 1.0}, 0.0, 1.0, 0.6);
  walls.insert(walls.end(), cabinet.begin(), cabinet.end());
  std::vector<LaserScan> scans;
  for (int k = 0; k < 12; ++k) {
    const Pose2D pose{-2.0 + 0.3 * k, -1.0 + 0.1 * k, 0.5 * k};
    rgnav::testing::ScanSpec spec;
    spec.noiseSigmaM = 0.005;
    spec.seed = unsigned(k + 1);
    scans.push_back(rgnav::testing::syntheticScan(walls, pose, spec));
  }
  return scans;
}

// Intel Research Lab, corrected keyframes first .. last at their corrected poses.
std::vector<LaserScan> intelScans(rgnav::DataId first, rgnav::DataId last) {
  const auto log = rgnav::openLog(rgnav::testing::sharedData("laser/corrected/intel-corrected.log.gz"));
  std::vector<LaserScan> scans;
  while (auto record = log->next()) {
    const auto* scan = std::get_if<LaserScan>(&*record);
    if (scan == nullptr || scan->id < first) continue;
    if (scan->id > last) break;
    scans.push_back(*scan);
  }
  return scans;
}

// The map as built by merging the whole map with each scan's segments (LineMerger::merge).
std::vector<LineSegment> fullRemerge(const std::vector<LaserScan>& scans) {
  const rgnav::LineExtractor extractor;
  const rgnav::LineMerger merger;
  std::vector<LineSegment> lines;
  rgnav::SegmentId next = 1;
  for (const auto& scan : scans) {
    auto fresh = extractor.extract(scan, scan.sensorPose, next);
    next += fresh.size();
    lines.insert(lines.end(), fresh.begin(), fresh.end());
    lines = merger.merge(std::move(lines));
  }
  return lines;
}

// Asserts that `map` holds the same lines as `expected` (by ID: same parts, same endpoints in
// either direction within 1 micrometre) and keeps them sorted by orientation.
void assertSameLines(std::vector<LineSegment> expected, const RegionLineMap& map) {
  const auto byId = [](const LineSegment& a, const LineSegment& b) { return a.id < b.id; };
  std::vector<LineSegment> got = map.lines();
  CPPUNIT_ASSERT(std::is_sorted(got.begin(), got.end(), [](const LineSegment& a, const LineSegment& b) {
    return a.orientationRad() < b.orientationRad();
  }));
  std::sort(expected.begin(), expected.end(), byId);
  std::sort(got.begin(), got.end(), byId);
  CPPUNIT_ASSERT_EQUAL(expected.size(), got.size());
  CPPUNIT_ASSERT_EQUAL(expected.size(), map.lineCount());
  for (std::size_t i = 0; i < got.size(); ++i) {
    CPPUNIT_ASSERT_EQUAL(expected[i].id, got[i].id);
    CPPUNIT_ASSERT(expected[i].provenance == got[i].provenance);
    const double same = std::max((expected[i].start - got[i].start).norm(), (expected[i].end - got[i].end).norm());
    const double swapped = std::max((expected[i].start - got[i].end).norm(), (expected[i].end - got[i].start).norm());
    CPPUNIT_ASSERT(std::min(same, swapped) < 1e-6);
  }
}

// Asserts that no two lines of `map` can be merged under the thesis rules.
void assertNothingLeftToMerge(const RegionLineMap& map) {
  const rgnav::LineMerger merger;
  const auto& lines = map.lines();
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (std::size_t j = i + 1; j < lines.size(); ++j) CPPUNIT_ASSERT(!merger.tryMerge(lines[i], lines[j]));
}

// Merge candidates per scan while `scans` are added to a fresh map, and its final line count.
std::pair<double, std::size_t> candidatesPerScan(const std::vector<LaserScan>& scans) {
  RegionLineMap map;
  for (const auto& scan : scans) map.addScan(scan, scan.sensorPose);
  return {double(map.mergeCandidateCount()) / double(scans.size()), map.lineCount()};
}

}  // namespace

class RegionLineMapTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionLineMapTest);
  CPPUNIT_TEST(syntheticRoomCollapsesToItsWalls);
  CPPUNIT_TEST(realIntelScansGiveCompactMap);
  CPPUNIT_TEST(incrementalMapEqualsFullRemerge);
  CPPUNIT_TEST(realScansGiveEquivalentMap);
  CPPUNIT_TEST(mergeWorkPerScanDoesNotGrowWithRegion);
  CPPUNIT_TEST(nonFinitePoseIsTypedErrorAndChangesNothing);
  CPPUNIT_TEST_SUITE_END();

 public:
  void syntheticRoomCollapsesToItsWalls() {
    // A 6 x 4 m room with a 1 x 0.6 m cabinet; 12 noisy scans from different poses.
    RegionLineMap map;
    std::size_t points = 0;
    for (const auto& scan : roomScans()) {
      points +=
          std::size_t(std::count_if(scan.ranges.begin(), scan.ranges.end(), [](float r) { return std::isfinite(r); }));
      map.addScan(scan, scan.sensorPose);
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
    RegionLineMap map;
    for (const auto& scan : intelScans(215, 244)) map.addScan(scan, scan.sensorPose);
    CPPUNIT_ASSERT_EQUAL(std::size_t(30), map.scanCount());
    CPPUNIT_ASSERT(map.pointCount() > 4000);
    CPPUNIT_ASSERT(map.lines().size() >= 20);
    CPPUNIT_ASSERT(map.lines().size() * 20 <= map.pointCount());
    CPPUNIT_ASSERT(map.segmentCount() > 2 * map.lines().size());
  }

  void incrementalMapEqualsFullRemerge() {
    rgnav::testing::ScanSpec noisy;
    noisy.noiseSigmaM = 0.01;
    for (const auto& scans : {roomScans(), rgnav::testing::hallwayScans(20.0, 150, noisy)}) {
      RegionLineMap map;
      for (const auto& scan : scans) map.addScan(scan, scan.sensorPose);
      assertNothingLeftToMerge(map);
      assertSameLines(fullRemerge(scans), map);
    }
  }

  void realScansGiveEquivalentMap() {
    // On real scans greedy merging in another order can split a few segments differently
    // between two nearby lines (here two short lines at 0 / 180 degrees): the same number of
    // lines, nearly all of the same parts, and no mergeable pair left.
    const auto scans = intelScans(215, 244);
    RegionLineMap map;
    for (const auto& scan : scans) map.addScan(scan, scan.sensorPose);
    assertNothingLeftToMerge(map);
    const auto expected = fullRemerge(scans);
    CPPUNIT_ASSERT_EQUAL(expected.size(), map.lineCount());
    const auto same = std::count_if(map.lines().begin(), map.lines().end(), [&](const LineSegment& line) {
      return std::any_of(expected.begin(), expected.end(),
                         [&](const LineSegment& e) { return e.provenance == line.provenance; });
    });
    CPPUNIT_ASSERT(std::size_t(same) + 2 >= expected.size());
  }

  void mergeWorkPerScanDoesNotGrowWithRegion() {
    // Hallways of 30 and 120 m driven to the end and back with a scan every 0.1 m: four times the
    // lines, about the same merge work per scan, and less than half a candidate per map line and
    // scan (merging the whole map again looks at every line at least once per scan).
    rgnav::testing::ScanSpec spec;
    spec.noiseSigmaM = 0.01;
    const auto [shortWork, shortLines] = candidatesPerScan(rgnav::testing::hallwayScans(30.0, 561, spec));
    const auto [longWork, longLines] = candidatesPerScan(rgnav::testing::hallwayScans(120.0, 2361, spec));
    CPPUNIT_ASSERT(longLines > 3 * shortLines);
    CPPUNIT_ASSERT(longWork < 1.2 * shortWork);
    CPPUNIT_ASSERT(longWork < 0.5 * double(longLines));
  }

  void nonFinitePoseIsTypedErrorAndChangesNothing() {
    const auto scans = roomScans();
    RegionLineMap map;
    map.addScan(scans[0], scans[0].sensorPose);
    const auto before = map.lines();
    Pose2D bad = scans[1].sensorPose;
    bad.theta = std::numeric_limits<double>::quiet_NaN();
    CPPUNIT_ASSERT_THROW(map.addScan(scans[1], bad), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), map.scanCount());
    CPPUNIT_ASSERT_EQUAL(before.size(), map.lineCount());
    map.addScan(scans[1], scans[1].sensorPose);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), map.scanCount());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RegionLineMapTest);
