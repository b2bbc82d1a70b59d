// Tests the narrow-passage detector (thesis 4.2.1) on constructed scans: a door in a wall is
// found with its width, from any sensor pose, also to the side of a hallway (our several
// viewing directions); a gap narrower than D_lr^min, a door beyond D_NP^max, niches without
// open space behind, gaps between table legs and a plain hallway are rejected; bad
// configurations are typed errors.
#include "core/gateways/passages/NarrowPassageDetector.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"
#include "core/lines/testing/SyntheticScan.h"

using Eigen::Vector2d;
using rgnav::NarrowPassageConfig;
using rgnav::NarrowPassageDetector;
using rgnav::PassageHypothesis;
using rgnav::Pose2D;
using rgnav::testing::boxWalls;
using rgnav::testing::syntheticScan;
using rgnav::testing::Wall;

namespace {

// A wall across the robot's view at x = wallX (sensor frame: x ahead, y left) with an opening
// from y = -width/2 to +width/2, a room of the given depth behind it, and the side walls of the
// hallway the robot stands in (y = ±3).
std::vector<Wall> wallWithOpening(double wallX, double width, double roomDepth) {
  const double h = width / 2;
  return {{{wallX, -3}, {wallX, -h}}, {{wallX, h}, {wallX, 3}},
          {{wallX, -3}, {wallX + roomDepth, -3}}, {{wallX, 3}, {wallX + roomDepth, 3}},
          {{wallX + roomDepth, -3}, {wallX + roomDepth, 3}},
          {{-2, -3}, {wallX, -3}}, {{-2, 3}, {wallX, 3}}};
}

// Walls given in the sensor frame, placed for a sensor at `pose`.
std::vector<Wall> placed(const std::vector<Wall>& local, const Pose2D& pose) {
  std::vector<Wall> walls;
  for (const Wall& w : local) walls.push_back({rgnav::transformPoint(pose, w.a), rgnav::transformPoint(pose, w.b)});
  return walls;
}

std::vector<PassageHypothesis> detect(const std::vector<Wall>& local, const Pose2D& pose = {},
                                      const NarrowPassageConfig& config = {}) {
  rgnav::LaserScan scan = syntheticScan(placed(local, pose), pose);
  scan.id = 7;
  return NarrowPassageDetector(config).detect(scan, pose);
}

}  // namespace

class NarrowPassageDetectorTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(NarrowPassageDetectorTest);
  CPPUNIT_TEST(doorAheadIsFoundWithItsWidth);
  CPPUNIT_TEST(doorIsFoundInTheWorldFrameOfAnyPose);
  CPPUNIT_TEST(doorToTheSideNeedsMoreViewingDirections);
  CPPUNIT_TEST(gapBelowMinimumWidthIsRejected);
  CPPUNIT_TEST(doorBeyondMaximumDistanceIsRejected);
  CPPUNIT_TEST(nichesWithoutOpenSpaceBehindAreRejected);
  CPPUNIT_TEST(gapBetweenTableLegsIsRejected);
  CPPUNIT_TEST(plainHallwayIsNoPassage);
  CPPUNIT_TEST(badConfigurationsAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void doorAheadIsFoundWithItsWidth() {
    const auto found = detect(wallWithOpening(2.0, 0.9, 4.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    const PassageHypothesis& h = found[0];
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(7), h.scanId);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.9, h.widthM, 0.04);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(h.widthM, (h.left - h.right).norm(), 1e-9);
    CPPUNIT_ASSERT((h.left - Vector2d(2.0, 0.45)).norm() < 0.04);  // P_left has the larger bearing
    CPPUNIT_ASSERT((h.right - Vector2d(2.0, -0.45)).norm() < 0.04);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, h.distanceM, 0.02);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0 * std::atan(0.45 / 2.0), h.apertureRad, 0.03);
    CPPUNIT_ASSERT(h.confidence > 0.9 && h.confidence <= 1.0);
  }

  void doorIsFoundInTheWorldFrameOfAnyPose() {
    const Pose2D pose{10.0, -4.0, 2.0};
    const auto found = detect(wallWithOpening(2.5, 1.0, 4.0), pose);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, found[0].widthM, 0.04);
    CPPUNIT_ASSERT((found[0].midpoint() - rgnav::transformPoint(pose, {2.5, 0.0})).norm() < 0.03);
  }

  void doorToTheSideNeedsMoreViewingDirections() {
    // A hallway 2 m wide along x; a 0.9 m door in its left wall at x = 1.5 .. 2.4, a room behind.
    const std::vector<Wall> walls{{{-2, -1}, {8, -1}}, {{-2, 1}, {1.5, 1}}, {{2.4, 1}, {8, 1}},
                                  {{1.5, 1}, {1.5, 5}}, {{2.4, 1}, {5, 1}}, {{1.5, 5}, {5, 5}}, {{5, 1}, {5, 5}}};
    const auto found = detect(walls);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.9, found[0].widthM, 0.05);
    CPPUNIT_ASSERT((found[0].midpoint() - Vector2d(1.95, 1.0)).norm() < 0.05);
    CPPUNIT_ASSERT(found[0].viewingDirectionRad > 0.0);
    NarrowPassageConfig headingOnly;  // the thesis: the robot's heading is the only α_m
    headingOnly.viewingStepRad = M_PI;
    CPPUNIT_ASSERT(detect(walls, {}, headingOnly).empty());
  }

  void gapBelowMinimumWidthIsRejected() {
    CPPUNIT_ASSERT(detect(wallWithOpening(2.0, 0.4, 4.0)).empty());  // D_lr^min = 0.6 m
    NarrowPassageConfig smallRobot;
    smallRobot.robotRadiusM = 0.15;
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), detect(wallWithOpening(2.0, 0.4, 4.0), {}, smallRobot).size());
  }

  void doorBeyondMaximumDistanceIsRejected() {
    CPPUNIT_ASSERT(detect(wallWithOpening(4.0, 0.9, 4.0)).empty());  // D_NP^max = 3 m
    NarrowPassageConfig farther;
    farther.maxDistanceM = 5.0;
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), detect(wallWithOpening(4.0, 0.9, 4.0), {}, farther).size());
  }

  void nichesWithoutOpenSpaceBehindAreRejected() {
    for (const double depth : {0.3, 0.8}) {  // the walk runs through the first, the second is too shallow
      const auto found = detect(wallWithOpening(2.0, 0.9, depth));
      CPPUNIT_ASSERT_MESSAGE("niche depth " + std::to_string(depth), found.empty());
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), detect(wallWithOpening(2.0, 0.9, 1.5)).size());
  }

  void gapBetweenTableLegsIsRejected() {
    // Two legs of 0.1 m, 1 m apart, 1.5 m ahead in an open room.
    std::vector<Wall> walls = boxWalls({1.5, -0.5}, 0.0, 0.1, 0.1);
    for (const Wall& w : boxWalls({1.5, 0.5}, 0.0, 0.1, 0.1)) walls.push_back(w);
    for (const Wall& w : boxWalls({2.0, 0.0}, 0.0, 12.0, 10.0)) walls.push_back(w);
    CPPUNIT_ASSERT(detect(walls).empty());
  }

  void plainHallwayIsNoPassage() {
    CPPUNIT_ASSERT(detect({{{-2, -0.75}, {20, -0.75}}, {{-2, 0.75}, {20, 0.75}}}).empty());
  }

  void badConfigurationsAreTypedErrors() {
    const auto bad = [](auto change) {
      NarrowPassageConfig config;
      change(config);
      CPPUNIT_ASSERT_THROW(NarrowPassageDetector{config}, rgnav::ConfigError);
    };
    bad([](NarrowPassageConfig& c) { c.robotRadiusM = 0.0; });
    bad([](NarrowPassageConfig& c) { c.maxDoorWidthM = 0.5; });  // not above D_lr^min
    bad([](NarrowPassageConfig& c) { c.maxDistanceM = std::nan(""); });
    bad([](NarrowPassageConfig& c) { c.halfRangeRad = 4.0; });
    bad([](NarrowPassageConfig& c) { c.minBeamsBehind = 0; });
    bad([](NarrowPassageConfig& c) { c.surfaceBreaks.lambdaRad = M_PI; });
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(NarrowPassageDetectorTest);
