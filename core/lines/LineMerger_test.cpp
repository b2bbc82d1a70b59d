// Tests line merging (thesis 3.1.1): each rule in isolation at its threshold (angle window,
// D_L, gap), the wrap of orientations at pi, the new endpoints, the TLS fit of the union,
// merging to a fixpoint, and reversal through the provenance.
#include "core/lines/LineMerger.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <random>

#include "core/common/Errors.h"
#include "core/lines/testing/CentredSegment.h"

using Eigen::Vector2d;
using rgnav::LineMerger;
using rgnav::LineMergerParams;
using rgnav::LineSegment;
using rgnav::segmentFromEndpoints;
using rgnav::testing::centredSegment;

namespace {

constexpr double kDeg = M_PI / 180.0;

// Parameters with every rule but one switched off.
LineMergerParams only(double angleRad, double lineDistanceM, double gapM) { return {angleRad, lineDistanceM, gapM}; }

}  // namespace

class LineMergerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LineMergerTest);
  CPPUNIT_TEST(thesisDefaults);
  CPPUNIT_TEST(angleWindow);
  CPPUNIT_TEST(lineDistanceIsMeanOfFourEndpointDistances);
  CPPUNIT_TEST(lineDistanceLimit);
  CPPUNIT_TEST(gapLimit);
  CPPUNIT_TEST(orientationsWrapAtPi);
  CPPUNIT_TEST(newSegmentRunsBetweenFarthestEndpoints);
  CPPUNIT_TEST(mergedLineIsFitOfAllPoints);
  CPPUNIT_TEST(mergesUntilNoPairIsLeft);
  CPPUNIT_TEST(provenanceReversesTheMerge);
  CPPUNIT_TEST(badParametersAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void thesisDefaults() {
    const LineMergerParams p;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3 * kDeg, p.maxAngleRad, 1e-15);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.020, p.maxLineDistanceM, 1e-15);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.150, p.maxGapM, 1e-15);
  }

  void angleWindow() {
    const LineMerger merger(only(3 * kDeg, 1.0, 1.0));
    const auto a = centredSegment(1, {0, 0}, 0.0, 1.0);
    CPPUNIT_ASSERT(merger.tryMerge(a, centredSegment(2, {0, 0}, 2.9 * kDeg, 1.0)));
    CPPUNIT_ASSERT(!merger.tryMerge(a, centredSegment(2, {0, 0}, 3.1 * kDeg, 1.0)));
    CPPUNIT_ASSERT(merger.tryMerge(a, centredSegment(2, {0, 0}, -2.9 * kDeg, 1.0)));
    CPPUNIT_ASSERT(!merger.tryMerge(a, centredSegment(2, {0, 0}, -3.1 * kDeg, 1.0)));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), merger.merge({a, centredSegment(2, {0, 0}, 3.1 * kDeg, 1.0)}).size());
  }

  void lineDistanceIsMeanOfFourEndpointDistances() {
    // a on y = 0; b from (0, 0.01) to (1, 0.03): endpoints of b are 0.01 and 0.03 from a's line,
    // a's endpoints are 0.01 and about 0.03 from b's line.
    const auto a = segmentFromEndpoints(1, {0, 0}, {1, 0});
    const auto b = segmentFromEndpoints(2, {0, 0.01}, {1, 0.03});
    const double c = std::cos(std::atan(0.02));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.25 * (0.01 + 0.03 + 0.01 * c + 0.03 * c), rgnav::lineDistance(a, b), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(rgnav::lineDistance(a, b), rgnav::lineDistance(b, a), 1e-15);
  }

  void lineDistanceLimit() {
    const LineMerger merger(only(10 * kDeg, 0.020, 1.0));
    const auto a = centredSegment(1, {0, 0}, 0.3, 1.0);
    const Vector2d normal(-std::sin(0.3), std::cos(0.3));
    CPPUNIT_ASSERT(merger.tryMerge(a, centredSegment(2, 0.019 * normal, 0.3, 1.0)));
    CPPUNIT_ASSERT(!merger.tryMerge(a, centredSegment(2, 0.021 * normal, 0.3, 1.0)));
    // A small angle makes far endpoints leave the line: (0 + 0.03 + 0 + 0.03) / 4 = 0.015.
    const auto b = segmentFromEndpoints(2, {0, 0}, {0.5, 0.0});
    CPPUNIT_ASSERT(merger.tryMerge(b, segmentFromEndpoints(3, {0, 0}, {0.5, 0.03})));
    CPPUNIT_ASSERT(!merger.tryMerge(b, segmentFromEndpoints(3, {0, 0}, {0.5, 0.05})));
  }

  void gapLimit() {
    const LineMerger merger(only(10 * kDeg, 1.0, 0.150));
    const auto a = segmentFromEndpoints(1, {0, 0}, {1, 0});
    const auto near = segmentFromEndpoints(2, {1.149, 0}, {2, 0});
    const auto far = segmentFromEndpoints(2, {2, 0}, {1.151, 0});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.149, rgnav::gapAlongLine(a, near), 1e-12);
    CPPUNIT_ASSERT(merger.tryMerge(a, near));
    CPPUNIT_ASSERT(!merger.tryMerge(a, far));
    CPPUNIT_ASSERT(!merger.tryMerge(far, a));
    // Overlap (negative gap) and containment always merge.
    const auto inside = segmentFromEndpoints(3, {0.2, 0}, {0.4, 0});
    CPPUNIT_ASSERT(rgnav::gapAlongLine(a, inside) < 0.0);
    CPPUNIT_ASSERT(merger.tryMerge(inside, a));
  }

  void orientationsWrapAtPi() {
    // 179.5 and 0.5 degrees are 1 degree apart; the sweep must find them across the wrap even
    // with other orientations in between in the sorted array.
    const LineMerger merger;
    std::vector<LineSegment> segments{centredSegment(1, {0, 0}, 179.5 * kDeg, 1.0), centredSegment(2, {0, 5}, 45 * kDeg, 1.0),
                                      centredSegment(3, {0, 0}, 0.5 * kDeg, 1.0), centredSegment(4, {0, -5}, 90 * kDeg, 1.0)};
    const auto merged = merger.merge(segments);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), merged.size());
    CPPUNIT_ASSERT(std::any_of(merged.begin(), merged.end(), [](const LineSegment& s) {
      return s.provenance == std::vector<rgnav::SegmentId>{1, 3} && s.id == 1;
    }));
  }

  void newSegmentRunsBetweenFarthestEndpoints() {
    const LineMerger merger;
    const auto merged =
        merger.tryMerge(segmentFromEndpoints(5, {0, 0}, {1, 0}), segmentFromEndpoints(3, {1.1, 0}, {2.5, 0}));
    CPPUNIT_ASSERT(merged);
    CPPUNIT_ASSERT_EQUAL(rgnav::SegmentId(3), merged->id);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.5, merged->length(), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, std::min(merged->start.x(), merged->end.x()), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.5, std::max(merged->start.x(), merged->end.x()), 1e-9);
    CPPUNIT_ASSERT(merged->provenance == (std::vector<rgnav::SegmentId>{3, 5}));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), merged->support());
  }

  void mergedLineIsFitOfAllPoints() {
    // Two noisy pieces of the line y = 0.1 x + 1: the merged line equals the TLS fit of all
    // their points, and its endpoints lie on that line.
    std::mt19937 random(11);
    std::normal_distribution<double> noise(0.0, 0.003);
    std::vector<Vector2d> left, right, all;
    for (int i = 0; i < 30; ++i) {
      const double x = 0.05 * i;
      (x < 0.8 ? left : right).emplace_back(x, 0.1 * x + 1 + noise(random));
      all.push_back((x < 0.8 ? left : right).back());
    }
    const auto merged = LineMerger().tryMerge(rgnav::segmentFromPoints(1, left), rgnav::segmentFromPoints(2, right));
    CPPUNIT_ASSERT(merged);
    const auto expected = rgnav::segmentFromPoints(1, all).fit();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.normalAngleRad, merged->fit().normalAngleRad, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.distanceM, merged->fit().distanceM, 1e-12);
    for (const Vector2d& p : {merged->start, merged->end})
      CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.distanceM, expected.normal.dot(p), 1e-12);
  }

  void mergesUntilNoPairIsLeft() {
    // Ten pieces of one wall, shuffled, each 0.1 m after the previous: one line. Pieces of a
    // parallel wall 0.5 m away and of a perpendicular wall stay apart.
    std::vector<LineSegment> segments;
    for (int i = 0; i < 10; ++i) segments.push_back(segmentFromEndpoints(10 + i, {0.6 * i, 0.0}, {0.6 * i + 0.5, 0.0}));
    segments.push_back(segmentFromEndpoints(30, {0, 0.5}, {2, 0.5}));
    segments.push_back(segmentFromEndpoints(31, {-0.05, 0.1}, {-0.05, 2}));
    std::shuffle(segments.begin(), segments.end(), std::mt19937(5));
    const auto merged = LineMerger().merge(segments);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), merged.size());
    for (std::size_t i = 1; i < merged.size(); ++i)
      CPPUNIT_ASSERT(merged[i - 1].orientationRad() <= merged[i].orientationRad());
    const auto wall = std::find_if(merged.begin(), merged.end(), [](const auto& s) { return s.support() == 10; });
    CPPUNIT_ASSERT(wall != merged.end());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.9, wall->length(), 1e-9);
    CPPUNIT_ASSERT_EQUAL(rgnav::SegmentId(10), wall->id);
    // Merging again changes nothing.
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), LineMerger().merge(merged).size());
  }

  void provenanceReversesTheMerge() {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> u(-0.003, 0.003);
    std::vector<LineSegment> originals;
    for (rgnav::SegmentId id = 1; id <= 40; ++id) {
      const double y = double(id % 4) * 1.0;  // four walls, ten pieces each
      const double x = 0.3 * double(id / 4);
      originals.push_back(segmentFromEndpoints(id, {x, y + u(random)}, {x + 0.25, y + u(random)}));
    }
    const auto merged = LineMerger().merge(originals);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), merged.size());
    std::vector<rgnav::SegmentId> seen;
    for (const auto& line : merged) {
      const auto parts = rgnav::unmerge(line, originals);
      CPPUNIT_ASSERT_EQUAL(line.support(), parts.size());
      for (const auto& part : parts) {
        const auto& original = originals[part.id - 1];
        CPPUNIT_ASSERT(part.start == original.start && part.end == original.end);
        seen.push_back(part.id);
      }
    }
    std::sort(seen.begin(), seen.end());
    CPPUNIT_ASSERT_EQUAL(std::size_t(40), seen.size());
    CPPUNIT_ASSERT(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
    // Without the originals the merge cannot be reversed.
    CPPUNIT_ASSERT_THROW(rgnav::unmerge(merged[0], {}), rgnav::NotAvailableError);
  }

  void badParametersAreTypedErrors() {
    CPPUNIT_ASSERT_THROW(LineMerger(only(-0.1, 0.02, 0.15)), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(LineMerger(only(M_PI / 2, 0.02, 0.15)), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(LineMerger(only(0.05, -0.02, 0.15)), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(LineMerger(only(0.05, 0.02, std::nan(""))), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LineMergerTest);
