// Tests the merge-candidate grid: every line that LineMerger would merge with a segment is among
// its near lines (random pairs around the 3.1.1 thresholds, thesis and loose parameters, short
// and long segments against small and large cells), far lines are not, each line is returned
// once in sweep order (orientation, then ID), removal, and typed errors.
#include "core/lines/LineGrid.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <limits>
#include <random>

#include "core/common/Errors.h"
#include "core/lines/testing/CentredSegment.h"

using Eigen::Vector2d;
using rgnav::LineGrid;
using rgnav::LineMerger;
using rgnav::LineMergerParams;
using rgnav::LineSegment;
using rgnav::segmentFromEndpoints;
using rgnav::testing::centredSegment;

namespace {

constexpr double kDeg = M_PI / 180.0;

bool contains(const std::vector<LineGrid::Handle>& handles, LineGrid::Handle h) {
  return std::find(handles.begin(), handles.end(), h) != handles.end();
}

// Random pairs (a, b) near the merge limits of `params`; for each pair that merges, b must be
// near a and a near b in a grid of `cellM` that also holds random clutter. Returns the merges.
std::size_t checkMergeablePairsAreNear(const LineMergerParams& params, double cellM, unsigned seed) {
  const LineMerger merger(params);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(random); };
  LineGrid grid(cellM, rgnav::mergeReach(params));
  rgnav::SegmentId id = 1;
  for (int k = 0; k < 200; ++k)
    grid.insert(centredSegment(id++, {uniform(-20, 20), uniform(-20, 20)}, uniform(0, M_PI), uniform(0.1, 6.0)));
  std::size_t merges = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double angle = uniform(0, M_PI), length = uniform(0.15, trial % 2 == 0 ? 1.0 : 12.0);
    const Vector2d center(uniform(-20, 20), uniform(-20, 20));
    const Vector2d along(std::cos(angle), std::sin(angle)), across(-along.y(), along.x());
    const LineSegment a = centredSegment(id++, center, angle, length);
    // b: beside or beyond a, tilted and offset up to a little past the limits.
    const double lengthB = uniform(0.15, trial % 3 == 0 ? 0.5 : 8.0);
    const double shift = 0.5 * (length + lengthB) + uniform(-length, 1.2 * params.maxGapM);
    const double tilt = std::min(params.maxAngleRad, 4.0 * params.maxLineDistanceM / (length + lengthB));
    const LineSegment b = centredSegment(
        id++,
        center + (trial % 4 < 2 ? 1.0 : -1.0) * shift * along + uniform(-2.0, 2.0) * params.maxLineDistanceM * across,
        angle + uniform(-1.2, 1.2) * tilt, lengthB);
    if (!merger.tryMerge(a, b)) continue;
    ++merges;
    const LineGrid::Handle ha = grid.insert(a);
    CPPUNIT_ASSERT(contains(grid.near(b), ha));
    grid.remove(ha);
    const LineGrid::Handle hb = grid.insert(b);
    CPPUNIT_ASSERT(contains(grid.near(a), hb));
    grid.remove(hb);
  }
  return merges;
}

}  // namespace

class LineGridTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LineGridTest);
  CPPUNIT_TEST(mergeReachFromThesisParameters);
  CPPUNIT_TEST(everyMergeablePairIsNear);
  CPPUNIT_TEST(farLinesAreNotNear);
  CPPUNIT_TEST(eachLineOnceInSweepOrder);
  CPPUNIT_TEST(removedLinesAreGoneAndHandlesReused);
  CPPUNIT_TEST(badInputIsTypedError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void mergeReachFromThesisParameters() {
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.150 + 4 * 0.020, rgnav::mergeReach(LineMergerParams{}), 1e-12);
  }

  void everyMergeablePairIsNear() {
    const LineMergerParams thesis, loose{10 * kDeg, 0.2, 0.5};
    for (const double cellM : {0.1, 1.0, 5.0}) {
      CPPUNIT_ASSERT(checkMergeablePairsAreNear(thesis, cellM, 1) > 300);
      CPPUNIT_ASSERT(checkMergeablePairsAreNear(loose, cellM, 2) > 300);
    }
  }

  void farLinesAreNotNear() {
    LineGrid grid(1.0, rgnav::mergeReach({}));
    const auto wall = grid.insert(centredSegment(1, {0, 0}, 0.0, 10.0));
    grid.insert(centredSegment(2, {0, 5}, 0.0, 10.0));
    grid.insert(centredSegment(3, {20, 0}, 0.0, 4.0));
    const auto found = grid.near(centredSegment(4, {3, 0.01}, 0.0, 1.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT_EQUAL(wall, found.front());
    CPPUNIT_ASSERT(grid.near(centredSegment(5, {0, -3}, 0.0, 2.0)).empty());
  }

  void eachLineOnceInSweepOrder() {
    LineGrid grid(0.5, rgnav::mergeReach({}));
    // Long lines through many shared cells, inserted in descending ID order; IDs 1-4 and 5-9
    // at two orientations (exactly, in binary), the second one lower.
    for (rgnav::SegmentId id = 9; id >= 1; --id) {
      const double y = double(id) / 64, rise = id <= 4 ? 1.0 / 32 : 1.0 / 64;
      grid.insert(segmentFromEndpoints(id, {-10, y}, {10, y + rise}));
    }
    const auto found = grid.near(centredSegment(10, {0, 0.1}, 0.0, 15.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(9), found.size());
    const std::vector<rgnav::SegmentId> expected{5, 6, 7, 8, 9, 1, 2, 3, 4};
    for (std::size_t i = 0; i < found.size(); ++i) {
      CPPUNIT_ASSERT_EQUAL(expected[i], grid.line(found[i]).id);
      CPPUNIT_ASSERT_EQUAL(grid.line(found[i]).orientationRad(), grid.orientationRad(found[i]));
    }
  }

  void removedLinesAreGoneAndHandlesReused() {
    LineGrid grid(1.0, rgnav::mergeReach({}));
    const auto a = grid.insert(centredSegment(1, {0, 0}, 0.0, 3.0));
    const auto b = grid.insert(centredSegment(2, {0, 0.05}, 0.0, 3.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), grid.size());
    CPPUNIT_ASSERT_EQUAL(rgnav::SegmentId(1), grid.remove(a).id);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), grid.size());
    const auto found = grid.near(centredSegment(3, {0, 0}, 0.0, 1.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT_EQUAL(b, found.front());
    const auto c = grid.insert(centredSegment(4, {30, 30}, 1.0, 2.0));
    CPPUNIT_ASSERT_EQUAL(a, c);
    CPPUNIT_ASSERT_EQUAL(rgnav::SegmentId(4), grid.line(c).id);
    CPPUNIT_ASSERT(grid.near(centredSegment(5, {0, 0}, 0.0, 1.0)) == found);
  }

  void badInputIsTypedError() {
    CPPUNIT_ASSERT_THROW(LineGrid(0.0, 0.2), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(LineGrid(1.0, -0.1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(LineGrid(std::numeric_limits<double>::infinity(), 0.2), rgnav::InvalidArgumentError);
    LineGrid grid(1.0, 0.2);
    LineSegment bad = centredSegment(1, {0, 0}, 0.0, 1.0);
    bad.end.x() = std::numeric_limits<double>::quiet_NaN();
    CPPUNIT_ASSERT_THROW(grid.insert(bad), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), grid.size());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LineGridTest);
