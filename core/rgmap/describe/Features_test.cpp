// Tests the single region features on hand-made input: main line directions (length-weighted
// orientation histogram modulo pi), line map accuracy (definition in LineMapAccuracy.h), bounding
// rectangles of a hull, the reservoir sample of measurements, and the global raster of a 1-bit map.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"
#include "core/lines/testing/CentredSegment.h"
#include "core/rgmap/describe/BoundingRectangles.h"
#include "core/rgmap/describe/FreespaceRaster.h"
#include "core/rgmap/describe/LineMapAccuracy.h"
#include "core/rgmap/describe/MainDirections.h"
#include "core/rgmap/describe/MeasurementSample.h"

using Eigen::Vector2d;
using rgnav::LineSegment;
using rgnav::segmentFromEndpoints;

namespace {

constexpr double kDeg = M_PI / 180.0;

LineSegment segment(const Vector2d& center, double angle, double length) {
  return rgnav::testing::centredSegment(1, center, angle, length);
}

double angleError(double a, double b) { return rgnav::orientationDifference(a, b); }

}  // namespace

class FeaturesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FeaturesTest);
  CPPUNIT_TEST(twoMainDirectionsOfARoom);
  CPPUNIT_TEST(oneMainDirectionAcrossTheWrap);
  CPPUNIT_TEST(weakSecondDirectionIsDropped);
  CPPUNIT_TEST(accuracyFollowsItsDefinition);
  CPPUNIT_TEST(rectanglesAroundAHull);
  CPPUNIT_TEST(sampleIsBoundedAndMerges);
  CPPUNIT_TEST(rasterPlacesTheMapGlobally);
  CPPUNIT_TEST(badParametersAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void twoMainDirectionsOfARoom() {
    // Walls at 20 and 110 degrees (with 1 degree jitter), plus short clutter at 60 degrees.
    std::vector<LineSegment> lines;
    for (int k = 0; k < 6; ++k) {
      lines.push_back(segment({k, 0}, (20 + (k % 3 - 1)) * kDeg, 3.0));
      lines.push_back(segment({0, k}, (110 + (k % 3 - 1)) * kDeg, 2.0));
      lines.push_back(segment({k, k}, 60 * kDeg, 0.3));
    }
    const auto d = rgnav::mainDirections(lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), d.size());
    CPPUNIT_ASSERT(angleError(d[0].angleRad, 20 * kDeg) < 0.1 * kDeg);
    CPPUNIT_ASSERT(angleError(d[1].angleRad, 110 * kDeg) < 0.1 * kDeg);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(18.0, d[0].lengthM, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(18.0 / 31.8, d[0].share, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(12.0 / 31.8, d[1].share, 1e-9);
  }

  void oneMainDirectionAcrossTheWrap() {
    // 179 and 1 degrees are the same direction; the mean lies at 0 (not 90).
    const std::vector<LineSegment> lines{segment({0, 0}, 179 * kDeg, 2.0), segment({0, 1}, 1 * kDeg, 2.0)};
    const auto d = rgnav::mainDirections(lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), d.size());
    CPPUNIT_ASSERT(angleError(d[0].angleRad, 0.0) < 1e-9);
    CPPUNIT_ASSERT(d[0].angleRad >= 0.0 && d[0].angleRad < M_PI);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, d[0].share, 1e-12);
    CPPUNIT_ASSERT(rgnav::mainDirections({}).empty());
  }

  void weakSecondDirectionIsDropped() {
    // A hallway: long walls along x and two short door jambs across (1 m of 21 m).
    const std::vector<LineSegment> lines{segment({0, 0}, 0.0, 10.0), segment({0, 2}, 0.0, 10.0),
                                         segment({2, 1}, M_PI / 2, 0.5), segment({5, 1}, M_PI / 2, 0.5)};
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), rgnav::mainDirections(lines).size());
    rgnav::MainDirectionParams params;
    params.minSecondWeight = 0.04;
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), rgnav::mainDirections(lines, params).size());
  }

  void accuracyFollowsItsDefinition() {
    // One segment from (0, 0) to (4, 0). Points at distances 0.01, 0.03, 0.2 (beside the end) and
    // 3 (clamped to 0.5).
    const std::vector<LineSegment> lines{segmentFromEndpoints(1, {0, 0}, {4, 0})};
    const std::vector<Vector2d> points{{1, 0.01}, {2, -0.03}, {4.2, 0}, {2, 3}};
    const auto a = rgnav::lineMapAccuracy(points, lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), a.pointCount);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, a.inlierShare, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL((0.01 + 0.03 + 0.2 + 0.5) / 4, a.meanDistanceM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::sqrt((0.0001 + 0.0009 + 0.04 + 0.25) / 4), a.rmsDistanceM, 1e-12);
    // Without lines every point is at the clamp; without points nothing is defined.
    const auto none = rgnav::lineMapAccuracy(points, {});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, none.inlierShare, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, none.rmsDistanceM, 1e-12);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), rgnav::lineMapAccuracy({}, lines).pointCount);
  }

  void rectanglesAroundAHull() {
    // A 4 x 1.5 m rectangle turned by 30 degrees.
    const rgnav::OrientedRectangle truth{{1.0, 2.0}, 30 * kDeg, 4.0, 1.5};
    const auto c = truth.corners();
    const auto hull = rgnav::convexHull({c.begin(), c.end()});
    const auto r = rgnav::minimumAreaRectangle(hull);
    CPPUNIT_ASSERT(r);
    CPPUNIT_ASSERT((r->center - truth.center).norm() < 1e-9);
    CPPUNIT_ASSERT(angleError(r->angleRad, truth.angleRad) < 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, r->lengthM, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.5, r->widthM, 1e-9);
    const auto box = rgnav::axisAlignedBox(hull);
    const double hx = 2.0 * std::cos(30 * kDeg) + 0.75 * std::sin(30 * kDeg);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 - hx, box.min().x(), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 + hx, box.max().x(), 1e-9);
    // Degenerate hulls.
    CPPUNIT_ASSERT(!rgnav::minimumAreaRectangle({}));
    CPPUNIT_ASSERT(rgnav::axisAlignedBox({}).isEmpty());
    const auto point = rgnav::minimumAreaRectangle({Vector2d(3, 4)});
    CPPUNIT_ASSERT(point && point->lengthM == 0.0 && point->center == Vector2d(3, 4));
    const auto stick = rgnav::minimumAreaRectangle({Vector2d(0, 0), Vector2d(0, 2)});
    CPPUNIT_ASSERT(stick && std::fabs(stick->lengthM - 2.0) < 1e-12 && stick->widthM == 0.0);
    CPPUNIT_ASSERT(angleError(stick->angleRad, M_PI / 2) < 1e-12);
  }

  void sampleIsBoundedAndMerges() {
    // 10000 points with x = 0..9999: the sample keeps 500, spread over the whole stream.
    rgnav::MeasurementSample sample(500);
    for (int k = 0; k < 10000; ++k) sample.add({double(k), 0.0});
    CPPUNIT_ASSERT_EQUAL(std::size_t(500), sample.points().size());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(10000), sample.seen());
    double mean = 0.0;
    for (const auto& p : sample.points()) mean += p.x() / 500.0;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5000.0, mean, 400.0);  // about 3 standard errors
    // Merged with a sample of 30000 points at y = 1 (shifted by the merge pose to y = 6): three
    // quarters of the merged sample come from it.
    rgnav::MeasurementSample other(500);
    for (int k = 0; k < 30000; ++k) other.add({double(k), 1.0});
    sample.mergeFrom(other, {0.0, 5.0, 0.0});
    CPPUNIT_ASSERT_EQUAL(std::size_t(500), sample.points().size());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(40000), sample.seen());
    const auto fromOther = std::count_if(sample.points().begin(), sample.points().end(),
                                         [](const Vector2d& p) { return p.y() == 6.0; });
    CPPUNIT_ASSERT_EQUAL(std::ptrdiff_t(375), fromOther);
    // Small samples are merged whole.
    rgnav::MeasurementSample a(100), b(100);
    a.add({0, 0});
    b.add({1, 1});
    b.add({2, 2});
    a.mergeFrom(b, {});
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), a.points().size());
  }

  void rasterPlacesTheMapGlobally() {
    // A 4 x 2 cell map of 0.5 m cells at origin (1, 1), free except cell (3, 1).
    auto map = rgnav::FreespaceBitmap::allOccupied(0.5, {1.0, 1.0}, 4, 2);
    for (int row = 0; row < 2; ++row)
      for (int col = 0; col < 4; ++col)
        if (!(col == 3 && row == 1)) map.setFree(col, row);
    CPPUNIT_ASSERT_EQUAL(std::size_t(7), map.freeCount());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), map.bytes.size());
    CPPUNIT_ASSERT_EQUAL(std::uint8_t(0x7f), map.bytes[0]);
    // The region frame lies at (10, 0) turned by 90 degrees: region x is global y.
    const rgnav::RasterFrame frame{0.25, {8.0, 0.0}, 16, 16};
    const auto raster = rgnav::rasteriseFreespace(map, {10.0, 0.0, M_PI / 2}, frame);
    CPPUNIT_ASSERT_EQUAL(std::size_t(256), raster.size());
    std::size_t free = 0;
    for (int row = 0; row < frame.height; ++row)
      for (int col = 0; col < frame.width; ++col) {
        const Vector2d global = frame.originM + frame.resolutionM * Vector2d(col + 0.5, row + 0.5);
        const Vector2d local = rgnav::transformPoint(rgnav::inverse({10.0, 0.0, M_PI / 2}), global);
        const std::uint8_t value = raster[std::size_t(row * frame.width + col)];
        CPPUNIT_ASSERT_EQUAL(std::uint8_t(map.isFreeAt(local)), value);
        free += value;
      }
    CPPUNIT_ASSERT_EQUAL(std::size_t(7 * 4), free);  // each 0.5 m cell covers 4 raster cells
    CPPUNIT_ASSERT_THROW(rgnav::rasteriseFreespace(map, {}, {0.0, {0, 0}, 1, 1}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::rasteriseFreespace(map, {std::nan(""), 0, 0}, frame), rgnav::InvalidArgumentError);
  }

  void badParametersAreTypedErrors() {
    rgnav::MainDirectionParams d;
    d.windowRad = 20 * kDeg;  // two windows would overlap within the 30 degree separation
    CPPUNIT_ASSERT_THROW(rgnav::mainDirections({}, d), rgnav::InvalidArgumentError);
    rgnav::AccuracyParams a;
    a.toleranceM = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::lineMapAccuracy({}, {}, a), rgnav::InvalidArgumentError);
    a = {0.6, 0.5};
    CPPUNIT_ASSERT_THROW(rgnav::lineMapAccuracy({}, {}, a), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::MeasurementSample(0), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(rgnav::FreespaceBitmap::allOccupied(0.0, {0, 0}, 1, 1), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(FeaturesTest);
