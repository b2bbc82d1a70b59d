// Tests rectangle detection (thesis 3.2): constructed boxes (full, against a wall, with an open
// corner) and boxes scanned by a simulated laser from all sides or from one side only.
#include "core/objects/RectangleDetector.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>

#include "core/common/Errors.h"
#include "core/lines/RegionLineMap.h"
#include "core/lines/testing/SyntheticScan.h"

using Eigen::Vector2d;
using rgnav::LineSegment;
using rgnav::Pose2D;
using rgnav::Rectangle2D;
using rgnav::RectangleDetector;
using rgnav::RectangleDetectorParams;

namespace {

constexpr double kDeg = M_PI / 180.0;

// Sides of a box (centre, heading, length along the heading, width), each ending `gap` short
// of its corners; the side `shortSide` is cut to `keep` of its length, starting at its corner.
std::vector<LineSegment> boxLines(const Pose2D& pose, double length, double width, double gap = 0.05,
                                  int shortSide = -1, double keep = 1.0) {
  std::vector<LineSegment> lines;
  const auto walls = rgnav::testing::boxWalls({pose.x, pose.y}, pose.theta, length, width);
  for (std::size_t s = 0; s < walls.size(); ++s) {
    const Vector2d d = (walls[s].b - walls[s].a).normalized();
    const double len = (walls[s].b - walls[s].a).norm() - 2 * gap;
    const Vector2d a = walls[s].a + gap * d;
    const Vector2d b = a + (int(s) == shortSide ? keep : 1.0) * len * d;
    lines.push_back(rgnav::segmentFromEndpoints(s + 1, a, b));
  }
  return lines;
}

// The detected rectangle nearest to (x, y), if one lies within 0.2 m.
const Rectangle2D* near(const std::vector<Rectangle2D>& found, double x, double y) {
  const Rectangle2D* best = nullptr;
  for (const auto& r : found)
    if (std::hypot(r.pose.x - x, r.pose.y - y) < 0.2 &&
        (!best || std::hypot(r.pose.x - x, r.pose.y - y) < std::hypot(best->pose.x - x, best->pose.y - y)))
      best = &r;
  return best;
}

double headingError(double a, double b) { return rgnav::orientationDifference(a, b); }

}  // namespace

class RectangleDetectorTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RectangleDetectorTest);
  CPPUNIT_TEST(fullBoxGivesItsPoseSizeAndCoverage);
  CPPUNIT_TEST(boxAgainstWallUsesTheWallAsFourthSide);
  CPPUNIT_TEST(openCornerNeedsNonRestrictiveCase);
  CPPUNIT_TEST(scannedFromAllSides);
  CPPUNIT_TEST(scannedFromOneSideGivesNoRectangle);
  CPPUNIT_TEST(badParametersAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void fullBoxGivesItsPoseSizeAndCoverage() {
    // Width along the heading direction's normal; the length axis is the heading (30 degrees).
    const auto found = RectangleDetector().detect(boxLines({2, 1, 30 * kDeg}, 1.2, 0.8));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    const Rectangle2D& r = found[0];
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, r.pose.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, r.pose.y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30 * kDeg, r.pose.theta, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.2, r.lengthM, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.8, r.widthM, 1e-9);
    // Sides 1.1 + 0.7 + 1.1 + 0.7 of a perimeter of 4 m are seen.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.6 / 4.0, r.confidence, 1e-9);
    // Headings are reported in [0, pi): the same box turned by 180 degrees.
    const auto turned = RectangleDetector().detect(boxLines({2, 1, 210 * kDeg}, 1.2, 0.8));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), turned.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30 * kDeg, turned[0].pose.theta, 1e-9);
  }

  void boxAgainstWallUsesTheWallAsFourthSide() {
    // A 1.2 x 0.8 table against a 6 m wall: the wall line closes it.
    std::vector<LineSegment> lines{
        rgnav::segmentFromEndpoints(1, {-3, 0}, {3, 0}), rgnav::segmentFromEndpoints(2, {1.2, 0.05}, {1.2, 0.75}),
        rgnav::segmentFromEndpoints(3, {1.15, 0.8}, {0.05, 0.8}), rgnav::segmentFromEndpoints(4, {0, 0.75}, {0, 0.05})};
    const auto found = RectangleDetector().detect(lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.6, found[0].pose.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.4, found[0].pose.y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.2, found[0].lengthM, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.8, found[0].widthM, 1e-9);
    // The wall counts only where it borders the table: (1.2 + 0.7 + 1.1 + 0.7) / 4.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.7 / 4.0, found[0].confidence, 1e-9);
  }

  void openCornerNeedsNonRestrictiveCase() {
    // The third side is seen only over 40 % of its length: one corner stays open.
    const auto lines = boxLines({0, 0, 0.0}, 2.0, 1.0, 0.05, 2, 0.4);
    CPPUNIT_ASSERT(RectangleDetector().detect(lines).empty());
    RectangleDetectorParams p;
    p.grouping.restrictive = false;
    const auto found = RectangleDetector(p).detect(lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, found[0].pose.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, found[0].lengthM, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, found[0].widthM, 1e-9);
    // Seen: 1.9 + 0.9 + 0.76 + 0.9 of 6 m.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.46 / 6.0, found[0].confidence, 1e-9);
    p.minConfidence = 0.8;
    CPPUNIT_ASSERT(RectangleDetector(p).detect(lines).empty());
  }

  void scannedFromAllSides() {
    // A 1.2 x 0.8 cabinet turned by 20 degrees in a 10 x 8 m room, scanned from four places
    // around it (0.5 degree beams, 5 mm range noise); the line map is built as for a region.
    auto walls = rgnav::testing::boxWalls({0, 0}, 0.0, 10.0, 8.0);
    const auto cabinet = rgnav::testing::boxWalls({1.0, 0.5}, 20 * kDeg, 1.2, 0.8);
    walls.insert(walls.end(), cabinet.begin(), cabinet.end());
    rgnav::RegionLineMap map;
    for (int k = 0; k < 4; ++k) {
      const double a = k * M_PI / 2 + 0.3;
      const Pose2D pose{1.0 + 2.2 * std::cos(a), 0.5 + 2.2 * std::sin(a), a + M_PI};
      rgnav::testing::ScanSpec spec;
      spec.noiseSigmaM = 0.005;
      spec.seed = unsigned(k + 1);
      map.addScan(rgnav::testing::syntheticScan(walls, pose, spec), pose);
    }
    const auto found = RectangleDetector().detect(map.lines());
    const Rectangle2D* r = near(found, 1.0, 0.5);
    CPPUNIT_ASSERT(r != nullptr);
    CPPUNIT_ASSERT(std::hypot(r->pose.x - 1.0, r->pose.y - 0.5) < 0.02);
    CPPUNIT_ASSERT(headingError(r->pose.theta, 20 * kDeg) < 1.0 * kDeg);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.2, r->lengthM, 0.03);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.8, r->widthM, 0.03);
    CPPUNIT_ASSERT(r->confidence > 0.8);
  }

  void scannedFromOneSideGivesNoRectangle() {
    // Seen from one place only two sides of the cabinet show: no rectangle, in either case.
    const auto cabinet = rgnav::testing::boxWalls({1.0, 0.5}, 20 * kDeg, 1.2, 0.8);
    const Pose2D pose{3.0, 2.0, M_PI};
    rgnav::RegionLineMap map;
    map.addScan(rgnav::testing::syntheticScan(cabinet, pose), pose);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), map.lines().size());
    RectangleDetectorParams p;
    CPPUNIT_ASSERT(RectangleDetector(p).detect(map.lines()).empty());
    p.grouping.restrictive = false;
    CPPUNIT_ASSERT(RectangleDetector(p).detect(map.lines()).empty());
  }

  void badParametersAreTypedErrors() {
    RectangleDetectorParams p;
    p.minConfidence = 1.5;
    CPPUNIT_ASSERT_THROW(RectangleDetector{p}, rgnav::InvalidArgumentError);
    p = {};
    p.maxOverlapRatio = -0.1;
    CPPUNIT_ASSERT_THROW(RectangleDetector{p}, rgnav::InvalidArgumentError);
    p = {};
    p.grouping.maxNeighbourDistanceM = 0.0;
    CPPUNIT_ASSERT_THROW(RectangleDetector{p}, rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RectangleDetectorTest);
