// Tests every rule of figure 3.2 (thesis 3.1) on constructed segments: stage 1 (angle window,
// neighbour distance), the five invalid configurations of stage 2, both valid configurations in
// the restrictive and non-restrictive case, and each of their conditions (neighbours, angles of
// the other corners, distance of opposite sides).
#include "core/objects/QuadrangleRules.h"

#include <cppunit/extensions/HelperMacros.h>

#include <array>

#include "core/common/Errors.h"

using Eigen::Vector2d;
using rgnav::classifyPairOfPairs;
using rgnav::GroupingParams;
using rgnav::LineSegment;
using rgnav::PairOfPairs;

namespace {

constexpr double kDeg = M_PI / 180.0;

LineSegment seg(double x0, double y0, double x1, double y1) {
  return rgnav::segmentFromEndpoints(1, {x0, y0}, {x1, y1});
}
Vector2d dir(double deg) { return {std::cos(deg * kDeg), std::sin(deg * kDeg)}; }

// Two segments meeting at the origin at `angleDeg`, each ending `gap` short of it.
std::array<LineSegment, 2> corner(double angleDeg, double gap) {
  return {seg(gap, 0, 1, 0), rgnav::segmentFromEndpoints(2, gap * dir(angleDeg), dir(angleDeg))};
}

// The sides of a w x h rectangle at the origin, each ending 5 cm short of the corners:
// bottom (i), right (j), top (k), left (l). Pairs: (i, j) and (k, l).
struct Box {
  LineSegment i, j, k, l;
};
Box box(double w, double h) {
  const double g = 0.05;
  return {seg(g, 0, w - g, 0), seg(w, g, w, h - g), seg(w - g, h, g, h), seg(0, h - g, 0, g)};
}

GroupingParams nonRestrictive() {
  GroupingParams p;
  p.restrictive = false;
  return p;
}

}  // namespace

class QuadrangleRulesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(QuadrangleRulesTest);
  CPPUNIT_TEST(thesisLaserDefaults);
  CPPUNIT_TEST(stage1AngleWindow);
  CPPUNIT_TEST(stage1UpperAngleBound);
  CPPUNIT_TEST(stage1NeighbourDistance);
  CPPUNIT_TEST(validRestrictiveBothConfigurations);
  CPPUNIT_TEST(invalidThirdNearBothOfFirstPair);
  CPPUNIT_TEST(invalidFourthNearBothOfFirstPair);
  CPPUNIT_TEST(invalidFirstNearBothOfSecondPair);
  CPPUNIT_TEST(invalidSecondNearBothOfSecondPair);
  CPPUNIT_TEST(invalidNoNeighbours);
  CPPUNIT_TEST(openCornerOnlyInNonRestrictiveCase);
  CPPUNIT_TEST(angleOfOpenCornerIsChecked);
  CPPUNIT_TEST(angleOfClosedCrossCornerIsChecked);
  CPPUNIT_TEST(oppositeSidesMustBeApart);
  CPPUNIT_TEST(badParametersAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void thesisLaserDefaults() {
    const GroupingParams p;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(80 * kDeg, p.minAngleRad, 1e-15);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(100 * kDeg, p.maxAngleRad, 1e-15);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2, p.maxNeighbourDistanceM, 1e-15);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2, p.minOppositeDistanceM, 1e-15);
    CPPUNIT_ASSERT(p.restrictive);
  }

  void stage1AngleWindow() {
    const GroupingParams p;
    const auto pair = [&](double deg) {
      const auto c = corner(deg, 0.1);
      return rgnav::isNeighbourPair(c[0], c[1], p);
    };
    CPPUNIT_ASSERT(pair(90));
    CPPUNIT_ASSERT(pair(81));
    CPPUNIT_ASSERT(!pair(79));
    // The smaller intersection angle of 99 degrees is 81: accepted; of 101 it is 79: rejected.
    CPPUNIT_ASSERT(pair(99));
    CPPUNIT_ASSERT(!pair(101));
    CPPUNIT_ASSERT(!pair(0.5));
  }

  void stage1UpperAngleBound() {
    // With the image parameters' kind of window below 90 degrees the upper bound acts.
    GroupingParams p;
    p.minAngleRad = 20 * kDeg;
    p.maxAngleRad = 60 * kDeg;
    const auto pair = [&](double deg) {
      const auto c = corner(deg, 0.0);
      return rgnav::isNeighbourPair(c[0], c[1], p);
    };
    CPPUNIT_ASSERT(pair(50));
    CPPUNIT_ASSERT(pair(130));  // smaller angle 50
    CPPUNIT_ASSERT(!pair(70));
    CPPUNIT_ASSERT(!pair(15));
  }

  void stage1NeighbourDistance() {
    const GroupingParams p;
    const auto pair = [&](double gap) {
      const auto c = corner(90, gap);
      return rgnav::isNeighbourPair(c[0], c[1], p);
    };
    CPPUNIT_ASSERT(pair(0.0));
    CPPUNIT_ASSERT(pair(0.19));
    CPPUNIT_ASSERT(!pair(0.21));
    // Touching in a T counts as neighbours (distance zero).
    CPPUNIT_ASSERT(rgnav::isNeighbourPair(seg(0, 0, 2, 0), seg(1, 0, 1, 1), p));
  }

  void validRestrictiveBothConfigurations() {
    const Box b = box(2, 1);
    for (const auto& p : {GroupingParams{}, nonRestrictive()}) {
      // i next to l and j next to k: quad(i, j, k, l).
      CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.k, b.l, p) == PairOfPairs::kQuadIJKL);
      // The second pair given the other way round: i next to k' (= l), j next to l' (= k).
      CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.l, b.k, p) == PairOfPairs::kQuadIJLK);
    }
  }

  void invalidThirdNearBothOfFirstPair() {
    // Corner (i, j); k runs 10 cm from i and 15 cm from j inside the corner; l meets k.
    const auto i = seg(0, 0, 1, 0), j = seg(1.05, 0.05, 1.05, 1);
    const auto k = seg(0.9, 0.1, 0.9, 0.8), l = seg(0.3, 0.85, 0.8, 0.85);
    CPPUNIT_ASSERT(rgnav::isNeighbourPair(k, l, GroupingParams{}));
    for (const auto& p : {GroupingParams{}, nonRestrictive()})
      CPPUNIT_ASSERT(classifyPairOfPairs(i, j, k, l, p) == PairOfPairs::kInvalidKNearIAndJ);
  }

  void invalidFourthNearBothOfFirstPair() {
    const auto i = seg(0, 0, 1, 0), j = seg(1.05, 0.05, 1.05, 1);
    const auto k = seg(0.9, 0.1, 0.9, 0.8), l = seg(0.3, 0.85, 0.8, 0.85);
    for (const auto& p : {GroupingParams{}, nonRestrictive()})
      CPPUNIT_ASSERT(classifyPairOfPairs(i, j, l, k, p) == PairOfPairs::kInvalidLNearIAndJ);
  }

  void invalidFirstNearBothOfSecondPair() {
    // The corner (k, l) sits on the middle of the long side i, far from j.
    const auto i = seg(0, 0, 3, 0), j = seg(3.05, 0.05, 3.05, 1);
    const auto k = seg(1, 0.05, 1, 1), l = seg(0.2, 0.1, 0.95, 0.1);
    for (const auto& p : {GroupingParams{}, nonRestrictive()})
      CPPUNIT_ASSERT(classifyPairOfPairs(i, j, k, l, p) == PairOfPairs::kInvalidINearKAndL);
  }

  void invalidSecondNearBothOfSecondPair() {
    const auto i = seg(0, 0, 3, 0), j = seg(3.05, 0.05, 3.05, 1);
    const auto k = seg(1, 0.05, 1, 1), l = seg(0.2, 0.1, 0.95, 0.1);
    for (const auto& p : {GroupingParams{}, nonRestrictive()})
      CPPUNIT_ASSERT(classifyPairOfPairs(j, i, k, l, p) == PairOfPairs::kInvalidJNearKAndL);
  }

  void invalidNoNeighbours() {
    const auto c1 = corner(90, 0.05);
    auto c2 = corner(90, 0.05);
    for (auto& s : c2) s.start += Vector2d(5, 5), s.end += Vector2d(5, 5);
    for (const auto& p : {GroupingParams{}, nonRestrictive()})
      CPPUNIT_ASSERT(classifyPairOfPairs(c1[0], c1[1], c2[0], c2[1], p) == PairOfPairs::kInvalidNoNeighbour);
  }

  void openCornerOnlyInNonRestrictiveCase() {
    // The right side ends half-way up: the corner (j, k) is open, 0.5 m.
    Box b = box(2, 1);
    b.j = seg(2, 0.05, 2, 0.5);
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.k, b.l, GroupingParams{}) == PairOfPairs::kNoQuadrangle);
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.k, b.l, nonRestrictive()) == PairOfPairs::kQuadIJKL);
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.l, b.k, GroupingParams{}) == PairOfPairs::kNoQuadrangle);
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.l, b.k, nonRestrictive()) == PairOfPairs::kQuadIJLK);
  }

  void angleOfOpenCornerIsChecked() {
    // The open side j leans so that it meets k's line at 60 degrees: no quadrangle; at 85: one.
    Box b = box(2, 1);
    b.j = rgnav::segmentFromEndpoints(2, {2, 0.05}, Vector2d(2, 0.05) + 0.45 * dir(60));
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.k, b.l, nonRestrictive()) == PairOfPairs::kNoQuadrangle);
    b.j = rgnav::segmentFromEndpoints(2, {2, 0.05}, Vector2d(2, 0.05) + 0.45 * dir(85));
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.k, b.l, nonRestrictive()) == PairOfPairs::kQuadIJKL);
  }

  void angleOfClosedCrossCornerIsChecked() {
    // l leans at 70 degrees to i but still touches i and k: no quadrangle in either case.
    Box b = box(2, 1);
    b.l = rgnav::segmentFromEndpoints(2, {0, 0.05}, Vector2d(0, 0.05) + 0.9 * dir(70));
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.k, b.l, GroupingParams{}) == PairOfPairs::kNoQuadrangle);
    CPPUNIT_ASSERT(classifyPairOfPairs(b.i, b.j, b.k, b.l, nonRestrictive()) == PairOfPairs::kNoQuadrangle);
  }

  void oppositeSidesMustBeApart() {
    GroupingParams wide;
    wide.minOppositeDistanceM = 0.5;
    // Top and bottom 0.3 m apart: opposite pair (i, k) too close for DO_min = 0.5 m.
    const Box flat = box(2, 0.3);
    CPPUNIT_ASSERT(classifyPairOfPairs(flat.i, flat.j, flat.k, flat.l, GroupingParams{}) == PairOfPairs::kQuadIJKL);
    CPPUNIT_ASSERT(classifyPairOfPairs(flat.i, flat.j, flat.k, flat.l, wide) == PairOfPairs::kNoQuadrangle);
    // Left and right 0.3 m apart: opposite pair (j, l).
    const Box narrow = box(0.3, 2);
    CPPUNIT_ASSERT(classifyPairOfPairs(narrow.i, narrow.j, narrow.k, narrow.l, GroupingParams{}) ==
                   PairOfPairs::kQuadIJKL);
    CPPUNIT_ASSERT(classifyPairOfPairs(narrow.i, narrow.j, narrow.k, narrow.l, wide) == PairOfPairs::kNoQuadrangle);
    // The same for the other configuration.
    CPPUNIT_ASSERT(classifyPairOfPairs(flat.i, flat.j, flat.l, flat.k, wide) == PairOfPairs::kNoQuadrangle);
    CPPUNIT_ASSERT(classifyPairOfPairs(narrow.i, narrow.j, narrow.l, narrow.k, wide) == PairOfPairs::kNoQuadrangle);
  }

  void badParametersAreTypedErrors() {
    GroupingParams p;
    p.minAngleRad = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::validate(p), rgnav::InvalidArgumentError);
    p = {};
    p.maxAngleRad = p.minAngleRad;
    CPPUNIT_ASSERT_THROW(rgnav::validate(p), rgnav::InvalidArgumentError);
    p = {};
    p.maxNeighbourDistanceM = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::validate(p), rgnav::InvalidArgumentError);
    p = {};
    p.minOppositeDistanceM = -0.1;
    CPPUNIT_ASSERT_THROW(rgnav::validate(p), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_NO_THROW(rgnav::validate(GroupingParams{}));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(QuadrangleRulesTest);
