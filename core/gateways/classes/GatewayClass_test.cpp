// Tests the gateway classes of thesis 4.1: every thesis name parses back to its class, other
// names do not, and the openings of each class match figure 4.1.
#include "core/gateways/classes/GatewayClass.h"

#include <cppunit/extensions/HelperMacros.h>

#include <set>
#include <string>

#include "core/gateways/classes/GatewayClassNames.h"

class GatewayClassTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GatewayClassTest);
  CPPUNIT_TEST(everyNameParsesBackToItsClass);
  CPPUNIT_TEST(otherNamesDoNotParse);
  CPPUNIT_TEST(openingsFollowTheClass);
  CPPUNIT_TEST_SUITE_END();

 public:
  void everyNameParsesBackToItsClass() {
    std::set<std::string> names;
    for (const rgnav::GatewayClass c : rgnav::kGatewayClasses) {
      names.emplace(rgnav::gatewayClassName(c));
      CPPUNIT_ASSERT(rgnav::parseGatewayClass(rgnav::gatewayClassName(c)) == c);
    }
    CPPUNIT_ASSERT_EQUAL(rgnav::kGatewayClasses.size(), names.size());
    CPPUNIT_ASSERT(rgnav::gatewayClassName(rgnav::GatewayClass::DeadEnd) == "Deadend");
  }

  void otherNamesDoNotParse() {
    CPPUNIT_ASSERT(!rgnav::parseGatewayClass("x-crossing"));
    CPPUNIT_ASSERT(!rgnav::parseGatewayClass(""));
    CPPUNIT_ASSERT(!rgnav::parseGatewayClass("unknown"));
  }

  void openingsFollowTheClass() {
    for (const rgnav::GatewayClass c : rgnav::kGatewayClasses) {
      const rgnav::GatewayOpenings o = rgnav::openingsOf(c);
      const int sideOpenings = int{o.left} + int{o.right};
      // Transitions turn off to at least one side; the counter-classes have no side opening.
      CPPUNIT_ASSERT_EQUAL(rgnav::isTransition(c), sideOpenings > 0);
    }
    const rgnav::GatewayOpenings t = rgnav::openingsOf(rgnav::GatewayClass::TJunction);
    CPPUNIT_ASSERT(t.left && !t.straight && t.right);
    const rgnav::GatewayOpenings hallway = rgnav::openingsOf(rgnav::GatewayClass::Hallway);
    CPPUNIT_ASSERT(!hallway.left && hallway.straight && !hallway.right);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(GatewayClassTest);
