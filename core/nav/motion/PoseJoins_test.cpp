// Tests the pose joins: symmetric turns end on the outgoing line at the tangent length from the
// corner with continuous curvature within the maximum; the G1 Hermite clothoid reaches the target
// pose (a quarter circle exactly) and respects the curvature bound; polylines of target poses
// become continuous-curvature chains that start at the start pose, end at the last target and
// fit short legs by sharper turns, and folded polylines are refused.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <random>

#include "core/common/Errors.h"
#include "core/nav/motion/PoseJoins.h"

using rgnav::Pose2D;
using rgnav::TrajectoryChain;
using rgnav::TrajectorySegment;
using rgnav::TurnShape;

namespace {

// Curvature within the maximum everywhere and continuous at every joint.
void assertSmooth(const TrajectoryChain& chain, double maxCurvature) {
  const auto& segments = chain.segments();
  CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, segments.front().curvature, 1e-9);
  CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, segments.back().curvatureAt(segments.back().length), 1e-9);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const TrajectorySegment& s = segments[i];
    CPPUNIT_ASSERT(std::abs(s.curvature) <= maxCurvature + 1e-9);
    CPPUNIT_ASSERT(std::abs(s.curvatureAt(s.length)) <= maxCurvature + 1e-9);
    if (i > 0) CPPUNIT_ASSERT_DOUBLES_EQUAL(segments[i - 1].curvatureAt(segments[i - 1].length), s.curvature, 1e-9);
  }
}

// The distance of point p from the line through a and b.
double offLine(const Pose2D& p, const Pose2D& a, const Pose2D& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return std::abs(dx * (p.y - a.y) - dy * (p.x - a.x)) / std::hypot(dx, dy);
}

}  // namespace

class PoseJoinsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PoseJoinsTest);
  CPPUNIT_TEST(turnsEndOnOutgoingLine);
  CPPUNIT_TEST(sharpTurnsApproachTheArc);
  CPPUNIT_TEST(cornerTurnStartsBeforeCorner);
  CPPUNIT_TEST(clothoidJoinReachesTarget);
  CPPUNIT_TEST(clothoidJoinRespectsCurvature);
  CPPUNIT_TEST(polylineBecomesSmoothChain);
  CPPUNIT_TEST(polylineFromOtherHeading);
  CPPUNIT_TEST(shortLegsGetSharperTurns);
  CPPUNIT_TEST(impossiblePolylinesAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void turnsEndOnOutgoingLine() {
    const TurnShape shape;
    for (double deflection : {0.05, 0.4, 1.0, -1.57, 2.5, -3.0}) {
      const double t = rgnav::turnTangentLength(deflection, shape);
      const TrajectoryChain turn(rgnav::symmetricTurn({}, deflection, shape));
      assertSmooth(turn, shape.maxCurvature);
      const Pose2D end = turn.end();
      CPPUNIT_ASSERT_DOUBLES_EQUAL(deflection, end.theta, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(t + t * std::cos(deflection), end.x, 1e-9);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(t * std::sin(deflection), end.y, 1e-9);
      // Small deflections need no arc and stay below the maximum curvature.
      CPPUNIT_ASSERT_EQUAL(std::abs(deflection) > 1.0 ? std::size_t{3} : std::size_t{2}, turn.segments().size());
    }
    CPPUNIT_ASSERT(rgnav::symmetricTurn({}, 0.0, shape).empty());
    CPPUNIT_ASSERT_EQUAL(0.0, rgnav::turnTangentLength(0.0, shape));
  }

  void sharpTurnsApproachTheArc() {
    TurnShape shape;
    shape.sharpness = 1e5;
    shape.maxSharpness = 1e5;
    // A 90 degree turn of radius 0.5: tangent length r tan(45 deg) = 0.5.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, rgnav::turnTangentLength(M_PI / 2.0, shape), 1e-4);
    // Gentler clothoids make the turn start earlier.
    CPPUNIT_ASSERT(rgnav::turnTangentLength(M_PI / 2.0, TurnShape{}) > 0.55);
  }

  void cornerTurnStartsBeforeCorner() {
    const TurnShape shape;
    const auto turn = rgnav::cornerTurn({0.0, 0.0, 0.0}, {3.0, 1.0, 0.0}, {3.0, 4.0, 0.0}, shape);
    CPPUNIT_ASSERT(turn.has_value());
    const TrajectoryChain chain(*turn);
    CPPUNIT_ASSERT(offLine(chain.start(), {0.0, 0.0, 0.0}, {3.0, 1.0, 0.0}) < 1e-9);
    CPPUNIT_ASSERT(offLine(chain.end(), {3.0, 1.0, 0.0}, {3.0, 4.0, 0.0}) < 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 2.0, chain.end().theta, 1e-9);
    CPPUNIT_ASSERT(!rgnav::cornerTurn({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, shape));
    CPPUNIT_ASSERT(!rgnav::cornerTurn({1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, shape));
  }

  void clothoidJoinReachesTarget() {
    // A quarter circle of radius 1 is the clothoid of sharpness 0.
    const auto quarter = rgnav::clothoidJoin({0.0, 0.0, 0.0}, {1.0, 1.0, M_PI / 2.0}, 10.0);
    CPPUNIT_ASSERT(quarter.has_value());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 2.0, quarter->length, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, quarter->curvature, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, quarter->sharpness, 1e-9);
    std::mt19937 random(27);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0), angle(-M_PI, M_PI);
    for (int i = 0; i < 200; ++i) {
      const Pose2D from{coordinate(random), coordinate(random), angle(random)};
      const Pose2D to{coordinate(random), coordinate(random), angle(random)};
      const auto join = rgnav::clothoidJoin(from, to, 1e6);
      CPPUNIT_ASSERT(join.has_value());
      CPPUNIT_ASSERT(join->start == from);
      const Pose2D end = join->end();
      CPPUNIT_ASSERT_DOUBLES_EQUAL(to.x, end.x, 1e-8);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(to.y, end.y, 1e-8);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, rgnav::normalizeAngle(to.theta - end.theta), 1e-9);
    }
    CPPUNIT_ASSERT(!rgnav::clothoidJoin({1.0, 1.0, 0.0}, {1.0, 1.0, 1.0}, 10.0));
  }

  void clothoidJoinRespectsCurvature() {
    // The quarter circle of radius 1 needs curvature 1.
    CPPUNIT_ASSERT(!rgnav::clothoidJoin({0.0, 0.0, 0.0}, {1.0, 1.0, M_PI / 2.0}, 0.9));
    CPPUNIT_ASSERT(rgnav::clothoidJoin({0.0, 0.0, 0.0}, {1.0, 1.0, M_PI / 2.0}, 1.1));
  }

  void polylineBecomesSmoothChain() {
    // Targets as the planner spaces them along an L: 4 m east, then 3 m north.
    const std::vector<Pose2D> targets = {{1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {3.0, 0.0, 0.0}, {4.0, 0.0, M_PI / 2.0},
                                         {4.0, 1.5, M_PI / 2.0}, {4.0, 3.0, M_PI / 2.0}};
    const TurnShape shape;
    const auto chain = rgnav::smoothPolyline({0.0, 0.0, 0.0}, targets, shape);
    CPPUNIT_ASSERT(chain.has_value());
    assertSmooth(*chain, shape.maxCurvature);
    CPPUNIT_ASSERT(chain->start() == (Pose2D{0.0, 0.0, 0.0}));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, chain->end().x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, chain->end().y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 2.0, chain->end().theta, 1e-9);
    // Straight, turn (three segments), straight; shorter than the polyline by cutting the corner.
    CPPUNIT_ASSERT_EQUAL(std::size_t{5}, chain->segments().size());
    CPPUNIT_ASSERT(chain->length() < 7.0 && chain->length() > 6.5);
  }

  void polylineFromOtherHeading() {
    // The robot faces north; the targets lie east.
    const std::vector<Pose2D> targets = {{2.0, 0.0, 0.0}, {4.0, 0.0, 0.0}};
    const TurnShape shape;
    const auto chain = rgnav::smoothPolyline({0.0, 0.0, M_PI / 2.0}, targets, shape);
    CPPUNIT_ASSERT(chain.has_value());
    assertSmooth(*chain, shape.maxCurvature);
    CPPUNIT_ASSERT(chain->start() == (Pose2D{0.0, 0.0, M_PI / 2.0}));
    CPPUNIT_ASSERT(chain->segments().front().sharpness != 0.0);  // turning at once
    CPPUNIT_ASSERT(offLine(chain->end(), {0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}) > 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, chain->end().theta, 1e-9);
    // It ends on the line from the start corner to the last target, at the last target's foot.
    const Pose2D end = chain->end();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, end.x, 1e-9);
  }

  void shortLegsGetSharperTurns() {
    // A detour of 90 degree corners 1.2 m apart: the default turns (tangent > 0.6 m) overlap.
    CPPUNIT_ASSERT(rgnav::turnTangentLength(M_PI / 2.0, TurnShape{}) > 0.6);
    const std::vector<Pose2D> targets = {{2.0, 0.0, 0.0}, {2.0, 1.2, 0.0}, {3.2, 1.2, 0.0}, {3.2, 0.0, 0.0},
                                         {5.0, 0.0, 0.0}};
    const TurnShape shape;
    const auto chain = rgnav::smoothPolyline({0.0, 0.0, 0.0}, targets, shape);
    CPPUNIT_ASSERT(chain.has_value());
    assertSmooth(*chain, shape.maxCurvature);
    double sharpest = 0.0;
    for (const TrajectorySegment& s : chain->segments()) sharpest = std::max(sharpest, std::abs(s.sharpness));
    CPPUNIT_ASSERT(sharpest > shape.sharpness);
    CPPUNIT_ASSERT(sharpest <= shape.maxSharpness);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, chain->end().x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, chain->end().y, 1e-9);
  }

  void impossiblePolylinesAreRefused() {
    const TurnShape shape;
    // Folding back on itself.
    CPPUNIT_ASSERT(!rgnav::smoothPolyline({0.0, 0.0, 0.0}, {{2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}, shape));
    // Corners 0.2 m apart: even the sharpest turns of radius 0.5 m do not fit.
    CPPUNIT_ASSERT(!rgnav::smoothPolyline({0.0, 0.0, 0.0}, {{2.0, 0.0, 0.0}, {2.0, 0.2, 0.0}, {3.0, 0.2, 0.0}}, shape));
    CPPUNIT_ASSERT(!rgnav::smoothPolyline({0.0, 0.0, 0.0}, {}, shape));
    TurnShape bad;
    bad.sharpness = 100.0;
    CPPUNIT_ASSERT_THROW(rgnav::smoothPolyline({0.0, 0.0, 0.0}, {{2.0, 0.0, 0.0}}, bad), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PoseJoinsTest);
