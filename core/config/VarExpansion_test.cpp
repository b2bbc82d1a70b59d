// Tests ${VAR} expansion: replacement, literal dollars, and each error.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/config/VarExpansion.h"

using rgnav::ConfigError;
using rgnav::expandVariables;

class VarExpansionTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(VarExpansionTest);
  CPPUNIT_TEST(replacesEveryReference);
  CPPUNIT_TEST(keepsDollarWithoutBrace);
  CPPUNIT_TEST(rejectsUnknownVariable);
  CPPUNIT_TEST(rejectsBadNameAndMissingBrace);
  CPPUNIT_TEST_SUITE_END();

  const rgnav::ConfigVars vars{{"RGNAV_BIN", "/opt/bin"}, {"X", "1"}};

 public:
  void replacesEveryReference() {
    CPPUNIT_ASSERT_EQUAL(std::string("/opt/bin/a-1-1"), expandVariables("${RGNAV_BIN}/a-${X}-${X}", vars));
    CPPUNIT_ASSERT_EQUAL(std::string("plain"), expandVariables("plain", vars));
  }
  void keepsDollarWithoutBrace() {
    CPPUNIT_ASSERT_EQUAL(std::string("cost $5 $"), expandVariables("cost $5 $", vars));
  }
  void rejectsUnknownVariable() {
    try {
      expandVariables("${HOME}/x", vars);
      CPPUNIT_FAIL("expected ConfigError");
    } catch (const ConfigError& e) {
      CPPUNIT_ASSERT(std::string(e.what()).find("unknown variable ${HOME}") != std::string::npos);
    }
  }
  void rejectsBadNameAndMissingBrace() {
    CPPUNIT_ASSERT_THROW(expandVariables("${1A}", vars), ConfigError);
    CPPUNIT_ASSERT_THROW(expandVariables("${}", vars), ConfigError);
    CPPUNIT_ASSERT_THROW(expandVariables("${X", vars), ConfigError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(VarExpansionTest);
