// Tests the Collision Avoidance's YAML: the shipped file loads and validates, a misspelt or
// missing key and a bad value are ConfigErrors.
#include <cppunit/extensions/HelperMacros.h>

#include <fstream>
#include <sstream>
#include <string>

#include "core/common/Errors.h"
#include "core/nav/avoidance/CollisionAvoidanceConfigYaml.h"

using rgnav::ConfigError;
using rgnav::loadCollisionAvoidanceConfig;
using rgnav::parseCollisionAvoidanceConfig;

namespace {

const char* kShipped = "config/modules/collisionavoidance.yaml";

std::string shippedText() {
  std::ifstream in(kShipped);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  CPPUNIT_ASSERT(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

class CollisionAvoidanceConfigYamlTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CollisionAvoidanceConfigYamlTest);
  CPPUNIT_TEST(theShippedFileLoads);
  CPPUNIT_TEST(keysAreStrict);
  CPPUNIT_TEST(valuesAreValidated);
  CPPUNIT_TEST_SUITE_END();

 public:
  void theShippedFileLoads() {
    const rgnav::CollisionAvoidanceConfig config = loadCollisionAvoidanceConfig(kShipped);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.05, config.safetyMarginM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.05, config.obstacleMap.resolutionM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(45.0 * M_PI / 180.0, config.candidates.pivotStepRad, 1e-12);
  }

  void keysAreStrict() {
    const std::string text = shippedText();
    CPPUNIT_ASSERT_THROW(parseCollisionAvoidanceConfig(replaced(text, "safety_margin_m", "safety_margin"), "t.yaml"),
                         ConfigError);
    CPPUNIT_ASSERT_THROW(parseCollisionAvoidanceConfig(replaced(text, "  fan_count: 9\n", ""), "t.yaml"), ConfigError);
  }

  void valuesAreValidated() {
    CPPUNIT_ASSERT_THROW(
        parseCollisionAvoidanceConfig(replaced(shippedText(), "blocked_wait_s: 3", "blocked_wait_s: 0"), "t.yaml"),
        ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CollisionAvoidanceConfigYamlTest);
