// Tests the swept-footprint check: a chain whose end is free but whose sweep cuts an obstacle is
// found (a check of the end pose alone misses it), the rectangle's corners count, the clearance
// along a chain is measured, and a free chain passes.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/nav/avoidance/SweptFootprint.h"

using rgnav::Cell;
using rgnav::checkSwept;
using rgnav::Footprint;
using rgnav::ObstacleClearance;
using rgnav::OccupancyGrid;
using rgnav::Pose2D;
using rgnav::SweptCheck;
using rgnav::TrajectoryChain;
using rgnav::TrajectorySegment;

namespace {

// 10 x 10 m of 5 cm cells, origin (-5, -5), with the cells of [x0, x1) x [y0, y1) occupied
// (corners on cell borders; a single point: its cell).
OccupancyGrid withBox(double x0, double y0, double x1, double y1) {
  OccupancyGrid grid(200, 200, 0.05, {-5.0, -5.0});
  for (double x = x0 + 0.025; x <= std::max(x1, x0 + 0.05); x += 0.05)
    for (double y = y0 + 0.025; y <= std::max(y1, y0 + 0.05); y += 0.05) grid.set(*grid.cellOf({x, y}), Cell::Occupied);
  return grid;
}

const Footprint kJackal = Footprint::rectangle(0.508, 0.43);

}  // namespace

class SweptFootprintTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SweptFootprintTest);
  CPPUNIT_TEST(theSweepFindsWhatTheEndPoseMisses);
  CPPUNIT_TEST(aCornerCountsWhereTheInscribedDiskIsFree);
  CPPUNIT_TEST(aFreeChainPassesWithItsClearance);
  CPPUNIT_TEST_SUITE_END();

 public:
  void theSweepFindsWhatTheEndPoseMisses() {
    // A post 1 m ahead; the chain drives straight through it to 2 m ahead.
    const ObstacleClearance clearance(withBox(1.0, -0.05, 1.1, 0.05));
    const TrajectoryChain chain({TrajectorySegment{{0, 0, 0}, 2.0, 0.0, 0.0}});
    CPPUNIT_ASSERT(!kJackal.overlapsGrid(clearance.obstacles(), chain.end()));  // the naive check
    CPPUNIT_ASSERT(clearance.footprintClearance(kJackal, chain.end(), 1.0) > 0.3);
    const SweptCheck check = checkSwept(clearance, chain, kJackal, {});
    CPPUNIT_ASSERT(!check.clear);
    // The front (0.254 m ahead) plus the margin stops before the post at 1 m.
    CPPUNIT_ASSERT(check.freeLength > 0.6 && check.freeLength < 0.75);
  }

  void aCornerCountsWhereTheInscribedDiskIsFree() {
    // One cell centred at (0.225, 0.225), seen from the pose at (0.22, 0.18) in the robot's frame:
    // 0.284 m from the centre, outside the inscribed disk (0.215 m), inside the rectangle.
    const ObstacleClearance clearance(withBox(0.2, 0.2, 0.2, 0.2));
    const Pose2D pose{0.005, 0.045, 0.0};
    CPPUNIT_ASSERT(clearance.footprintClearance(Footprint::disk(0.215), pose, 0.5) > 0.03);
    CPPUNIT_ASSERT(clearance.footprintClearance(kJackal, pose, 0.5) < 0.0);
  }

  void aFreeChainPassesWithItsClearance() {
    // A wall 0.6 m beside a straight chain: the rectangle's side is 0.385 m from its nearest cell
    // edge (cells as half-cell disks: within a centimetre).
    const ObstacleClearance clearance(withBox(-1.0, 0.6, 3.0, 0.7));
    const TrajectoryChain chain({TrajectorySegment{{0, 0, 0}, 2.0, 0.0, 0.0}});
    const SweptCheck check = checkSwept(clearance, chain, kJackal, {0.05, 0.03, 0.5});
    CPPUNIT_ASSERT(check.clear);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, check.freeLength, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.6 - 0.215, check.minClearance, 0.015);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(SweptFootprintTest);
