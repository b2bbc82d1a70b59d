// Tests the localization fault test's scoring of scans without a served estimate: a served
// estimate is taken as it is, a missing one is the estimate before moved on by the odometry's
// motion (in the estimate's frame, also across two missing scans in a row), and a run whose first
// scan has none is refused.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <stdexcept>

#include "tests/fault/ScanEstimates.h"

using namespace rgnav;
using namespace rgnav::testing;

class ScanEstimatesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ScanEstimatesTest);
  CPPUNIT_TEST(missingScansMoveOnByTheOdometry);
  CPPUNIT_TEST(refusesARunWithoutTheFirstEstimate);
  CPPUNIT_TEST_SUITE_END();

 public:
  void missingScansMoveOnByTheOdometry() {
    // Odometry along its x axis; the estimate of scan 1 faces +y in the map.
    const std::vector<AnchoredScan> scans{{1, {0.0, 0.0, 0.0}, {}},
                                          {2, {1.0, 0.0, 0.0}, {}},
                                          {3, {2.0, 0.0, M_PI / 2}, {}},
                                          {4, {2.0, 1.0, M_PI / 2}, {}}};
    const std::map<DataId, Pose2D> served{{1, {5.0, 5.0, M_PI / 2}}, {4, {9.0, 9.0, 0.0}}};
    const ScanEstimates e = estimatesOfEveryScan(scans, served);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), e.estimates.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), e.propagated);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, e.estimates[1].x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(6.0, e.estimates[1].y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, e.estimates[2].x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0, e.estimates[2].y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI, std::abs(e.estimates[2].theta), 1e-9);
    CPPUNIT_ASSERT(e.estimates[3] == served.at(4));
  }

  void refusesARunWithoutTheFirstEstimate() {
    const std::vector<AnchoredScan> scans{{1, {}, {}}, {2, {}, {}}};
    CPPUNIT_ASSERT_THROW(estimatesOfEveryScan(scans, {{2, {1.0, 1.0, 0.0}}}), std::runtime_error);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ScanEstimatesTest);
