// Tests the measures of thesis 4.1.2 on ideal and perturbed VLMs: W_d and W_r of a square, a
// stretched and a skewed quadrangle; the on-line / over-line freespace measures per sector on
// scans of every junction type (the true class gets the largest class measure), a VLM moved off
// the walls losing on-line support, clutter in front of a line occluding beams without counting
// against the line, clutter in an opening; W(GW, VLM) as the weighted sum of 4.1.2.3.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/gateways/vlm/FreespaceMeasures.h"
#include "core/gateways/vlm/GatewayWeights.h"
#include "core/gateways/vlm/ModelMeasures.h"
#include "core/gateways/vlm/testing/JunctionScan.h"

using rgnav::GatewayClass;
using rgnav::GatewayPoints;
using rgnav::Sector;

namespace {

const rgnav::Pose2D kPose{-2.5, 0.1, 0.0};  // heading along +x: sensor frame = world frame shifted

GatewayPoints inSensorFrame(const GatewayPoints& world) {
  return rgnav::transformed(world, rgnav::inverse(kPose));
}

// The VLM whose gateway points are `g` (sensor frame).
rgnav::VlmHypothesis vlmOf(const GatewayPoints& g) {
  using namespace rgnav;
  return {*lineThrough(g[kHiddenLeft], g[kFrontLeft]), *lineThrough(g[kHiddenRight], g[kFrontRight]),
          *lineThrough(g[kFrontRight], g[kFrontLeft]), *lineThrough(g[kHiddenRight], g[kHiddenLeft]),
          HiddenLineSource::HallwayWidth, g};
}

rgnav::SectorFreespace idealFreespace(GatewayClass c, const std::vector<rgnav::testing::Wall>& clutter = {}) {
  const rgnav::LaserScan scan = rgnav::testing::junctionScan(c, 2.0, kPose, 0.01, 3, clutter);
  return rgnav::freespaceMeasures(vlmOf(inSensorFrame(rgnav::squareGatewayArea(2.0))), scan);
}

}  // namespace

class MeasuresTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(MeasuresTest);
  CPPUNIT_TEST(idealSquare);
  CPPUNIT_TEST(stretchedQuadrangle);
  CPPUNIT_TEST(skewedQuadrangle);
  CPPUNIT_TEST(freespacePicksTheTrueClass);
  CPPUNIT_TEST(deadEndIsOnLineEverywhere);
  CPPUNIT_TEST(displacedVlmLosesOnLineSupport);
  CPPUNIT_TEST(occludedBeamsAreNoEvidence);
  CPPUNIT_TEST(clutterInAnOpeningLowersOverLine);
  CPPUNIT_TEST(weightsCombineTheMeasures);
  CPPUNIT_TEST(badParametersAreRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  void idealSquare() {
    const GatewayPoints square = rgnav::squareGatewayArea(2.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, rgnav::distanceMeasure(square, 2.0), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, rgnav::rectangularityMeasure(square), 1e-12);
  }

  // Sides 2, 2.5, 2, 2.5 against d_hw = 2: w = 1, 1 - sqrt(0.25), ...; still a rectangle.
  void stretchedQuadrangle() {
    const GatewayPoints rect{Eigen::Vector2d(-1.25, 1), Eigen::Vector2d(1.25, 1), Eigen::Vector2d(1.25, -1),
                             Eigen::Vector2d(-1.25, -1)};
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.75, rgnav::distanceMeasure(rect, 2.0), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, rgnav::rectangularityMeasure(rect), 1e-12);
    CPPUNIT_ASSERT(rgnav::distanceMeasure(rect, 4.0) < rgnav::distanceMeasure(rect, 2.0));
  }

  // A parallelogram sheared by s: every inner angle deviates from 90 degrees by atan(s / 2).
  void skewedQuadrangle() {
    const double s = 0.4;
    const GatewayPoints skewed{Eigen::Vector2d(-1 + s, 1), Eigen::Vector2d(1 + s, 1), Eigen::Vector2d(1, -1),
                               Eigen::Vector2d(-1, -1)};
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 - 4.0 * std::atan(s / 2.0) / (2.0 * M_PI), rgnav::rectangularityMeasure(skewed),
                                 1e-12);
    CPPUNIT_ASSERT(rgnav::distanceMeasure(skewed, 2.0) < 1.0);  // two sides are longer than 2 m
  }

  void freespacePicksTheTrueClass() {
    for (const GatewayClass truth : rgnav::kGatewayClasses) {
      if (truth == GatewayClass::Hallway) continue;
      const rgnav::SectorFreespace fsm = idealFreespace(truth);
      for (const GatewayClass other : rgnav::kGatewayClasses) {
        if (other == truth || other == GatewayClass::Hallway) continue;
        CPPUNIT_ASSERT_MESSAGE(std::string(rgnav::gatewayClassName(truth)) + " vs " +
                                   std::string(rgnav::gatewayClassName(other)),
                               rgnav::classFreespace(truth, fsm) > rgnav::classFreespace(other, fsm) + 0.3);
      }
      CPPUNIT_ASSERT(rgnav::classFreespace(truth, fsm) > 2.5);
    }
  }

  void deadEndIsOnLineEverywhere() {
    const rgnav::SectorFreespace fsm = idealFreespace(GatewayClass::DeadEnd);
    for (const Sector s : {Sector::Left, Sector::Front, Sector::Right}) {
      CPPUNIT_ASSERT(fsm.on(s) > 0.95);
      CPPUNIT_ASSERT_EQUAL(0.0, fsm.over(s));
      CPPUNIT_ASSERT(fsm.beams[static_cast<std::size_t>(s)] > 10);
    }
  }

  // The VLM of a dead end moved 0.4 m forward: the front wall lies before the virtual front line.
  void displacedVlmLosesOnLineSupport() {
    GatewayPoints moved = rgnav::squareGatewayArea(2.0);
    for (Eigen::Vector2d& p : moved) p.x() += 0.4;
    const rgnav::LaserScan scan = rgnav::testing::junctionScan(GatewayClass::DeadEnd, 2.0, kPose, 0.01);
    const rgnav::SectorFreespace fsm = rgnav::freespaceMeasures(vlmOf(inSensorFrame(moved)), scan);
    CPPUNIT_ASSERT(fsm.on(Sector::Front) < 0.05);
    CPPUNIT_ASSERT(rgnav::classFreespace(GatewayClass::DeadEnd, fsm) <
                   rgnav::classFreespace(GatewayClass::DeadEnd, idealFreespace(GatewayClass::DeadEnd)) - 0.9);
  }

  // A 0.6 m box 0.5 m before the front wall of an L-turn hides part of it: fewer beams see the
  // wall, and those that do still all end on it.
  void occludedBeamsAreNoEvidence() {
    const auto box = rgnav::testing::boxWalls({0.3, 0.0}, 0.0, 0.3, 0.6);
    const rgnav::SectorFreespace clean = idealFreespace(GatewayClass::LTurn);
    const rgnav::SectorFreespace cluttered = idealFreespace(GatewayClass::LTurn, box);
    const auto front = static_cast<std::size_t>(Sector::Front);
    CPPUNIT_ASSERT_EQUAL(clean.beams[front], cluttered.beams[front]);
    CPPUNIT_ASSERT_EQUAL(clean.beams[front], clean.seenBeams[front]);
    CPPUNIT_ASSERT(cluttered.seenBeams[front] + 5 < clean.seenBeams[front]);
    CPPUNIT_ASSERT(clean.on(Sector::Front) > 0.95);
    CPPUNIT_ASSERT(cluttered.on(Sector::Front) > 0.95);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(clean.on(Sector::Right), cluttered.on(Sector::Right), 1e-12);
  }

  // A box standing in the left hallway of an L-turn, 0.3 m behind the opening: beams through
  // the opening end on it, short of the over-line setback of the side, so Over Line drops.
  void clutterInAnOpeningLowersOverLine() {
    const auto box = rgnav::testing::boxWalls({0.0, 1.45}, 0.0, 2.0, 0.3);
    const rgnav::SectorFreespace clean = idealFreespace(GatewayClass::LTurn);
    const rgnav::SectorFreespace cluttered = idealFreespace(GatewayClass::LTurn, box);
    CPPUNIT_ASSERT(clean.over(Sector::Left) > 0.8);
    CPPUNIT_ASSERT(cluttered.over(Sector::Left) > 0.8);  // 0.3 m is beyond the 0.1 m setback
    const auto closer = rgnav::testing::boxWalls({0.0, 1.2}, 0.0, 2.0, 0.3);  // its face 0.05 m behind
    CPPUNIT_ASSERT(idealFreespace(GatewayClass::LTurn, closer).over(Sector::Left) < 0.1);
    // Most of its face is within the on-line band along the beams: the opening looks closed.
    CPPUNIT_ASSERT(idealFreespace(GatewayClass::LTurn, closer).on(Sector::Left) > 0.6);
  }

  void weightsCombineTheMeasures() {
    rgnav::SectorFreespace fsm;
    fsm.onLine = {0.2, 0.9, 1.0};
    fsm.overLine = {0.7, 0.1, 0.0};
    const rgnav::WeightParams params{0.4, 0.6};
    const std::vector<double> w = rgnav::gatewayWeights(0.8, 0.9, fsm, params);
    CPPUNIT_ASSERT_EQUAL(rgnav::kGatewayClasses.size(), w.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2 * 1.7 + 0.2 * (0.7 + 0.9 + 1.0), w[4], 1e-12);  // L-Turn
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2 * 1.7 + 0.2 * (0.7 + 0.1 + 0.0), w[0], 1e-12);  // X-Crossing
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2 * 1.7 + 0.2 * (0.2 + 0.9 + 1.0), w[6], 1e-12);  // Deadend
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2 * 1.7 + 0.2 * (0.2 + 0.1 + 1.0), w[7], 1e-12);  // Hallway
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, std::size_t(std::max_element(w.begin(), w.end()) - w.begin()));
  }

  void badParametersAreRejected() {
    CPPUNIT_ASSERT_THROW(rgnav::distanceMeasure(rgnav::squareGatewayArea(2.0), 0.0),
                         rgnav::InvalidArgumentError);
    rgnav::FreespaceParams p;
    p.onLineLowerM = 0.2;
    p.onLineUpperM = 0.1;
    CPPUNIT_ASSERT_THROW(rgnav::freespaceMeasures(vlmOf(rgnav::squareGatewayArea(2.0)), rgnav::LaserScan{}, p),
                         rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(MeasuresTest);
