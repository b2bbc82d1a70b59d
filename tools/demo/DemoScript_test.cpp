// Tests the navigating demo's scripted user: the shipped answers and tasks load (three names, an
// object, a room, the object, the start); every kind of task is read; a task naming a region or an
// object the answers do not name, an unknown kind, an unknown key and no task are refused naming
// the file and the key.
#include "tools/demo/DemoScript.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"

using namespace rgnav;

namespace {

const char* const kAnswers = "regions: [home, Ada, Babbage]\nobject: the cabinet\n";

void expectRefused(const std::string& answers, const std::string& tasks, const std::string& expected) {
  try {
    parseDemoScript(answers, tasks, "a.yaml", "t.yaml");
    CPPUNIT_FAIL("accepted, expected: " + expected);
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    CPPUNIT_ASSERT_MESSAGE(message, message.find(expected) != std::string::npos);
  }
}

}  // namespace

class DemoScriptTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DemoScriptTest);
  CPPUNIT_TEST(shippedScriptLoads);
  CPPUNIT_TEST(everyKindOfTaskIsRead);
  CPPUNIT_TEST(badScriptsAreRefusedNamingFileAndKey);
  CPPUNIT_TEST_SUITE_END();

 public:
  void shippedScriptLoads() {
    const DemoScript script = loadDemoScript("config/demo/answers.yaml", "config/demo/tasks.yaml");
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), script.regionNames.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), script.tasks.size());
    CPPUNIT_ASSERT(script.tasks[0].kind == DemoTask::Kind::Region);
    CPPUNIT_ASSERT(script.tasks[1].kind == DemoTask::Kind::Object);
    CPPUNIT_ASSERT(script.tasks[2].kind == DemoTask::Kind::Start);
  }

  void everyKindOfTaskIsRead() {
    const DemoScript script = parseDemoScript(
        kAnswers,
        "tasks:\n  - {go: region, name: Ada}\n  - {go: object, name: the cabinet}\n  - {go: start}\n"
        "  - {go: point, at: [1.5, -2]}\n");
    CPPUNIT_ASSERT_EQUAL(std::string("region 'Ada'"), script.tasks[0].describe());
    CPPUNIT_ASSERT_EQUAL(std::string("object 'the cabinet'"), script.tasks[1].describe());
    CPPUNIT_ASSERT_EQUAL(std::string("the start"), script.tasks[2].describe());
    CPPUNIT_ASSERT_EQUAL(std::string("point (1.50, -2.00)"), script.tasks[3].describe());
    CPPUNIT_ASSERT_EQUAL(std::string("the cabinet"), script.objectName);
  }

  void badScriptsAreRefusedNamingFileAndKey() {
    expectRefused(kAnswers, "tasks:\n  - {go: region, name: Curie}\n", "t.yaml: tasks[0].name: 'Curie' is no region name");
    expectRefused(kAnswers, "tasks:\n  - {go: object, name: desk}\n", "t.yaml: tasks[0].name: 'desk' is not the object");
    expectRefused(kAnswers, "tasks:\n  - {go: fly}\n", "t.yaml: tasks[0].go: is region, object, start or point");
    expectRefused(kAnswers, "tasks:\n  - {go: start, name: x}\n", "t.yaml: tasks[0].name: unknown key");
    expectRefused(kAnswers, "tasks: []\n", "t.yaml: tasks: has no task");
    expectRefused("regions: [a, a]\nobject: o\n", "tasks:\n  - {go: start}\n", "a.yaml: regions: has an empty or repeated");
    expectRefused("regions: [a]\n", "tasks:\n  - {go: start}\n", "a.yaml");
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(DemoScriptTest);
