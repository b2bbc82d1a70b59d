// Tests the cutting of a path into target poses: spacing within [min, max] along the path, every
// corner kept unless too close, the goal always last with its heading.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/planning/TargetSpacing.h"

using Eigen::Vector2d;
using rgnav::targetsAlong;

class TargetSpacingTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TargetSpacingTest);
  CPPUNIT_TEST(longStretchesAreDividedEvenly);
  CPPUNIT_TEST(closeCornersAreDroppedButTheGoalStays);
  CPPUNIT_TEST(theGoalKeepsTheLastHeading);
  CPPUNIT_TEST(badSpacingsAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void longStretchesAreDividedEvenly() {
    const std::vector<Vector2d> path{{0, 0}, {5, 0}};
    const auto targets = targetsAlong(path, 0.5, 2.0, std::nullopt);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), targets.size());  // 5 m in three pieces of 1.67 m
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0 / 3.0, targets[0].x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, targets[2].x, 1e-9);
    for (const auto& t : targets) CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, t.theta, 1e-12);
  }

  void closeCornersAreDroppedButTheGoalStays() {
    // Corners at 1.0 and 1.2 along the path: the second is too close to the first; the goal at
    // 1.4 is too close too and replaces the target at 1.0 (the gap from the start stays <= 2 m).
    const std::vector<Vector2d> path{{0, 0}, {1, 0}, {1, 0.2}, {1.2, 0.2}};
    const auto targets = targetsAlong(path, 0.5, 2.0, 0.7);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), targets.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.2, targets.back().x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.7, targets.back().theta, 1e-12);
    // Spacing along a zig-zag path stays within the limits between consecutive targets.
    std::vector<Vector2d> zigzag{{0, 0}};
    for (int i = 1; i <= 20; ++i) zigzag.push_back({0.3 * i, (i % 2) * 0.3});
    const auto many = targetsAlong(zigzag, 0.5, 2.0, std::nullopt);
    CPPUNIT_ASSERT(many.size() >= 5);
    for (std::size_t i = 1; i < many.size(); ++i) {
      const double gap = std::hypot(many[i].x - many[i - 1].x, many[i].y - many[i - 1].y);
      CPPUNIT_ASSERT(gap <= 2.0 + 1e-9);
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(6.0, many.back().x, 1e-9);
  }

  void theGoalKeepsTheLastHeading() {
    const std::vector<Vector2d> path{{0, 0}, {3, 0}, {3, 4}};
    const auto targets = targetsAlong(path, 0.5, 2.0, std::nullopt);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 2, targets.back().theta, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, targets.front().theta, 1e-12);
  }

  void badSpacingsAreRefused() {
    const std::vector<Vector2d> path{{0, 0}, {3, 0}};
    CPPUNIT_ASSERT_THROW(targetsAlong(path, 0.0, 2.0, std::nullopt), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(targetsAlong(path, 2.0, 1.0, std::nullopt), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TargetSpacingTest);
