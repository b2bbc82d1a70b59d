// Tests server-set parsing: the full schema, defaults, and every class of config error with the
// key path it must name. Also loads every shipped set in config/sets.
#include <cppunit/extensions/HelperMacros.h>

#include <filesystem>

#include "core/common/Errors.h"
#include "core/supervision/SetConfig.h"

using namespace std::chrono_literals;
using rgnav::ConfigError;
using rgnav::RestartPolicy;
using rgnav::SetConfig;

namespace {

const rgnav::ConfigVars kVars{{"RGNAV_BIN", "/opt/rgnav/bin"}, {"RGNAV_ROOT", "/opt/rgnav"},
                              {"RGNAV_SHARED", "/opt/shared"}};

// Three modules, so that tests can break modules[2].
const std::string kSet = R"(
robot: b21
host: 10.0.0.5
naming: {host: 10.0.0.5, port: 12809}
run_dir: run/intel
watchdog: {port: 12810, heartbeat_period_s: 0.5, heartbeat_timeout_s: 0.4, hang_misses: 3}
defaults: {restart: transient, max_restarts: 5, restart_window_s: 30, backoff_initial_s: 0.1,
           backoff_max_s: 1.5, start_timeout_s: 8, stop_timeout_s: 2}
modules:
  - name: LogPlayback
    command: ["${RGNAV_BIN}/rgnav-carmen-playback", "--log", "${RGNAV_SHARED}/intel.log"]
    port: 12811
    objects: [Laser, Base]
    env: {OMNIORB_TRACE: "0", DATA: "${RGNAV_SHARED}"}
  - name: ScanMapper
    command: ["${RGNAV_BIN}/rgnav-scanmapper"]
    port: 12812
    objects: [ScanMapper]
    after: [LogPlayback]
    restart: permanent
    max_restarts: 2
  - name: Kernel
    command: ["${RGNAV_BIN}/rgnav-kernel"]
    port: 12813
    objects: [RGMappingKernel]
    after: [ScanMapper]
)";

SetConfig parse(const std::string& text) { return rgnav::parseSetConfig(text, "intel", kVars, "/base"); }

// kSet with the first occurrence of `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = kSet;
  const std::size_t at = text.find(from);
  CPPUNIT_ASSERT_MESSAGE("test text not found: " + from, at != std::string::npos);
  return text.replace(at, from.size(), to);
}

void expectConfigError(const std::string& text, const std::string& fragment) {
  try {
    parse(text);
  } catch (const ConfigError& e) {
    CPPUNIT_ASSERT_MESSAGE(std::string("message \"") + e.what() + "\" lacks \"" + fragment + "\"",
                           std::string(e.what()).find(fragment) != std::string::npos);
    return;
  }
  CPPUNIT_FAIL("expected ConfigError containing \"" + fragment + "\"");
}

}  // namespace

class SetConfigTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SetConfigTest);
  CPPUNIT_TEST(parsesEveryField);
  CPPUNIT_TEST(moduleKeysOverrideDefaults);
  CPPUNIT_TEST(appliesBuiltInDefaults);
  CPPUNIT_TEST(loadsFileNamedAfterSet);
  CPPUNIT_TEST(loadErrorsNameTheFile);
  CPPUNIT_TEST(loadsEveryShippedSet);
  CPPUNIT_TEST(rejectsUnknownKey);
  CPPUNIT_TEST(rejectsMissingKey);
  CPPUNIT_TEST(rejectsWrongType);
  CPPUNIT_TEST(rejectsOutOfRange);
  CPPUNIT_TEST(rejectsEmptyLists);
  CPPUNIT_TEST(rejectsDuplicateName);
  CPPUNIT_TEST(rejectsDuplicatePort);
  CPPUNIT_TEST(rejectsDuplicateObject);
  CPPUNIT_TEST(rejectsUnknownAfter);
  CPPUNIT_TEST(rejectsCycle);
  CPPUNIT_TEST(rejectsUnknownVariable);
  CPPUNIT_TEST(rejectsYamlSyntaxError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void parsesEveryField() {
    const SetConfig set = parse(kSet);
    CPPUNIT_ASSERT_EQUAL(std::string("intel"), set.name);
    CPPUNIT_ASSERT_EQUAL(std::string("b21"), set.robot);
    CPPUNIT_ASSERT_EQUAL(std::string("10.0.0.5"), set.host);
    CPPUNIT_ASSERT_EQUAL(std::string("/base/run/intel"), set.runDir);
    CPPUNIT_ASSERT_EQUAL(12809, set.naming.port);
    CPPUNIT_ASSERT(set.naming.managed);
    CPPUNIT_ASSERT_EQUAL(12810, set.watchdog.port);
    CPPUNIT_ASSERT(set.watchdog.heartbeatPeriod == 500ms);
    CPPUNIT_ASSERT(set.watchdog.heartbeatTimeout == 400ms);
    CPPUNIT_ASSERT_EQUAL(3, set.watchdog.hangMisses);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), set.modules.size());
    const rgnav::ModuleSpec& playback = set.modules[0];
    CPPUNIT_ASSERT_EQUAL(std::string("LogPlayback"), playback.name);
    const std::vector<std::string> command{"/opt/rgnav/bin/rgnav-carmen-playback", "--log", "/opt/shared/intel.log"};
    CPPUNIT_ASSERT(command == playback.command);
    CPPUNIT_ASSERT_EQUAL(12811, playback.port);
    CPPUNIT_ASSERT(std::vector<std::string>({"Laser", "Base"}) == playback.objects);
    CPPUNIT_ASSERT(playback.after.empty());
    CPPUNIT_ASSERT_EQUAL(std::string("0"), playback.env.at("OMNIORB_TRACE"));
    CPPUNIT_ASSERT_EQUAL(std::string("/opt/shared"), playback.env.at("DATA"));
    CPPUNIT_ASSERT(std::vector<std::string>{"ScanMapper"} == set.modules[2].after);
  }
  void moduleKeysOverrideDefaults() {
    const SetConfig set = parse(kSet);
    const rgnav::ModulePolicy& inherited = set.modules[0].policy;
    CPPUNIT_ASSERT(inherited.restart == RestartPolicy::Transient);
    CPPUNIT_ASSERT_EQUAL(5, inherited.maxRestarts);
    CPPUNIT_ASSERT(inherited.restartWindow == 30s);
    CPPUNIT_ASSERT(inherited.backoffInitial == 100ms);
    CPPUNIT_ASSERT(inherited.backoffMax == 1500ms);
    CPPUNIT_ASSERT(inherited.startTimeout == 8s);
    CPPUNIT_ASSERT(inherited.stopTimeout == 2s);
    const rgnav::ModulePolicy& own = set.modules[1].policy;
    CPPUNIT_ASSERT(own.restart == RestartPolicy::Permanent);
    CPPUNIT_ASSERT_EQUAL(2, own.maxRestarts);
    CPPUNIT_ASSERT(own.restartWindow == 30s);
  }
  void appliesBuiltInDefaults() {
    const SetConfig set = parse(R"(
host: 127.0.0.1
naming: {host: 127.0.0.1, port: 12809, managed: false}
watchdog: {port: 12809}
modules: [{name: A, command: [a], port: 12811, objects: [A]}]
)");
    CPPUNIT_ASSERT_EQUAL(std::string("tumbot"), set.robot);
    CPPUNIT_ASSERT_EQUAL(std::string("/base/run/intel"), set.runDir);
    CPPUNIT_ASSERT(!set.naming.managed);
    CPPUNIT_ASSERT(set.watchdog.heartbeatPeriod == 100ms);
    CPPUNIT_ASSERT(set.watchdog.heartbeatTimeout == 250ms);
    CPPUNIT_ASSERT_EQUAL(2, set.watchdog.hangMisses);
    const rgnav::ModulePolicy& p = set.modules[0].policy;
    CPPUNIT_ASSERT(p.restart == RestartPolicy::Permanent);
    CPPUNIT_ASSERT_EQUAL(10, p.maxRestarts);
    CPPUNIT_ASSERT(p.restartWindow == 60s);
    CPPUNIT_ASSERT(p.backoffInitial == 50ms);
    CPPUNIT_ASSERT(p.backoffMax == 2s);
    CPPUNIT_ASSERT(p.startTimeout == 10s);
    CPPUNIT_ASSERT(p.stopTimeout == 3s);
  }
  void loadsFileNamedAfterSet() {
    const SetConfig set = rgnav::loadSetConfig("core/supervision/testdata/two_modules.yaml", kVars, "/base");
    CPPUNIT_ASSERT_EQUAL(std::string("two_modules"), set.name);
    CPPUNIT_ASSERT_EQUAL(std::string("/base/run/two_modules"), set.runDir);
    CPPUNIT_ASSERT_EQUAL(std::string("/opt/rgnav/bin/rgnav-scanmapper"), set.modules[0].command[0]);
  }
  void loadErrorsNameTheFile() {
    CPPUNIT_ASSERT_THROW(rgnav::loadSetConfig("core/supervision/testdata/none.yaml", kVars, "/base"),
                         rgnav::FileError);
    try {
      rgnav::loadSetConfig("core/supervision/testdata/two_modules.yaml", {}, "/base");
      CPPUNIT_FAIL("expected ConfigError");
    } catch (const ConfigError& e) {
      const std::string message = e.what();
      CPPUNIT_ASSERT_MESSAGE(message, message.find("two_modules.yaml: modules[0].command[0]: unknown variable "
                                                   "${RGNAV_BIN} (line 7)") != std::string::npos);
    }
  }
  // Every set the project ships must load (Cartographer's rule); the watchdog passes these vars.
  void loadsEveryShippedSet() {
    if (!std::filesystem::is_directory("config/sets")) return;
    for (const auto& entry : std::filesystem::directory_iterator("config/sets")) {
      if (entry.path().extension() != ".yaml") continue;
      try {
        rgnav::loadSetConfig(entry.path().string(), kVars, ".");
      } catch (const rgnav::Error& e) {
        CPPUNIT_FAIL(e.what());
      }
    }
  }
  void rejectsUnknownKey() {
    expectConfigError(edited("    after: [ScanMapper]", "    after: [ScanMapper]\n    retsart: permanent"),
                      "modules[2].retsart: unknown key");
    expectConfigError(edited("port: 12809}", "port: 12809, hots: x}"), "naming.hots: unknown key");
    expectConfigError(edited("robot: b21", "robot: b21\nrobto: b21"), "robto: unknown key");
    expectConfigError(edited("backoff_max_s: 1.5,", "backoff_max_s: 1.5, max_restart: 3,"),
                      "defaults.max_restart: unknown key");
    expectConfigError(edited("robot: b21", "robot: b21\nrobot: b22"), "robot: duplicate key");
  }
  void rejectsMissingKey() {
    expectConfigError(edited("{port: 12810, ", "{"), "watchdog.port: missing required key");
    expectConfigError(edited("host: 10.0.0.5\n", ""), "host: missing required key");
    expectConfigError(edited("    port: 12813\n", ""), "modules[2].port: missing required key");
  }
  void rejectsWrongType() {
    expectConfigError(edited("port: 12811", "port: twelve"), "modules[0].port: wrong type, expected an integer");
    expectConfigError(edited("max_restarts: 2", "max_restarts: 1.5"), "modules[1].max_restarts: wrong type");
    expectConfigError(edited("port: 12809}", "port: 12809, managed: maybe}"), "naming.managed: wrong type");
    expectConfigError(edited(R"(["${RGNAV_BIN}/rgnav-kernel"])", "rgnav-kernel"),
                      "modules[2].command: wrong type, expected a list");
    expectConfigError(edited("objects: [ScanMapper]", "objects: [[ScanMapper]]"),
                      "modules[1].objects[0]: wrong type, expected a string");
    expectConfigError(edited("restart_window_s: 30", "restart_window_s: soon"),
                      "defaults.restart_window_s: wrong type, expected a number");
    expectConfigError(edited("naming: {host: 10.0.0.5, port: 12809}", "naming: [10.0.0.5]"),
                      "naming: wrong type, expected a mapping");
  }
  void rejectsOutOfRange() {
    expectConfigError(edited("port: 12811", "port: 70000"), "modules[0].port: out of range");
    expectConfigError(edited("port: 12811", "port: 0"), "modules[0].port: out of range");
    expectConfigError(edited("restart: permanent", "restart: sometimes"), "modules[1].restart: out of range");
    expectConfigError(edited("restart_window_s: 30", "restart_window_s: 0"), "defaults.restart_window_s: out of range");
    expectConfigError(edited("stop_timeout_s: 2", "stop_timeout_s: .inf"), "defaults.stop_timeout_s: out of range");
    expectConfigError(edited("max_restarts: 2", "max_restarts: -1"), "modules[1].max_restarts: out of range");
    expectConfigError(edited("hang_misses: 3", "hang_misses: 0"), "watchdog.hang_misses: out of range");
    expectConfigError(edited("max_restarts: 2", "backoff_max_s: 0.01"),
                      "modules[1]: backoff_max_s is smaller than backoff_initial_s");
    expectConfigError(edited("name: Kernel", "name: Kernel/1"), "modules[2].name: bad name");
  }
  void rejectsEmptyLists() {
    expectConfigError(edited(R"(["${RGNAV_BIN}/rgnav-kernel"])", "[]"), "modules[2].command: must not be empty");
    expectConfigError(edited("objects: [ScanMapper]", "objects: []"), "modules[1].objects: must not be empty");
    expectConfigError(kSet.substr(0, kSet.find("modules:")) + "modules: []\n", "modules: must not be empty");
  }
  void rejectsDuplicateName() {
    expectConfigError(edited("name: Kernel", "name: ScanMapper"),
                      "modules[2].name: duplicate module name \"ScanMapper\" (also modules[1])");
  }
  void rejectsDuplicatePort() {
    expectConfigError(edited("port: 12813", "port: 12811"), "modules[2].port: port 12811 already used by modules[0].port");
    expectConfigError(edited("port: 12813", "port: 12810"), "modules[2].port: port 12810 already used by watchdog.port");
    expectConfigError(edited("port: 12813", "port: 12809"), "modules[2].port: port 12809 already used by naming.port");
    expectConfigError(edited("{port: 12810,", "{port: 12809,"), "naming.port: port 12809 already used by watchdog.port");
    parse(edited("port: 12809}", "port: 12813, managed: false}"));
  }
  void rejectsDuplicateObject() {
    expectConfigError(edited("objects: [ScanMapper]", "objects: [Laser]"),
                      "modules[1].objects: object \"Laser\" already published by module LogPlayback");
  }
  void rejectsUnknownAfter() {
    expectConfigError(edited("after: [ScanMapper]", "after: [ScanMaper]"),
                      "modules[2].after[0]: unknown module \"ScanMaper\"");
  }
  void rejectsCycle() {
    expectConfigError(edited("    env: {", "    after: [Kernel]\n    env: {"),
                      "modules: dependency cycle in after: LogPlayback -> Kernel -> ScanMapper -> LogPlayback");
  }
  void rejectsUnknownVariable() {
    expectConfigError(edited("${RGNAV_BIN}/rgnav-kernel", "${RGNAV_BINDIR}/rgnav-kernel"),
                      "modules[2].command[0]: unknown variable ${RGNAV_BINDIR}");
    expectConfigError(edited(R"(DATA: "${RGNAV_SHARED}")", R"(DATA: "${DATA}")"),
                      "modules[0].env.DATA: unknown variable ${DATA}");
  }
  void rejectsYamlSyntaxError() { expectConfigError("host: [1, 2\nnaming: x\n", "YAML syntax error"); }
};
CPPUNIT_TEST_SUITE_REGISTRATION(SetConfigTest);
