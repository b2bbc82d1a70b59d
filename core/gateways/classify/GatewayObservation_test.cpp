// Tests observation sequences: building them from plain vectors, the checks every classifier
// applies, and the matrix view the HMMs read.
#include "core/gateways/classify/GatewayObservation.h"

#include <cppunit/extensions/HelperMacros.h>

#include <limits>

#include "core/common/Errors.h"

using rgnav::GatewayObservationSequence;

class GatewayObservationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GatewayObservationTest);
  CPPUNIT_TEST(buildsSequencesFromPlainVectors);
  CPPUNIT_TEST(checksEveryObservation);
  CPPUNIT_TEST_SUITE_END();

 public:
  void buildsSequencesFromPlainVectors() {
    const GatewayObservationSequence s = rgnav::makeObservationSequence({3.0, 2.5}, {{0.1, 0.2}, {0.3, 0.4}});
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.size());
    CPPUNIT_ASSERT_EQUAL(2.5, s[1].distance);
    const Eigen::MatrixXd m = rgnav::weightMatrix(s, 2);
    CPPUNIT_ASSERT(m == (Eigen::MatrixXd(2, 2) << 0.1, 0.3, 0.2, 0.4).finished());
    CPPUNIT_ASSERT_THROW(rgnav::makeObservationSequence({3.0}, {}), rgnav::InvalidArgumentError);
  }

  void checksEveryObservation() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CPPUNIT_ASSERT_THROW(rgnav::checkSequence({}, 2), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::checkSequence(rgnav::makeObservationSequence({1.0}, {{0.1}}), 2),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::checkSequence(rgnav::makeObservationSequence({1.0}, {{0.1, nan}}), 2),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::checkSequence(rgnav::makeObservationSequence({nan}, {{0.1, 0.2}}), 2),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::checkSequence(rgnav::makeObservationSequence({-0.1}, {{0.1, 0.2}}), 2),
                         rgnav::InvalidArgumentError);
    rgnav::checkSequence(rgnav::makeObservationSequence({0.0, 1.0}, {{0.1, 0.2}, {0.0, 1.0}}), 2);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(GatewayObservationTest);
