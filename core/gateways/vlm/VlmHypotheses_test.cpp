// Tests VLM hypotheses (thesis 4.1.1) on constructed scans of every junction type: virtual lines
// span openings, depth singularities sit at the corners of side openings, and the hypothesis of
// the true gateway is found with left and right lines on the correct sides and its hidden line
// from a singularity where a side hallway leaves (from the hallway width otherwise), also with
// range noise and a robot that is off the axis and turned. A straight hallway gives no
// hypothesis at the labelled place.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <optional>

#include "core/common/Errors.h"
#include "core/gateways/vlm/DepthSingularities.h"
#include "core/gateways/vlm/VlmObserver.h"
#include "core/gateways/vlm/testing/JunctionScan.h"
#include "core/lines/LineExtractor.h"

using rgnav::GatewayClass;
using rgnav::VlmObservation;

namespace {

const rgnav::Pose2D kPose{-4.0, 0.15, 0.05};

// The observation of the true gateway of a 2 m layout seen from `pose`, if any.
std::optional<VlmObservation> trueGateway(const std::vector<VlmObservation>& obs, const rgnav::Pose2D& pose,
                                          double tolerance = 0.12) {
  for (const VlmObservation& o : obs)
    if (rgnav::largestPointDistance(rgnav::transformed(o.hypothesis.gatewayPoints, pose),
                                    rgnav::squareGatewayArea(2.0)) <= tolerance)
      return o;
  return std::nullopt;
}

std::vector<VlmObservation> observe(GatewayClass c, const rgnav::Pose2D& pose, double noise = 0.01) {
  return rgnav::VlmObserver().observe(rgnav::testing::junctionScan(c, 2.0, pose, noise));
}

}  // namespace

class VlmHypothesesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(VlmHypothesesTest);
  CPPUNIT_TEST(virtualLinesSpanOpenings);
  CPPUNIT_TEST(singularitiesAtSideOpenings);
  CPPUNIT_TEST(trueGatewayOfEveryJunction);
  CPPUNIT_TEST(straightHallwayHasNoGatewayHere);
  CPPUNIT_TEST(identicalHypothesesAreKeptOnce);
  CPPUNIT_TEST(badParametersAreRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  // In an X-crossing the left wall before and after the crossing is one virtual line.
  void virtualLinesSpanOpenings() {
    const rgnav::Pose2D pose{-3.0, 0.0, 0.0};
    const rgnav::LaserScan scan = rgnav::testing::junctionScan(GatewayClass::XCrossing, 2.0, pose);
    const auto lines = rgnav::groupVirtualLines(rgnav::LineExtractor().extract(scan, rgnav::Pose2D{}, 0));
    const auto left = std::find_if(lines.begin(), lines.end(), [](const rgnav::VirtualLine& l) {
      return std::abs(l.line.direction.y()) < 0.01 && std::abs(l.line.signedOffset({0.0, 0.0})) > 0.9 &&
             l.line.point.y() > 0.0;
    });
    CPPUNIT_ASSERT(left != lines.end());
    CPPUNIT_ASSERT(left->segmentCount >= 2);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, std::abs(left->line.signedOffset({0.0, 0.0})), 0.01);
  }

  void singularitiesAtSideOpenings() {
    const rgnav::Pose2D pose{-4.0, 0.0, 0.0};
    for (const GatewayClass c : {GatewayClass::TJunction, GatewayClass::LTurn, GatewayClass::RTurn}) {
      const auto singular = rgnav::depthSingularities(rgnav::testing::junctionScan(c, 2.0, pose), 0.5);
      const auto near = [&](double y) {
        return std::any_of(singular.begin(), singular.end(), [&](const Eigen::Vector2d& s) {
          return (s - Eigen::Vector2d(3.0, y)).norm() < 0.1;  // corner (-1, y) in the sensor frame
        });
      };
      const rgnav::GatewayOpenings open = rgnav::openingsOf(c);
      CPPUNIT_ASSERT_EQUAL(open.left, near(1.0));
      CPPUNIT_ASSERT_EQUAL(open.right, near(-1.0));
    }
    CPPUNIT_ASSERT(rgnav::depthSingularities(rgnav::testing::junctionScan(GatewayClass::DeadEnd, 2.0, pose), 0.5).empty());
  }

  void trueGatewayOfEveryJunction() {
    for (const GatewayClass c : rgnav::kGatewayClasses) {
      if (c == GatewayClass::Hallway) continue;
      const auto found = trueGateway(observe(c, kPose), kPose);
      CPPUNIT_ASSERT_MESSAGE(std::string(rgnav::gatewayClassName(c)), found.has_value());
      const rgnav::VlmHypothesis& h = found->hypothesis;
      const rgnav::GatewayOpenings open = rgnav::openingsOf(c);
      CPPUNIT_ASSERT(h.left.signedOffset({0.0, 0.0}) < 0.0);  // the robot is right of the left line
      CPPUNIT_ASSERT(h.right.signedOffset({0.0, 0.0}) > 0.0);
      CPPUNIT_ASSERT(h.left.direction.x() > 0.9);
      const auto expected = open.left || open.right ? rgnav::HiddenLineSource::DepthSingularity
                                                    : rgnav::HiddenLineSource::HallwayWidth;
      CPPUNIT_ASSERT_MESSAGE(std::string(rgnav::gatewayClassName(c)), expected == h.hiddenSource);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(std::hypot(kPose.x, kPose.y), found->distanceM, 0.05);
      CPPUNIT_ASSERT_EQUAL(rgnav::kGatewayClasses.size(), found->weights.size());
    }
  }

  void straightHallwayHasNoGatewayHere() {
    for (const VlmObservation& o : observe(GatewayClass::Hallway, kPose))
      CPPUNIT_ASSERT(rgnav::gatewayCentre(rgnav::transformed(o.hypothesis.gatewayPoints, kPose)).norm() > 1.0);
  }

  // A T-junction has singularities at both corners and the width-based hidden line: one VLM.
  void identicalHypothesesAreKeptOnce() {
    const auto obs = observe(GatewayClass::TJunction, kPose, 0.0);
    const auto close = std::count_if(obs.begin(), obs.end(), [](const VlmObservation& o) {
      return rgnav::largestPointDistance(rgnav::transformed(o.hypothesis.gatewayPoints, kPose),
                                         rgnav::squareGatewayArea(2.0)) < 0.1;
    });
    CPPUNIT_ASSERT_EQUAL(std::ptrdiff_t{1}, close);
  }

  void badParametersAreRejected() {
    rgnav::VlmObserverParams p;
    p.hypotheses.hallwayWidthM = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::VlmObserver{p}, rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::depthSingularities(rgnav::LaserScan{}, 0.0), rgnav::InvalidArgumentError);
    rgnav::VirtualLineParams v;
    v.maxAngleRad = M_PI;
    CPPUNIT_ASSERT_THROW(rgnav::groupVirtualLines({}, v), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(VlmHypothesesTest);
