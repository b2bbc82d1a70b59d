// Every file the project ships under config/ is loaded by its loader (found by walking the
// folder, so a new file is covered; a file no loader takes fails), and the module parameter files
// (config/modules) hold exactly the code's defaults, read back exactly what is written, and name
// the file, key path and line in every error.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>

#include "core/common/Errors.h"
#include "core/config/DescribedConfig.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"
#include "core/nav/avoidance/CollisionAvoidanceConfigYaml.h"
#include "core/nav/localization/MclConfigYaml.h"
#include "core/nav/motion/LowLevelDriveConfigYaml.h"
#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "core/nav/tasks/HighLevelPlanningConfigYaml.h"
#include "core/rgmap/kernel/RgMappingKernelConfigYaml.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/SimulationConfigYaml.h"
#include "core/slam/SlamConfigYaml.h"
#include "core/supervision/SetConfig.h"
#include "tests/eval/split/IpaSplit.h"
#include "tools/demo/DemoScript.h"

namespace fs = std::filesystem;
using namespace rgnav;

namespace {

// A module file's complete text as the writer gives it for the loaded values: equal texts are
// equal values (each number is written with the digits that read back to exactly it).
struct ModuleFile {
  std::function<std::string(const std::string& file)> loadedYaml;
  std::function<std::string(const std::string& yamlText)> parsedYaml;
  std::string defaultsYaml;
};

template <class Config>
ModuleFile moduleFile(Config (*parse)(const std::string&, const std::string&)) {
  return {[parse](const std::string& file) { return describedYaml(parse(readConfigFile(file), file)); },
          [parse](const std::string& text) { return describedYaml(parse(text, "defaults")); },
          describedYaml(Config{})};
}

const std::map<std::string, ModuleFile>& moduleFiles() {
  static const std::map<std::string, ModuleFile> files{
      {"scanmapper", moduleFile(&parseSlamConfig)},
      {"gatewaydetection", moduleFile(&parseGatewayDetectorConfig)},
      {"rgmappingkernel", moduleFile(&parseRgMappingKernelConfig)},
      {"pathplanning", moduleFile(&parseRoutePlannerConfig)},
      {"lowleveldrive", moduleFile(&parseLowLevelDriveConfig)},
      {"collisionavoidance", moduleFile(&parseCollisionAvoidanceConfig)},
      {"localization", moduleFile(&parseMclConfig)},
      {"highlevelplanning", moduleFile(&parseHighLevelPlanningConfig)}};
  return files;
}

// The variables the watchdog passes a set, with the project root as the working directory.
ConfigVars setVariables() {
  const std::string root = fs::absolute(".").lexically_normal().string();
  return {{"RGNAV_BIN", root + "/build/bin"}, {"RGNAV_ROOT", root}, {"RGNAV_SHARED", root + "/../shared"}};
}

// A set is loaded, and every --config file its modules are given exists.
void loadSet(const fs::path& file) {
  const SetConfig set = loadSetConfig(file.string(), setVariables(), ".");
  for (const ModuleSpec& module : set.modules)
    for (std::size_t i = 0; i + 1 < module.command.size(); ++i)
      if (module.command[i] == "--config" && !fs::is_regular_file(module.command[i + 1]))
        throw FileError(file.string() + ": module " + module.name + ": no file " + module.command[i + 1]);
}

// Loads one shipped file with the loader of its folder; false if no loader takes it.
bool loadShipped(const fs::path& file) {
  const std::string folder = file.parent_path().lexically_relative("config").string();
  const std::string extension = file.extension().string();
  if (file.filename() == "README.md") return true;
  if (folder == "modules" && extension == ".yaml") {
    const auto module = moduleFiles().find(file.stem().string());
    if (module == moduleFiles().end()) return false;
    module->second.loadedYaml(file.string());
  } else if (folder == "sim" && extension == ".yaml") {
    loadSimulationConfig(file.string());
  } else if ((folder == "sets" || folder == "sets/templates") && extension == ".yaml") {
    loadSet(file);
  } else if (folder == "worlds" && extension == ".yaml") {
    loadWorld(file.string());
  } else if (folder == "gateways" && extension == ".txt") {
    loadHmmModels(file.string());
  } else if (folder == "demo" && (file.filename() == "answers.yaml" || file.filename() == "tasks.yaml")) {
    loadDemoScript((file.parent_path() / "answers.yaml").string(), (file.parent_path() / "tasks.yaml").string());
  } else if (folder == "eval" && file.filename() == "ipa-split.yaml") {
    loadIpaSplit(file.string());
  } else {
    return false;
  }
  return true;
}

std::string shippedModuleText(const std::string& module) {
  return readConfigFile("config/modules/" + module + ".yaml");
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  CPPUNIT_ASSERT_MESSAGE(from, at != std::string::npos);
  return text.replace(at, from.size(), to);
}

void expectConfigError(const std::string& text, const std::string& expected) {
  try {
    parseSlamConfig(text, "scanmapper.yaml");
    CPPUNIT_FAIL("expected ConfigError containing " + expected);
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    CPPUNIT_ASSERT_MESSAGE(message, message.rfind("scanmapper.yaml: " + expected, 0) == 0);
  }
}

}  // namespace

class ShippedConfigsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ShippedConfigsTest);
  CPPUNIT_TEST(loadsEveryShippedFile);
  CPPUNIT_TEST(moduleFilesHoldTheDefaults);
  CPPUNIT_TEST(writtenDefaultsReadBack);
  CPPUNIT_TEST(moduleErrorsNameFileKeyAndLine);
  CPPUNIT_TEST(loadedValuesAreValidated);
  CPPUNIT_TEST_SUITE_END();

 public:
  void loadsEveryShippedFile() {
    CPPUNIT_ASSERT_MESSAGE("run from the project root", fs::is_directory("config/modules"));
    std::size_t loaded = 0;
    for (const auto& entry : fs::recursive_directory_iterator("config")) {
      if (!entry.is_regular_file()) continue;
      try {
        CPPUNIT_ASSERT_MESSAGE("no test loads " + entry.path().string(), loadShipped(entry.path()));
      } catch (const Error& e) {
        CPPUNIT_FAIL(e.what());
      }
      ++loaded;
    }
    CPPUNIT_ASSERT(loaded >= moduleFiles().size() + 3);
  }

  void moduleFilesHoldTheDefaults() {
    for (const auto& [module, file] : moduleFiles())
      CPPUNIT_ASSERT_EQUAL_MESSAGE(module, file.defaultsYaml, file.loadedYaml("config/modules/" + module + ".yaml"));
  }

  void writtenDefaultsReadBack() {
    for (const auto& [module, file] : moduleFiles())
      CPPUNIT_ASSERT_EQUAL_MESSAGE(module, file.defaultsYaml, file.parsedYaml(file.defaultsYaml));
  }

  void moduleErrorsNameFileKeyAndLine() {
    const std::string text = shippedModuleText("scanmapper");
    const std::size_t at = text.find("resolution_m: 0.05", text.find("\nloop:"));
    CPPUNIT_ASSERT(at != std::string::npos);
    const std::string line = std::to_string(std::count(text.begin(), text.begin() + long(at), '\n') + 1);
    expectConfigError(std::string(text).replace(at, 12, "resolutoin_m"),
                      "loop.grid.resolutoin_m: unknown key (line " + line + ")");
    expectConfigError(std::string(text).replace(at, 18, ""), "loop.grid.resolution_m: missing required key");
    expectConfigError(replaced(text, "max_candidates: 3", "max_candidates: three"),
                      "loop.max_candidates: wrong type, expected an integer");
    expectConfigError(replaced(text, "loop_loss_scale: 3", "loop_loss_scale: .inf"),
                      "graph.loop_loss_scale: out of range: not a finite number");
    expectConfigError(replaced(text, "loop_loss_scale: 3", "loop_loss_scale: .nan"),
                      "graph.loop_loss_scale: out of range: not a finite number");
  }

  void loadedValuesAreValidated() {
    const std::string text = shippedModuleText("scanmapper");
    CPPUNIT_ASSERT_THROW(parseSlamConfig(replaced(text, "max_range_m: 30", "max_range_m: 0.05"), "s.yaml"),
                         ConfigError);
    CPPUNIT_ASSERT_THROW(
        parseGatewayDetectorConfig(replaced(shippedModuleText("gatewaydetection"), "hallway_width_m: 2", "hallway_width_m: 0"),
                                   "g.yaml"),
        ConfigError);
    CPPUNIT_ASSERT_THROW(
        parseRgMappingKernelConfig(replaced(shippedModuleText("rgmappingkernel"), "door_open_m: -30", "door_open_m: 1"),
                                   "k.yaml"),
        ConfigError);
    CPPUNIT_ASSERT_THROW(
        parseLowLevelDriveConfig(replaced(shippedModuleText("lowleveldrive"), "kx_per_s: 2", "kx_per_s: 0"), "l.yaml"),
        ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ShippedConfigsTest);
