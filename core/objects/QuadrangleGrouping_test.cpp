// Tests quadrangle grouping on line maps: a single box, agreement of the two-stage search with
// the naive C(N,4) search on random line maps, and removal of contained and overlapping
// hypotheses.
#include "core/objects/QuadrangleGrouping.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/objects/testing/SyntheticLines.h"

using Eigen::Vector2d;
using rgnav::GroupingParams;
using rgnav::LineSegment;
using rgnav::QuadrangleGrouping;

namespace {

// The four sides of an axis-aligned w x h box at (x, y), ending 5 cm short of the corners,
// appended to `lines`: bottom, right, top, left.
void addBox(std::vector<LineSegment>& lines, double x, double y, double w, double h) {
  const double g = 0.05;
  const auto add = [&](double x0, double y0, double x1, double y1) {
    lines.push_back(rgnav::segmentFromEndpoints(lines.size() + 1, {x + x0, y + y0}, {x + x1, y + y1}));
  };
  add(g, 0, w - g, 0);
  add(w, g, w, h - g);
  add(w - g, h, g, h);
  add(0, h - g, 0, g);
}

bool sameSides(const std::vector<rgnav::Quadrangle>& a, const std::vector<rgnav::Quadrangle>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].sides != b[i].sides) return false;
  return true;
}

}  // namespace

class QuadrangleGroupingTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(QuadrangleGroupingTest);
  CPPUNIT_TEST(singleBoxGivesOneQuadrangle);
  CPPUNIT_TEST(canonicalCycle);
  CPPUNIT_TEST(naiveAndTwoStageAgreeOnRandomMaps);
  CPPUNIT_TEST(containedHypothesesAreRemoved);
  CPPUNIT_TEST(overlapRatioDecidesRemoval);
  CPPUNIT_TEST(badParametersAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void singleBoxGivesOneQuadrangle() {
    std::vector<LineSegment> lines;
    addBox(lines, 1, 2, 1.2, 0.8);
    const auto found = QuadrangleGrouping().twoStage(lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT((found[0].sides == rgnav::SideCycle{0, 1, 2, 3}));
    // Corner m joins sides m and m+1: bottom/right at (2.2, 2), right/top, top/left, left/bottom.
    const std::array<Vector2d, 4> expected{Vector2d(2.2, 2), Vector2d(2.2, 2.8), Vector2d(1, 2.8), Vector2d(1, 2)};
    for (std::size_t m = 0; m < 4; ++m) CPPUNIT_ASSERT((found[0].corners[m] - expected[m]).norm() < 1e-9);
    CPPUNIT_ASSERT(sameSides(found, QuadrangleGrouping().naive(lines)));
  }

  void canonicalCycle() {
    CPPUNIT_ASSERT((rgnav::canonicalCycle({7, 3, 9, 5}) == rgnav::SideCycle{3, 7, 5, 9}));
    CPPUNIT_ASSERT((rgnav::canonicalCycle({9, 5, 3, 7}) == rgnav::SideCycle{3, 5, 9, 7}));
    CPPUNIT_ASSERT((rgnav::canonicalCycle({3, 5, 9, 7}) == rgnav::SideCycle{3, 5, 9, 7}));
    CPPUNIT_ASSERT((rgnav::canonicalCycle({5, 3, 7, 9}) == rgnav::SideCycle{3, 5, 9, 7}));
  }

  void naiveAndTwoStageAgreeOnRandomMaps() {
    std::size_t total = 0;
    for (const bool restrictive : {true, false})
      for (unsigned seed = 1; seed <= 4; ++seed) {
        GroupingParams p;
        p.restrictive = restrictive;
        const auto lines = rgnav::testing::syntheticLineMap(50, seed);
        const QuadrangleGrouping grouping(p);
        const auto fast = grouping.twoStage(lines);
        CPPUNIT_ASSERT(sameSides(fast, grouping.naive(lines)));
        total += fast.size();
      }
    CPPUNIT_ASSERT(total >= 12);  // the boxes are found, so the comparison is not vacuous
    // Wider parameters make many more pairs; the searches still agree.
    GroupingParams wide;
    wide.restrictive = false;
    wide.minAngleRad = 20 * M_PI / 180;
    wide.maxAngleRad = 160 * M_PI / 180;
    wide.maxNeighbourDistanceM = 0.8;
    const auto lines = rgnav::testing::syntheticLineMap(40, 1);
    const auto fast = QuadrangleGrouping(wide).twoStage(lines);
    CPPUNIT_ASSERT(fast.size() > 20);
    CPPUNIT_ASSERT(sameSides(fast, QuadrangleGrouping(wide).naive(lines)));
  }

  void containedHypothesesAreRemoved() {
    // A 3 x 2 box with a 1 x 0.6 box inside and a 1 x 1 box elsewhere.
    std::vector<LineSegment> lines;
    addBox(lines, 0, 0, 3, 2);
    addBox(lines, 1, 0.7, 1, 0.6);
    addBox(lines, 6, 0, 1, 1);
    const QuadrangleGrouping grouping;
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), grouping.twoStage(lines).size());
    const auto kept = grouping.group(lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), kept.size());
    CPPUNIT_ASSERT((kept[0].sides == rgnav::SideCycle{0, 1, 2, 3}));  // largest first
    CPPUNIT_ASSERT((kept[1].sides == rgnav::SideCycle{8, 9, 10, 11}));
  }

  void overlapRatioDecidesRemoval() {
    // Two 2 x 1 boxes; the second shifted by 0.8 m (60 % of it covered) or 1.4 m (30 %).
    for (const auto& [shift, removed] : {std::pair(0.8, true), std::pair(1.4, false)}) {
      std::vector<LineSegment> lines;
      addBox(lines, 0, 0, 2, 1);
      addBox(lines, shift, 0, 2, 1);
      const std::vector<rgnav::Quadrangle> both{rgnav::makeQuadrangle(lines, {0, 1, 2, 3}),
                                                rgnav::makeQuadrangle(lines, {4, 5, 6, 7})};
      CPPUNIT_ASSERT_EQUAL(removed ? std::size_t(1) : std::size_t(2),
                           rgnav::removeContainedAndOverlapping(both, 0.5).size());
    }
  }

  void badParametersAreTypedErrors() {
    GroupingParams p;
    p.minOppositeDistanceM = -1;
    CPPUNIT_ASSERT_THROW(QuadrangleGrouping{p}, rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::removeContainedAndOverlapping({}, 1.0), rgnav::InvalidArgumentError);
    std::vector<LineSegment> parallel{
        rgnav::segmentFromEndpoints(1, {0, 0}, {1, 0}), rgnav::segmentFromEndpoints(2, {0, 1}, {1, 1}),
        rgnav::segmentFromEndpoints(3, {0, 2}, {1, 2}), rgnav::segmentFromEndpoints(4, {0, 3}, {1, 3})};
    CPPUNIT_ASSERT_THROW(rgnav::makeQuadrangle(parallel, {0, 1, 2, 3}), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(QuadrangleGroupingTest);
