// Tests the multi-resolution correlative search: every pyramid level is the exact maximum of the
// fine cells it covers (so it bounds the score), and branch and bound finds the same best score
// as scoring the whole lattice exhaustively.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <random>

#include "core/slam/CorrelativeSearch.h"
#include "core/slam/ReferenceMap.h"
#include "core/slam/ScanPoints.h"
#include "core/slam/testing/SyntheticWorld.h"

using rgnav::Pose2D;

namespace {

// The sum of fine likelihoods of `query` placed at `pose`, as the search scores a lattice pose.
long latticeScore(const rgnav::PointGrid& grid, const std::vector<Eigen::Vector2f>& query, const Pose2D& pose) {
  long sum = 0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (const auto& q : query) {
    const auto cell = grid.cellOf({pose.x + c * q.x() - s * q.y(), pose.y + s * q.x() + c * q.y()});
    sum += grid.likelihood(cell.x(), cell.y());
  }
  return sum;
}

}  // namespace

class CorrelativeSearchTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CorrelativeSearchTest);
  CPPUNIT_TEST(pyramidLevelsAreExactMaxima);
  CPPUNIT_TEST(branchAndBoundEqualsExhaustiveSearch);
  CPPUNIT_TEST_SUITE_END();

 public:
  void pyramidLevelsAreExactMaxima() {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < 60; ++i) points.emplace_back(coordinate(random), coordinate(random));
    rgnav::PointGrid grid(rgnav::GridConfig{});
    grid.build(points);
    rgnav::LikelihoodPyramid pyramid;
    pyramid.build(grid, 5);
    for (int level = 0; level < 5; ++level) {
      const int size = 1 << level;
      for (int cy = -size; cy < grid.height() + 2; cy += 3)
        for (int cx = -size; cx < grid.width() + 2; cx += 3) {
          int expected = 0;
          for (int y = cy; y < cy + size; ++y)
            for (int x = cx; x < cx + size; ++x) expected = std::max<int>(expected, grid.likelihood(x, y));
          CPPUNIT_ASSERT_EQUAL(expected, static_cast<int>(pyramid.value(level, cx, cy)));
        }
    }
  }
  void branchAndBoundEqualsExhaustiveSearch() {
    const rgnav::SlamConfig config;
    const auto world = rgnav::testing::boxWorld();
    const Pose2D from{-1.0, 0.5, 0.3};
    const auto referencePoints = rgnav::scanToPoints(rgnav::testing::simulateScan(world, from), config.points);
    rgnav::ReferenceMap reference(config.local.grid, rgnav::pyramidLevelsFor(0.3, config.local.grid.resolution));
    reference.add(referencePoints, rgnav::estimateNormals(referencePoints, config.points), from);
    reference.build();
    const auto query = rgnav::scanToPoints(rgnav::testing::simulateScan(world, {-0.8, 0.4, 0.35}), config.points);
    const rgnav::SearchWindow window{0.3, 0.1};
    const auto match = rgnav::correlativeSearch(reference.grid(), reference.pyramid(), query, from, window, 0.0);
    CPPUNIT_ASSERT(match.has_value());

    const double resolution = reference.grid().resolution();
    const double step = rgnav::angularStep(query, resolution);
    const int angles = static_cast<int>(std::ceil(window.rotation / step));
    const int cells = static_cast<int>(std::ceil(window.translation / resolution));
    long best = 0;
    for (int k = -angles; k <= angles; ++k)
      for (int dx = -cells; dx <= cells; ++dx)
        for (int dy = -cells; dy <= cells; ++dy)
          best = std::max(best, latticeScore(reference.grid(), query,
                                             {from.x + dx * resolution, from.y + dy * resolution, from.theta + k * step}));
    CPPUNIT_ASSERT_EQUAL(best, latticeScore(reference.grid(), query, match->pose));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(static_cast<double>(best) / (255.0 * query.size()), match->score, 1e-12);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CorrelativeSearchTest);
