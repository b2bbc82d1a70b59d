// Tests the conversion of tracked VLM sequences into classifier input: distances and weight
// vectors keep their order, and a sequence with mismatched sizes is rejected.
#include "core/gateways/vlm/TrackedObservations.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"

class TrackedObservationsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TrackedObservationsTest);
  CPPUNIT_TEST(keepsDistancesAndWeightsInOrder);
  CPPUNIT_TEST(rejectsMismatchedSizes);
  CPPUNIT_TEST_SUITE_END();

 public:
  void keepsDistancesAndWeightsInOrder() {
    rgnav::TrackedSequence tracked;
    tracked.distances = {4.0, 3.5};
    tracked.observations = {{0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}};
    const rgnav::GatewayObservationSequence s = rgnav::toObservationSequence(tracked);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, s.size());
    CPPUNIT_ASSERT_EQUAL(4.0, s[0].distance);
    CPPUNIT_ASSERT_EQUAL(3.5, s[1].distance);
    CPPUNIT_ASSERT_EQUAL(Eigen::Index{3}, s[1].weights.size());
    CPPUNIT_ASSERT_EQUAL(0.2, s[0].weights[1]);
    CPPUNIT_ASSERT_EQUAL(0.6, s[1].weights[2]);
  }

  void rejectsMismatchedSizes() {
    rgnav::TrackedSequence tracked;
    tracked.distances = {4.0, 3.5};
    tracked.observations = {{0.1, 0.2, 0.3}};
    CPPUNIT_ASSERT_THROW(rgnav::toObservationSequence(tracked), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TrackedObservationsTest);
