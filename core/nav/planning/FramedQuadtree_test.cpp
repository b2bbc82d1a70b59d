// Tests the framed-quadtree decomposition: on random grids the quads cover exactly the free cells,
// are disjoint, free and inside the grid, and the graph nodes are exactly the frame cells of the
// quads with contiguous ids per quad, and its components are those of a flood fill over the free
// cells (8 neighbours, no diagonal squeeze between two blocked cells); a free power-of-two grid is
// one quad, a blocked cell splits it.
#include <cppunit/extensions/HelperMacros.h>

#include <cstdlib>
#include <map>
#include <random>
#include <set>

#include "core/nav/planning/testing/RandomGrids.h"
#include "core/nav/planning/FramedQuadtree.h"

using rgnav::Cell;
using rgnav::CellIndex;
using rgnav::FramedQuadtree;
using rgnav::OccupancyGrid;
using rgnav::testing::randomGrid;

namespace {

bool onFrame(const FramedQuadtree::Quad& q, CellIndex c) {
  return c.col == q.col || c.row == q.row || c.col == q.col + q.size - 1 || c.row == q.row + q.size - 1;
}

}  // namespace

class FramedQuadtreeTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FramedQuadtreeTest);
  CPPUNIT_TEST(quadsCoverExactlyTheFreeCells);
  CPPUNIT_TEST(nodesAreTheFramesOfTheQuads);
  CPPUNIT_TEST(neighboursAreSymmetricAndAdjacent);
  CPPUNIT_TEST(aFreeSquareIsOneFramedQuad);
  CPPUNIT_TEST(aBlockedCellSplitsTheSquare);
  CPPUNIT_TEST(componentsAreThoseOfAFloodFill);
  CPPUNIT_TEST_SUITE_END();

 public:
  void quadsCoverExactlyTheFreeCells() {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 30; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 5 + trial * 3, 40 - trial, trial % 3 == 0 ? 0.02 : 0.25);
      const FramedQuadtree tree(grid);
      std::vector<int> covered(grid.cells().size(), 0);
      for (std::size_t q = 0; q < tree.quads().size(); ++q) {
        const FramedQuadtree::Quad& quad = tree.quads()[q];
        for (int r = quad.row; r < quad.row + quad.size; ++r)
          for (int c = quad.col; c < quad.col + quad.size; ++c) {
            CPPUNIT_ASSERT(grid.contains({c, r}));
            CPPUNIT_ASSERT(!grid.blocked({c, r}));
            CPPUNIT_ASSERT_EQUAL(static_cast<std::int32_t>(q), tree.quadOf({c, r}));
            ++covered[static_cast<std::size_t>(r) * grid.width() + c];
          }
      }
      std::size_t free = 0;
      for (int r = 0; r < grid.height(); ++r)
        for (int c = 0; c < grid.width(); ++c) {
          const bool isFree = !grid.blocked({c, r});
          free += isFree ? 1 : 0;
          CPPUNIT_ASSERT_EQUAL(isFree ? 1 : 0, covered[static_cast<std::size_t>(r) * grid.width() + c]);
          if (!isFree) CPPUNIT_ASSERT_EQUAL(FramedQuadtree::kNone, tree.quadOf({c, r}));
        }
      CPPUNIT_ASSERT_EQUAL(free, tree.freeCellCount());
    }
  }

  void nodesAreTheFramesOfTheQuads() {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 20; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 37, 29, 0.03 * trial);
      const FramedQuadtree tree(grid);
      std::size_t expected = 0;
      for (std::size_t q = 0; q < tree.quads().size(); ++q) {
        const FramedQuadtree::Quad& quad = tree.quads()[q];
        CPPUNIT_ASSERT_EQUAL(quad.size == 1 ? 1 : 4 * quad.size - 4, quad.nodeCount);
        expected += static_cast<std::size_t>(quad.nodeCount);
        for (std::int32_t n = quad.firstNode; n < quad.firstNode + quad.nodeCount; ++n) {
          CPPUNIT_ASSERT_EQUAL(static_cast<std::int32_t>(q), tree.nodeQuad(n));
          CPPUNIT_ASSERT(onFrame(quad, tree.nodeCell(n)));
          CPPUNIT_ASSERT_EQUAL(n, tree.nodeOf(tree.nodeCell(n)));
        }
        for (int r = quad.row; r < quad.row + quad.size; ++r)
          for (int c = quad.col; c < quad.col + quad.size; ++c)
            CPPUNIT_ASSERT_EQUAL(onFrame(quad, {c, r}), tree.nodeOf({c, r}) != FramedQuadtree::kNone);
      }
      CPPUNIT_ASSERT_EQUAL(expected, tree.nodeCount());
    }
  }

  // Cell neighbours are the 8-adjacent frame cells of other quads, diagonal ones unless both cells
  // beside the step are blocked; frame neighbours the rest of the same frame; each link both ways.
  void neighboursAreSymmetricAndAdjacent() {
    std::mt19937 rng(13);
    const OccupancyGrid grid = randomGrid(rng, 33, 27, 0.3);
    const FramedQuadtree tree(grid);
    std::set<std::pair<std::int32_t, std::int32_t>> links;
    std::size_t diagonals = 0;
    for (std::int32_t u = 0; u < static_cast<std::int32_t>(tree.nodeCount()); ++u) {
      const CellIndex cu = tree.nodeCell(u);
      tree.forEachNeighbour(u, [&](std::int32_t n) { CPPUNIT_ASSERT(links.insert({u, n}).second); });
      tree.forEachCellNeighbour(u, [&](std::int32_t n) {
        const CellIndex cn = tree.nodeCell(n);
        CPPUNIT_ASSERT(tree.nodeQuad(n) != tree.nodeQuad(u));
        CPPUNIT_ASSERT(std::max(std::abs(cn.col - cu.col), std::abs(cn.row - cu.row)) == 1);
        if (cn.col != cu.col && cn.row != cu.row) {
          ++diagonals;
          CPPUNIT_ASSERT(!grid.blocked({cn.col, cu.row}) || !grid.blocked({cu.col, cn.row}));
        }
      });
      tree.forEachFrameNeighbour(u, [&](std::int32_t n) { CPPUNIT_ASSERT_EQUAL(tree.nodeQuad(u), tree.nodeQuad(n)); });
    }
    for (const auto& [u, n] : links) CPPUNIT_ASSERT(links.count({n, u}) == 1);
    // Every free 8-adjacent pair in different quads is linked unless the diagonal squeezes.
    for (int r = 0; r < grid.height(); ++r)
      for (int c = 0; c < grid.width(); ++c)
        for (const auto& [dc, dr] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}, std::pair{1, -1}}) {
          const std::int32_t u = tree.nodeOf({c, r}), n = tree.nodeOf({c + dc, r + dr});
          if (u == FramedQuadtree::kNone || n == FramedQuadtree::kNone || tree.nodeQuad(u) == tree.nodeQuad(n)) continue;
          const bool squeezed = dc != 0 && dr != 0 && grid.blocked({c + dc, r}) && grid.blocked({c, r + dr});
          CPPUNIT_ASSERT_EQUAL(!squeezed, links.count({u, n}) == 1);
        }
    CPPUNIT_ASSERT(diagonals > 100);
  }

  void aFreeSquareIsOneFramedQuad() {
    const FramedQuadtree tree(OccupancyGrid(16, 16, 0.05));
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, tree.quads().size());
    CPPUNIT_ASSERT_EQUAL(16, tree.quads()[0].size);
    CPPUNIT_ASSERT_EQUAL(std::size_t{60}, tree.nodeCount());
    CPPUNIT_ASSERT_EQUAL(FramedQuadtree::kNone, tree.nodeOf({5, 7}));
  }

  void aBlockedCellSplitsTheSquare() {
    OccupancyGrid grid(8, 8, 0.05);
    grid.set({0, 0}, Cell::Occupied);
    const FramedQuadtree tree(grid);
    // Three 4x4 quads, and the lower-left 4x4 as three 2x2 and three 1x1 quads.
    CPPUNIT_ASSERT_EQUAL(std::size_t{9}, tree.quads().size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{3 * 12 + 3 * 4 + 3}, tree.nodeCount());
    CPPUNIT_ASSERT_EQUAL(FramedQuadtree::kNone, tree.quadOf({0, 0}));
    CPPUNIT_ASSERT_EQUAL(4, tree.quads()[static_cast<std::size_t>(tree.quadOf({7, 7}))].size);
  }

  void componentsAreThoseOfAFloodFill() {
    std::mt19937 rng(11);
    std::size_t split = 0;
    for (int trial = 0; trial < 30; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 10 + trial, 30 - trial / 2, 0.2 + 0.01 * trial);
      const FramedQuadtree tree(grid);
      const std::vector<int> fill = floodFill(grid);
      std::map<int, std::int32_t> toComponent;
      std::set<std::int32_t> components;
      for (int r = 0; r < grid.height(); ++r)
        for (int c = 0; c < grid.width(); ++c) {
          const std::int32_t component = tree.componentOf({c, r});
          if (grid.blocked({c, r})) {
            CPPUNIT_ASSERT_EQUAL(FramedQuadtree::kNone, component);
            continue;
          }
          const int label = fill[static_cast<std::size_t>(r * grid.width() + c)];
          const auto [it, added] = toComponent.emplace(label, component);
          CPPUNIT_ASSERT_EQUAL(it->second, component);                        // one fill part, one component
          CPPUNIT_ASSERT(!added || components.insert(component).second);  // and the other way round
        }
      split += components.size();
    }
    CPPUNIT_ASSERT(split > 60);  // the grids fall apart into many components
  }

 private:
  // Labels per cell (-1 blocked): the parts of the free cells joined by steps to the 8 neighbours,
  // a diagonal step not between two blocked cells.
  static std::vector<int> floodFill(const OccupancyGrid& grid) {
    std::vector<int> label(static_cast<std::size_t>(grid.width() * grid.height()), -1);
    const auto at = [&](CellIndex c) -> int& { return label[static_cast<std::size_t>(c.row * grid.width() + c.col)]; };
    int next = 0;
    for (int r = 0; r < grid.height(); ++r)
      for (int c = 0; c < grid.width(); ++c) {
        if (grid.blocked({c, r}) || at({c, r}) >= 0) continue;
        std::vector<CellIndex> pending{{c, r}};
        at({c, r}) = next;
        while (!pending.empty()) {
          const CellIndex u = pending.back();
          pending.pop_back();
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const CellIndex v{u.col + dx, u.row + dy};
              if (grid.blocked(v) || at(v) >= 0) continue;
              if (dx != 0 && dy != 0 && grid.blocked({u.col + dx, u.row}) && grid.blocked({u.col, u.row + dy})) continue;
              at(v) = next;
              pending.push_back(v);
            }
        }
        ++next;
      }
    return label;
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FramedQuadtreeTest);
