// Tests line extraction from single scans of known walls: endpoints at the corners, breakpoints
// at depth jumps, robustness to range noise, invalid and missing returns, parameter checks.
#include "core/lines/LineExtractor.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>

#include "core/common/Errors.h"
#include "core/lines/testing/SyntheticScan.h"

using Eigen::Vector2d;
using rgnav::LineExtractor;
using rgnav::LineSegment;
using rgnav::Pose2D;
using rgnav::testing::boxWalls;
using rgnav::testing::ScanSpec;
using rgnav::testing::syntheticScan;
using rgnav::testing::Wall;

namespace {

// A full-circle scan of 720 beams of 0.5 degrees whose first beam points at `corner`, so that
// no wall is cut in two where the scan starts and ends.
ScanSpec fullCircle(const Vector2d& corner, const Pose2D& pose, double noise = 0.0) {
  ScanSpec spec;
  spec.beams = 720;
  spec.startAngleRad = std::atan2(corner.y() - pose.y, corner.x() - pose.x) - pose.theta;
  spec.noiseSigmaM = noise;
  return spec;
}

// Distance of the segment's endpoints (either order) from the wall's endpoints.
double endpointError(const LineSegment& s, const Wall& w) {
  return std::min(std::max((s.start - w.a).norm(), (s.end - w.b).norm()),
                  std::max((s.start - w.b).norm(), (s.end - w.a).norm()));
}

// The largest distance of the segment's endpoints from the wall's line.
double offLine(const LineSegment& s, const Wall& w) {
  const Vector2d d = (w.b - w.a).normalized();
  const auto dist = [&](const Vector2d& p) { return std::fabs(d.x() * (p - w.a).y() - d.y() * (p - w.a).x()); };
  return std::max(dist(s.start), dist(s.end));
}

}  // namespace

class LineExtractorTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LineExtractorTest);
  CPPUNIT_TEST(roomWallsGiveOneSegmentEachWithCornerEndpoints);
  CPPUNIT_TEST(breakpointsSeparateOccluderFromWall);
  CPPUNIT_TEST(breakpointDetectorCutsAtDepthJumpsOnly);
  CPPUNIT_TEST(noisyScanGivesSameWalls);
  CPPUNIT_TEST(invalidAndMissingReturnsAreSkipped);
  CPPUNIT_TEST(minimumPointsAndLengthDropSmallPieces);
  CPPUNIT_TEST(segmentsAreInTheFrameOfTheSensorPose);
  CPPUNIT_TEST(badParametersAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void roomWallsGiveOneSegmentEachWithCornerEndpoints() {
    const auto walls = boxWalls({0, 0}, 0.0, 6.0, 4.0);
    const Pose2D pose{0.5, -0.3, 0.2};
    const auto segments = LineExtractor().extract(syntheticScan(walls, pose, fullCircle(walls[0].a, pose)), pose, 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), segments.size());
    for (const Wall& w : walls) {
      const auto& s = *std::min_element(segments.begin(), segments.end(), [&](const auto& a, const auto& b) {
        return endpointError(a, w) < endpointError(b, w);
      });
      // Beams 0.5 degrees apart hit the walls near the corners at most 6 cm apart: the end
      // points lie within one spacing of the corners.
      CPPUNIT_ASSERT(endpointError(s, w) < 0.06);
      CPPUNIT_ASSERT(offLine(s, w) < 1e-6);
      CPPUNIT_ASSERT(s.fit().rmsResidualM < 1e-6);
    }
    // IDs are consecutive from the first ID, each segment its own provenance.
    for (std::size_t i = 0; i < segments.size(); ++i) {
      CPPUNIT_ASSERT_EQUAL(rgnav::SegmentId(1 + i), segments[i].id);
      CPPUNIT_ASSERT(segments[i].provenance == std::vector<rgnav::SegmentId>{segments[i].id});
    }
  }

  void breakpointsSeparateOccluderFromWall() {
    // A wall 4 m ahead, a 1 m board 2 m ahead in front of its middle: three segments, none of
    // which bridges the depth jump.
    const std::vector<Wall> walls{{{4, -3}, {4, 3}}, {{2, -0.5}, {2, 0.5}}};
    ScanSpec spec;  // 180 degrees ahead
    const auto segments = LineExtractor().extract(syntheticScan(walls, {0, 0, 0}, spec), {0, 0, 0}, 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), segments.size());
    int onWall = 0, onBoard = 0;
    for (const auto& s : segments) {
      if (offLine(s, walls[0]) < 1e-6) ++onWall;
      if (offLine(s, walls[1]) < 1e-6) ++onBoard;
    }
    CPPUNIT_ASSERT_EQUAL(2, onWall);
    CPPUNIT_ASSERT_EQUAL(1, onBoard);
    // The wall pieces end at the edges of the board's shadow (|y| = 1 m on the wall).
    for (const auto& s : segments)
      if (offLine(s, walls[0]) < 1e-6)
        CPPUNIT_ASSERT(std::min(std::fabs(std::fabs(s.start.y()) - 1.0), std::fabs(std::fabs(s.end.y()) - 1.0)) < 0.04);
  }

  void breakpointDetectorCutsAtDepthJumpsOnly() {
    // Points along a wall at 3 m, a jump to 2 m, then a skipped beam.
    std::vector<rgnav::ScanPoint> points;
    const double inc = M_PI / 180;
    const auto at = [&](std::size_t beam, double r) {
      const double b = double(beam) * inc;
      points.push_back({Vector2d(r * std::cos(b), r * std::sin(b)), r, beam});
    };
    for (std::size_t k = 0; k < 5; ++k) at(k, 3.0);
    for (std::size_t k = 5; k < 10; ++k) at(k, 2.0);
    at(11, 2.0);  // beam 10 missing: 2 degrees, no jump in depth
    at(30, 2.0);  // 19 degrees further: more than lambda
    const auto runs = rgnav::splitAtBreakpoints(points, inc, {});
    const std::vector<std::pair<std::size_t, std::size_t>> expected{{0, 5}, {5, 11}, {11, 12}};
    CPPUNIT_ASSERT(runs == expected);
    CPPUNIT_ASSERT(rgnav::splitAtBreakpoints({}, inc, {}).empty());
  }

  void noisyScanGivesSameWalls() {
    const auto walls = boxWalls({0, 0}, 0.4, 8.0, 5.0);
    const Pose2D pose{1.0, 0.5, -0.3};
    const auto clean = LineExtractor().extract(syntheticScan(walls, pose, fullCircle(walls[0].a, pose)), pose, 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), clean.size());
    for (unsigned seed = 1; seed <= 5; ++seed) {
      auto spec = fullCircle(walls[0].a, pose, 0.01);
      spec.seed = seed;
      const auto noisy = LineExtractor().extract(syntheticScan(walls, pose, spec), pose, 1);
      CPPUNIT_ASSERT_EQUAL(clean.size(), noisy.size());
      for (std::size_t i = 0; i < noisy.size(); ++i) {
        const LineSegment& s = noisy[i];
        const Wall& w = *std::min_element(walls.begin(), walls.end(),
                                          [&](const Wall& a, const Wall& b) { return offLine(s, a) < offLine(s, b); });
        CPPUNIT_ASSERT(offLine(s, w) < 0.02);
        CPPUNIT_ASSERT(s.fit().rmsResidualM < 0.015);
        // Same pieces as without noise; an end point may move by one beam spacing, up to 11 cm
        // at the corner seen at the most grazing angle, when the corner point changes sides.
        CPPUNIT_ASSERT(endpointError(s, Wall{clean[i].start, clean[i].end}) < 0.12);
      }
    }
  }

  void invalidAndMissingReturnsAreSkipped() {
    const std::vector<Wall> walls{{{3, -4}, {3, 4}}};
    auto scan = syntheticScan(walls, {0, 0, 0});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), LineExtractor().extract(scan, {0, 0, 0}, 1).size());
    // A few invalid beams inside the wall and beyond-range values do not break it up.
    scan.ranges[170] = rgnav::LaserScan::kInvalid;
    scan.ranges[171] = -1.0f;
    scan.ranges[190] = rgnav::LaserScan::kNoReturn;
    scan.ranges[0] = float(scan.maxRange) + 5.0f;
    const auto segments = LineExtractor().extract(scan, {0, 0, 0}, 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), segments.size());
    CPPUNIT_ASSERT(offLine(segments[0], walls[0]) < 1e-6);
    // Nothing valid: no segments.
    std::fill(scan.ranges.begin(), scan.ranges.end(), rgnav::LaserScan::kInvalid);
    CPPUNIT_ASSERT(LineExtractor().extract(scan, {0, 0, 0}, 1).empty());
  }

  void minimumPointsAndLengthDropSmallPieces() {
    // A 10 cm board 2 m away is hit by about 6 beams: too short for the default 15 cm.
    const std::vector<Wall> board{{{2, -0.05}, {2, 0.05}}};
    const auto scan = syntheticScan(board, {0, 0, 0});
    CPPUNIT_ASSERT(LineExtractor().extract(scan, {0, 0, 0}, 1).empty());
    rgnav::LineExtractorParams loose;
    loose.minLengthM = 0.05;
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), LineExtractor(loose).extract(scan, {0, 0, 0}, 1).size());
    loose.minPoints = 10;
    CPPUNIT_ASSERT(LineExtractor(loose).extract(scan, {0, 0, 0}, 1).empty());
  }

  void segmentsAreInTheFrameOfTheSensorPose() {
    const std::vector<Wall> walls{{{3, -4}, {3, 4}}};
    const auto scan = syntheticScan(walls, {0, 0, 0});
    const auto moved = LineExtractor().extract(scan, {10, 5, M_PI / 2}, 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), moved.size());
    // x = 3 in the sensor frame is y = 8 in the frame of the pose (10, 5, 90 degrees).
    CPPUNIT_ASSERT_DOUBLES_EQUAL(8.0, moved[0].start.y(), 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(8.0, moved[0].end.y(), 1e-6);
  }

  void badParametersAreTypedErrors() {
    rgnav::LineExtractorParams p;
    p.splitDistanceM = 0.0;
    CPPUNIT_ASSERT_THROW(LineExtractor{p}, rgnav::InvalidArgumentError);
    p = {};
    p.minPoints = 1;
    CPPUNIT_ASSERT_THROW(LineExtractor{p}, rgnav::InvalidArgumentError);
    rgnav::BreakpointParams b;
    b.lambdaRad = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::splitAtBreakpoints({}, 0.01, b), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LineExtractorTest);
