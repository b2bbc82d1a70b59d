// Tests the confusion matrix: counts, per-class recognition rates as in thesis tables 4.2/4.3,
// overall, mean and minimum accuracy, the text table and typed errors.
#include "core/gateways/classify/GatewayConfusionMatrix.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>

#include "core/common/Errors.h"

using rgnav::GatewayClass;

class GatewayConfusionMatrixTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GatewayConfusionMatrixTest);
  CPPUNIT_TEST(countsAndRates);
  CPPUNIT_TEST(textTableNamesClasses);
  CPPUNIT_TEST(typedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void countsAndRates() {
    rgnav::GatewayConfusionMatrix m({GatewayClass::LTurn, GatewayClass::RTurn, GatewayClass::TJunction});
    for (int i = 0; i < 3; ++i) m.add(GatewayClass::LTurn, GatewayClass::LTurn);
    m.add(GatewayClass::LTurn, GatewayClass::TJunction);
    m.add(GatewayClass::RTurn, GatewayClass::RTurn);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), m.count(GatewayClass::LTurn, GatewayClass::LTurn));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), m.count(GatewayClass::LTurn, GatewayClass::TJunction));
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), m.total(GatewayClass::LTurn));
    CPPUNIT_ASSERT_EQUAL(std::size_t(5), m.total());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.75, m.classAccuracy(GatewayClass::LTurn), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.8, m.accuracy(), 1e-12);
    // T-Junction has no sequences and does not count in the mean or minimum.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.875, m.meanClassAccuracy(), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.75, m.minClassAccuracy(), 1e-12);
  }

  void textTableNamesClasses() {
    rgnav::GatewayConfusionMatrix m;
    m.add(GatewayClass::XCrossing, GatewayClass::TJunction);
    const std::string text = m.toText();
    CPPUNIT_ASSERT(text.find("X-Crossing") != std::string::npos);
    CPPUNIT_ASSERT(text.find("Hallway") != std::string::npos);
    CPPUNIT_ASSERT(text.find("0.0%") != std::string::npos);
    CPPUNIT_ASSERT_EQUAL(std::size_t(9), static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')));
  }

  void typedErrors() {
    rgnav::GatewayConfusionMatrix m({GatewayClass::LTurn, GatewayClass::RTurn});
    CPPUNIT_ASSERT_THROW(m.accuracy(), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(m.minClassAccuracy(), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(m.classAccuracy(GatewayClass::LTurn), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(m.add(GatewayClass::LTurn, GatewayClass::DeadEnd), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::GatewayConfusionMatrix(std::vector<GatewayClass>{}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::GatewayConfusionMatrix({GatewayClass::LTurn, GatewayClass::LTurn}),
                         rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(GatewayConfusionMatrixTest);
