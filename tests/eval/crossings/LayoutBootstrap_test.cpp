// Tests the cluster bootstrap of LayoutBootstrap.h: no spread when every test gateway of a group
// has the group's rate, the spread one all-wrong gateway brings, the lowest group deciding,
// reproducibility from the seed, and the rejected inputs.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "tests/eval/crossings/LayoutBootstrap.h"

using rgnav::bootstrapLowestRate;
using rgnav::GatewayTally;
using rgnav::RateInterval;

namespace {

// Ten gateways decided all right and one decided all wrong, 12 sequences each: rate 10/11.
std::vector<GatewayTally> oneBadGateway() {
  std::vector<GatewayTally> group(10, GatewayTally{12, 12});
  group.push_back({0, 12});
  return group;
}

class LayoutBootstrapTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LayoutBootstrapTest);
  CPPUNIT_TEST(equalGatewaysLeaveNoSpread);
  CPPUNIT_TEST(oneBadGatewaySpreadsTheRate);
  CPPUNIT_TEST(isReproducibleFromTheSeed);
  CPPUNIT_TEST(rejectsInvalidInput);
  CPPUNIT_TEST_SUITE_END();

 public:
  void equalGatewaysLeaveNoSpread() {
    // Rates 0.9 and 0.7 in every gateway of their group: every resample gives 0.7.
    const RateInterval interval = bootstrapLowestRate({{{9, 10}, {18, 20}}, {{7, 10}, {14, 20}}}, 500, 0.9, 1);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.7, interval.low, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.7, interval.high, 1e-12);
  }

  void oneBadGatewaySpreadsTheRate() {
    // The number of bad gateways in a resample of 11 is Binomial(11, 1/11): none with
    // probability 0.35 (rate 1), three or more with 0.072 and four or more with 0.014, so the
    // 5 % quantile is three bad gateways (8/11) and the 95 % quantile no bad one.
    const RateInterval interval = bootstrapLowestRate({oneBadGateway()}, 4000, 0.9, 7);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(8.0 / 11.0, interval.low, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, interval.high, 1e-12);
    // A second group that is always perfect does not raise the lowest rate.
    const RateInterval withPerfect =
        bootstrapLowestRate({oneBadGateway(), std::vector<GatewayTally>(5, GatewayTally{3, 3})}, 4000, 0.9, 7);
    CPPUNIT_ASSERT(withPerfect.low <= 9.0 / 11.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, withPerfect.high, 1e-12);
  }

  void isReproducibleFromTheSeed() {
    const RateInterval a = bootstrapLowestRate({oneBadGateway()}, 200, 0.8, 3);
    const RateInterval b = bootstrapLowestRate({oneBadGateway()}, 200, 0.8, 3);
    CPPUNIT_ASSERT_EQUAL(a.low, b.low);
    CPPUNIT_ASSERT_EQUAL(a.high, b.high);
  }

  void rejectsInvalidInput() {
    CPPUNIT_ASSERT_THROW(bootstrapLowestRate({}, 10, 0.9, 1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(bootstrapLowestRate({{}}, 10, 0.9, 1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(bootstrapLowestRate({{{0, 0}}}, 10, 0.9, 1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(bootstrapLowestRate({{{3, 2}}}, 10, 0.9, 1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(bootstrapLowestRate({{{1, 2}}}, 0, 0.9, 1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(bootstrapLowestRate({{{1, 2}}}, 10, 1.0, 1), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LayoutBootstrapTest);

}  // namespace
