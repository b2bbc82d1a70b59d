// Tests the grouping of clusters into left-right HMM states by distance interval on the
// clustering of thesis table 4.1, where the thesis obtains five states [C1 C2 C3] [C4] [C5 C6]
// [C7] [C8], and the distance summaries and overlaps it rests on.
#include "core/gateways/classify/StateGrouping.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"

using rgnav::ClusterDistances;

class StateGroupingTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(StateGroupingTest);
  CPPUNIT_TEST(table41GivesTheThesisStates);
  CPPUNIT_TEST(summariesUseQuantiles);
  CPPUNIT_TEST(overlapFractionOfTheShorterInterval);
  CPPUNIT_TEST_SUITE_END();

 public:
  void table41GivesTheThesisStates() {
    // Mean, min and max distance of clusters 1..8 of table 4.1 (mm).
    const std::vector<ClusterDistances> table = {
        {6112.0, 4854.5, 6872.2}, {5796.4, 4960.8, 6956.1}, {5770.2, 4878.0, 6976.3}, {4455.0, 3954.8, 4968.7},
        {3796.8, 3438.6, 4009.4}, {3538.3, 3037.8, 4103.6}, {2706.2, 1775.9, 3591.7}, {1755.5, 1427.9, 2310.3}};
    const std::vector<std::vector<std::size_t>> expected = {{0, 1, 2}, {3}, {4, 5}, {6}, {7}};
    CPPUNIT_ASSERT(expected == rgnav::groupByDistanceInterval(table, 0.75));
    // The input order does not matter: states follow decreasing mean distance.
    const std::vector<ClusterDistances> reversed(table.rbegin(), table.rend());
    const std::vector<std::vector<std::size_t>> expectedReversed = {{7, 6, 5}, {4}, {3, 2}, {1}, {0}};
    CPPUNIT_ASSERT(expectedReversed == rgnav::groupByDistanceInterval(reversed, 0.75));
    // Demanding full overlap keeps together only intervals inside one another (C2 in C3, C5 in C6).
    const std::vector<std::vector<std::size_t>> strict = {{0}, {1, 2}, {3}, {4, 5}, {6}, {7}};
    CPPUNIT_ASSERT(strict == rgnav::groupByDistanceInterval(table, 1.0));
  }

  void summariesUseQuantiles() {
    const ClusterDistances all = rgnav::summariseDistances({5.0, 1.0, 3.0, 2.0, 4.0}, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, all.mean, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, all.low, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, all.high, 1e-12);
    const ClusterDistances inner = rgnav::summariseDistances({5.0, 1.0, 3.0, 2.0, 4.0}, 0.1);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.4, inner.low, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.6, inner.high, 1e-12);
    CPPUNIT_ASSERT_THROW(rgnav::summariseDistances({}, 0.1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::summariseDistances({1.0}, 0.6), rgnav::InvalidArgumentError);
  }

  void overlapFractionOfTheShorterInterval() {
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, rgnav::overlapFraction({0.0, 1.0, 2.0}, {0.0, 3.0, 4.0}), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, rgnav::overlapFraction({0.0, 1.0, 5.0}, {0.0, 2.0, 3.0}), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, rgnav::overlapFraction({0.0, 1.0, 3.0}, {0.0, 2.0, 6.0}), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, rgnav::overlapFraction({0.0, 2.0, 2.0}, {0.0, 1.0, 3.0}), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, rgnav::overlapFraction({0.0, 4.0, 4.0}, {0.0, 1.0, 3.0}), 1e-12);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(StateGroupingTest);
