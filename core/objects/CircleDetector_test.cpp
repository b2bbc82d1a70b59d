// Tests circle fitting and detection (thesis Table 2.1, round objects): exact and noisy arcs,
// the geometric refinement against the algebraic start, clustering, and the rejection of
// walls, corners, too small or too large circles and too short arcs.
#include "core/objects/CircleDetector.h"

#include <cppunit/extensions/HelperMacros.h>

#include <random>

#include "core/common/Errors.h"
#include "core/objects/CircleFit.h"
#include "core/objects/PointClustering.h"

using Eigen::Vector2d;
using rgnav::CircleDetector;

namespace {

constexpr double kDeg = M_PI / 180.0;

// `n` points on an arc of the circle (center, radius) from `fromDeg` to `toDeg`, with Gaussian
// radial noise.
std::vector<Vector2d> arc(const Vector2d& center, double radius, double fromDeg, double toDeg, int n, double noise,
                          unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> error(0.0, noise);
  std::vector<Vector2d> points;
  for (int i = 0; i < n; ++i) {
    const double a = (fromDeg + (toDeg - fromDeg) * i / (n - 1)) * kDeg;
    const double r = radius + (noise > 0 ? error(random) : 0.0);
    points.push_back(center + r * Vector2d(std::cos(a), std::sin(a)));
  }
  return points;
}

std::vector<Vector2d> straight(const Vector2d& a, const Vector2d& b, int n) {
  std::vector<Vector2d> points;
  for (int i = 0; i < n; ++i) points.push_back(a + (b - a) * double(i) / (n - 1));
  return points;
}

void append(std::vector<Vector2d>& to, const std::vector<Vector2d>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

class CircleDetectorTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CircleDetectorTest);
  CPPUNIT_TEST(exactPointsGiveExactCircle);
  CPPUNIT_TEST(noisyArcsAreFittedClosely);
  CPPUNIT_TEST(geometricRefinementBeatsAlgebraicStartOnShortArcs);
  CPPUNIT_TEST(collinearPointsHaveNoCircle);
  CPPUNIT_TEST(clusteringSeparatesByGap);
  CPPUNIT_TEST(detectsBinAmongWallsAndCorners);
  CPPUNIT_TEST(radiusLimitsAndArcLength);
  CPPUNIT_TEST(badParametersAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void exactPointsGiveExactCircle() {
    const auto points = arc({1.5, -2.0}, 0.45, 10, 200, 30, 0.0, 1);
    for (const auto& fit : {rgnav::fitCircleAlgebraic(points), rgnav::fitCircle(points)}) {
      CPPUNIT_ASSERT(fit);
      CPPUNIT_ASSERT((fit->center - Vector2d(1.5, -2.0)).norm() < 1e-9);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(0.45, fit->radiusM, 1e-9);
      CPPUNIT_ASSERT(fit->rmsResidualM < 1e-9);
    }
  }

  void noisyArcsAreFittedClosely() {
    // A round table (r = 0.4 m) seen over 120 degrees, 5 mm noise.
    for (unsigned seed = 1; seed <= 10; ++seed) {
      const auto fit = rgnav::fitCircle(arc({0, 0}, 0.4, -60, 60, 40, 0.005, seed));
      CPPUNIT_ASSERT(fit);
      CPPUNIT_ASSERT(fit->center.norm() < 0.02);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(0.4, fit->radiusM, 0.02);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(0.005, fit->rmsResidualM, 0.002);
    }
  }

  void geometricRefinementBeatsAlgebraicStartOnShortArcs() {
    // On a 90 degree arc with 1 cm noise the algebraic fit shrinks the radius; the geometric
    // refinement has a smaller mean error and a smaller rms residual.
    double algebraic = 0, geometric = 0;
    for (unsigned seed = 1; seed <= 30; ++seed) {
      const auto points = arc({0, 0}, 0.5, 0, 90, 30, 0.01, seed);
      const auto a = rgnav::fitCircleAlgebraic(points), g = rgnav::fitCircle(points);
      CPPUNIT_ASSERT(a && g);
      algebraic += std::fabs(a->radiusM - 0.5);
      geometric += std::fabs(g->radiusM - 0.5);
      CPPUNIT_ASSERT(g->rmsResidualM <= a->rmsResidualM + 1e-12);
    }
    CPPUNIT_ASSERT(geometric < algebraic);
  }

  void collinearPointsHaveNoCircle() {
    const auto points = straight({0, 0}, {2, 1}, 20);
    CPPUNIT_ASSERT(!rgnav::fitCircleAlgebraic(points));
    CPPUNIT_ASSERT(!rgnav::fitCircle(points));
    CPPUNIT_ASSERT(!rgnav::fitCircle(std::vector<Vector2d>{{0, 0}, {1, 1}}));
  }

  void clusteringSeparatesByGap() {
    // A chain of points 8 cm apart stays one cluster; a 15 cm gap separates.
    std::vector<Vector2d> points = straight({0, 0}, {0.8, 0}, 11);
    append(points, straight({0.95, 0}, {1.5, 0}, 8));
    points.push_back({-3, -3});
    const auto clusters = rgnav::clusterPoints(points, 0.1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), clusters.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(11), clusters[0].size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(8), clusters[1].size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(19), clusters[2].front());
    CPPUNIT_ASSERT_THROW(rgnav::clusterPoints(points, 0.0), rgnav::InvalidArgumentError);
  }

  void detectsBinAmongWallsAndCorners() {
    // A bin (r = 0.2 m) seen over 180 degrees, a straight wall, a wall corner and a gently
    // curved wall (r = 3 m), all with 5 mm noise.
    std::vector<Vector2d> points = arc({2, 1}, 0.2, 180, 360, 25, 0.005, 3);
    append(points, straight({-2, -2}, {2, -2}, 120));
    append(points, straight({-4, 2}, {-4, 4}, 60));
    append(points, straight({-4, 4}, {-2, 4}, 60));
    append(points, arc({10, 0}, 3.0, 150, 210, 80, 0.005, 4));
    const auto circles = CircleDetector().detect(points);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), circles.size());
    CPPUNIT_ASSERT((circles[0].center - Vector2d(2, 1)).norm() < 0.02);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2, circles[0].radiusM, 0.01);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI, circles[0].arcRad, 5 * kDeg);
    CPPUNIT_ASSERT_EQUAL(std::size_t(25), circles[0].pointCount);
    CPPUNIT_ASSERT(circles[0].confidence > 0.5 && circles[0].confidence <= 1.0);
  }

  void radiusLimitsAndArcLength() {
    const CircleDetector detector;
    CPPUNIT_ASSERT(detector.detect(arc({0, 0}, 0.05, 0, 300, 30, 0.0, 1)).empty());  // too small
    CPPUNIT_ASSERT(detector.detect(arc({0, 0}, 1.2, 0, 120, 80, 0.0, 1)).empty());   // too large
    CPPUNIT_ASSERT(detector.detect(arc({0, 0}, 0.4, 0, 60, 20, 0.0, 1)).empty());    // arc too short
    CPPUNIT_ASSERT(detector.detect(arc({0, 0}, 0.4, 0, 40, 6, 0.0, 1)).empty());     // too few points
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), detector.detect(arc({0, 0}, 0.4, 0, 120, 20, 0.0, 1)).size());
    // A full circle scores higher than half a circle only up to the cap of 1.
    const auto full = detector.detect(arc({0, 0}, 0.4, 0, 350, 60, 0.0, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), full.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, full[0].confidence, 1e-6);
  }

  void badParametersAreTypedErrors() {
    rgnav::CircleDetectorParams p;
    p.maxRadiusM = p.minRadiusM;
    CPPUNIT_ASSERT_THROW(CircleDetector{p}, rgnav::InvalidArgumentError);
    p = {};
    p.minPoints = 2;
    CPPUNIT_ASSERT_THROW(CircleDetector{p}, rgnav::InvalidArgumentError);
    p = {};
    p.maxResidualM = 0.0;
    CPPUNIT_ASSERT_THROW(CircleDetector{p}, rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CircleDetectorTest);
