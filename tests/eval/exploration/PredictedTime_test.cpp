// Tests the predicted time of a plan (PredictedTime.h): a straight plan takes the trapezoidal
// profile's time under the limits, a start facing away adds the turn on the spot, a plan that
// folds back is still timed (straights and turns on the spot), no targets take no time.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "tests/eval/exploration/PredictedTime.h"

using namespace rgnav;

namespace {

Plan along(std::initializer_list<Eigen::Vector2d> points) {
  Plan plan;
  for (const Eigen::Vector2d& p : points) plan.targets.push_back({{p.x(), p.y(), 0.0}, RegionId()});
  return plan;
}

}  // namespace

class PredictedTimeTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PredictedTimeTest);
  CPPUNIT_TEST(straightPlanTakesTheTrapezoidTime);
  CPPUNIT_TEST(startFacingAwayAddsATurnOnTheSpot);
  CPPUNIT_TEST(foldingPlanIsStillTimed);
  CPPUNIT_TEST_SUITE_END();

 public:
  void straightPlanTakesTheTrapezoidTime() {
    MotionLimits limits;  // 1 m/s, 0.5 m/s^2 both ways
    const Plan plan = along({{1, 0}, {2, 0}, {3, 0}, {4, 0}});
    // 1 m to speed up, 1 m to brake (1 m/s at 0.5 m/s^2: 2 s each), 2 m at 1 m/s.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(6.0, predictedSeconds(plan, {0, 0, 0}, {}, limits), 0.05);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, predictedSeconds(Plan{}, {0, 0, 0}, {}, limits), 1e-12);
  }

  void startFacingAwayAddsATurnOnTheSpot() {
    MotionLimits limits;
    const Plan plan = along({{1, 0}, {2, 0}, {3, 0}, {4, 0}});
    const double straight = predictedSeconds(plan, {0, 0, 0}, {}, limits);
    const double turned = predictedSeconds(plan, {0, 0, M_PI / 2.0}, {}, limits);
    // A quarter turn at up to pi/2 rad/s^2 from and to a standstill takes at least 2 sqrt(0.5) s.
    CPPUNIT_ASSERT(turned > straight + 1.4);
    CPPUNIT_ASSERT(turned < straight + 4.0);
  }

  void foldingPlanIsStillTimed() {
    MotionLimits limits;
    const Plan plan = along({{2, 0}, {0, 0}});
    const double seconds = predictedSeconds(plan, {0, 0, 0}, {}, limits);
    CPPUNIT_ASSERT(std::isfinite(seconds));
    CPPUNIT_ASSERT(seconds > 2.0 * predictedSeconds(along({{2, 0}}), {0, 0, 0}, {}, limits));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PredictedTimeTest);
