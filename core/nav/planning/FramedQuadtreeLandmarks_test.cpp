// Tests the landmark distances: consistent along every graph edge (the bound changes by at most the
// edge's length), zero at each landmark, never below the straight-line distance to it, and
// unreachable exactly outside the landmarks' component.
#include <cppunit/extensions/HelperMacros.h>

#include <random>

#include "core/nav/planning/FramedQuadtreeLandmarks.h"

using rgnav::Cell;
using rgnav::FramedQuadtree;
using rgnav::FramedQuadtreeLandmarks;
using rgnav::OccupancyGrid;

class FramedQuadtreeLandmarksTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FramedQuadtreeLandmarksTest);
  CPPUNIT_TEST(distancesAreConsistentAlongEdges);
  CPPUNIT_TEST(aWalledOffPartIsUnreachable);
  CPPUNIT_TEST_SUITE_END();

 public:
  void distancesAreConsistentAlongEdges() {
    std::mt19937 rng(23);
    for (int trial = 0; trial < 6; ++trial) {
      OccupancyGrid grid(60, 45, 0.05);
      std::bernoulli_distribution blocked(0.04 * trial);
      for (int r = 0; r < 45; ++r)
        for (int c = 0; c < 60; ++c)
          if (blocked(rng)) grid.set({c, r}, Cell::Occupied);
      const FramedQuadtree tree(grid);
      const rgnav::LineOfSight lineOfSight(grid);
      const FramedQuadtreeLandmarks landmarks(tree, lineOfSight);
      std::size_t zeros = 0;
      for (std::int32_t u = 0; u < static_cast<std::int32_t>(tree.nodeCount()); ++u) {
        const rgnav::CellIndex cu = tree.nodeCell(u);
        for (std::size_t l = 0; l < FramedQuadtreeLandmarks::kCount; ++l) zeros += landmarks.of(u)[l] == 0.0 ? 1 : 0;
        tree.forEachNeighbour(u, [&](std::int32_t n) {
          const rgnav::CellIndex cn = tree.nodeCell(n);
          const double edge = std::hypot(cu.col - cn.col, cu.row - cn.row);
          CPPUNIT_ASSERT(FramedQuadtreeLandmarks::lowerBound(landmarks.of(u), landmarks.of(n)) <= edge * (1 + 1e-12));
        });
      }
      CPPUNIT_ASSERT_EQUAL(FramedQuadtreeLandmarks::kCount, zeros);
    }
  }

  void aWalledOffPartIsUnreachable() {
    OccupancyGrid grid(40, 20, 0.05);
    for (int r = 0; r < 20; ++r) grid.set({30, r}, Cell::Occupied);
    const FramedQuadtree tree(grid);
    const rgnav::LineOfSight lineOfSight(grid);
    const FramedQuadtreeLandmarks landmarks(tree, lineOfSight);
    for (std::int32_t u = 0; u < static_cast<std::int32_t>(tree.nodeCount()); ++u) {
      const bool beyond = tree.nodeCell(u).col > 30;
      for (std::size_t l = 0; l < FramedQuadtreeLandmarks::kCount; ++l)
        CPPUNIT_ASSERT_EQUAL(beyond, landmarks.of(u)[l] == FramedQuadtreeLandmarks::kUnreachable);
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FramedQuadtreeLandmarksTest);
