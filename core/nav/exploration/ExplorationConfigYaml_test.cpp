// Tests the exploration parameters' YAML: the code's defaults written and read back exactly, the
// `exploration:` section of a larger file read alone, and typed errors for an unknown key, a
// missing one and a value out of range, naming the key.
#include <cppunit/extensions/HelperMacros.h>

#include <sstream>
#include <string>

#include "core/common/Errors.h"
#include "core/config/DescribedConfig.h"
#include "core/nav/exploration/ExplorationConfigYaml.h"

using rgnav::ConfigError;
using rgnav::ExplorationConfig;

namespace {

bool sameConfig(const ExplorationConfig& a, const ExplorationConfig& b) {
  return rgnav::describedYaml(a) == rgnav::describedYaml(b);
}

bool throwsNaming(const std::string& yaml, const std::string& key) {
  try {
    rgnav::parseExplorationConfig(yaml, "exploration.yaml");
  } catch (const ConfigError& e) {
    return std::string(e.what()).find(key) != std::string::npos;
  }
  return false;
}

}  // namespace

class ExplorationConfigYamlTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExplorationConfigYamlTest);
  CPPUNIT_TEST(defaultsReadBackExactly);
  CPPUNIT_TEST(aSectionOfALargerFile);
  CPPUNIT_TEST(badFilesAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void defaultsReadBackExactly() {
    ExplorationConfig changed;
    changed.frontier.minCells = 7;
    changed.grid.resolutionM = 0.05;
    const std::string text = rgnav::describedYaml(changed);
    CPPUNIT_ASSERT(sameConfig(changed, rgnav::parseExplorationConfig(text, "exploration.yaml")));
    CPPUNIT_ASSERT(!sameConfig(ExplorationConfig{}, changed));
  }

  void aSectionOfALargerFile() {
    std::string text = "strategy: rg\nexploration:\n";
    std::istringstream lines(rgnav::describedYaml(ExplorationConfig{}));
    for (std::string line; std::getline(lines, line);) text += "  " + line + "\n";
    const rgnav::ConfigVars none;
    const rgnav::ConfigNode root(rgnav::parseYamlDocument(text), "", none);
    CPPUNIT_ASSERT(sameConfig(ExplorationConfig{}, rgnav::explorationConfigFromYaml(root["exploration"])));
  }

  void badFilesAreTypedErrors() {
    const std::string good = rgnav::describedYaml(ExplorationConfig{});
    CPPUNIT_ASSERT(throwsNaming(good + "speed_m_s: 1\n", "speed_m_s"));
    const std::string noRadius = good.substr(0, good.find("robot_radius_m")) + good.substr(good.find("max_goal_failures"));
    CPPUNIT_ASSERT(throwsNaming(noRadius, "robot_radius_m"));
    std::string zero = good;
    zero.replace(zero.find("max_goal_failures: 2"), 20, "max_goal_failures: 0");
    CPPUNIT_ASSERT(throwsNaming(zero, "max_goal_failures"));
    CPPUNIT_ASSERT_THROW(rgnav::loadExplorationConfig("/nonexistent/exploration.yaml"), rgnav::FileError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExplorationConfigYamlTest);
