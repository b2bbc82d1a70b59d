// Tests the overlap transfers: two regions whose free cells overlap give one transfer point inside
// both per overlapping piece, in the map frame whatever the regions' frames; disjoint or barely
// touching regions give none.
#include <cppunit/extensions/HelperMacros.h>

#include "core/nav/planning/RegionOverlaps.h"

using Eigen::Vector2d;
using rgnav::Cell;
using rgnav::OccupancyGrid;
using rgnav::Pose2D;
using rgnav::RegionGrid;

namespace {

// A region grid of w x h metres at 0.05 m, free except a one-cell border, origin at (0, 0) of
// its region frame.
RegionGrid freeBox(double w, double h) {
  RegionGrid g{OccupancyGrid(static_cast<int>(w / 0.05), static_cast<int>(h / 0.05), 0.05, {0.0, 0.0}, Cell::Free), {}};
  for (int c = 0; c < g.grid.width(); ++c) {
    g.grid.set({c, 0}, Cell::Occupied);
    g.grid.set({c, g.grid.height() - 1}, Cell::Occupied);
  }
  for (int r = 0; r < g.grid.height(); ++r) {
    g.grid.set({0, r}, Cell::Occupied);
    g.grid.set({g.grid.width() - 1, r}, Cell::Occupied);
  }
  return g;
}

}  // namespace

class RegionOverlapsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionOverlapsTest);
  CPPUNIT_TEST(overlappingRegionsGiveOneTransferInBoth);
  CPPUNIT_TEST(framesArePlacedInTheMap);
  CPPUNIT_TEST(disjointOrTouchingRegionsGiveNone);
  CPPUNIT_TEST_SUITE_END();

 public:
  void overlappingRegionsGiveOneTransferInBoth() {
    const RegionGrid a = freeBox(4.0, 3.0), b = freeBox(4.0, 3.0);
    const Pose2D frameA{0.0, 0.0, 0.0}, frameB{3.0, 0.0, 0.0};  // overlap: x in [3, 4]
    const auto transfers = rgnav::overlapTransfers(a, frameA, b, frameB, 0.15, 0.25);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), transfers.size());
    const Vector2d p = transfers.front();
    CPPUNIT_ASSERT(a.freeAt(p));
    CPPUNIT_ASSERT(b.freeAt(p - Vector2d(3.0, 0.0)));
    CPPUNIT_ASSERT(p.x() > 3.0 && p.x() < 4.0 && p.y() > 1.0 && p.y() < 2.0);  // near the piece's centre
  }

  void framesArePlacedInTheMap() {
    const RegionGrid a = freeBox(4.0, 3.0), b = freeBox(4.0, 3.0);
    // Region b turned by 90 degrees about its origin placed at (5, 1): it covers x in [2, 5].
    const Pose2D frameA{0.0, 0.0, 0.0}, frameB{5.0, 1.0, M_PI / 2};
    const auto transfers = rgnav::overlapTransfers(a, frameA, b, frameB, 0.15, 0.25);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), transfers.size());
    CPPUNIT_ASSERT(a.freeAt(transfers.front()));
    const Pose2D inB = rgnav::between(frameB, {transfers.front().x(), transfers.front().y(), 0.0});
    CPPUNIT_ASSERT(b.freeAt({inB.x, inB.y}));
  }

  void disjointOrTouchingRegionsGiveNone() {
    const RegionGrid a = freeBox(4.0, 3.0), b = freeBox(4.0, 3.0);
    CPPUNIT_ASSERT(rgnav::overlapTransfers(a, {0, 0, 0}, b, {10.0, 0, 0}, 0.15, 0.25).empty());
    // Overlapping by 0.1 m: the borders meet, no free cell is shared.
    CPPUNIT_ASSERT(rgnav::overlapTransfers(a, {0, 0, 0}, b, {3.9, 0, 0}, 0.15, 0.25).empty());
    // Overlapping in a corner of 0.4 x 0.4 m: 0.09 m2 of shared free cells, below the minimum.
    CPPUNIT_ASSERT(rgnav::overlapTransfers(a, {0, 0, 0}, b, {3.6, 2.6, 0}, 0.15, 0.25).empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), rgnav::overlapTransfers(a, {0, 0, 0}, b, {3.6, 2.6, 0}, 0.15, 0.05).size());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RegionOverlapsTest);
