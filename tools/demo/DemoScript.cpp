// The navigating demo's scripted user (see DemoScript.h).
#include "tools/demo/DemoScript.h"

#include <algorithm>
#include <cstdio>

#include "core/common/Errors.h"
#include "core/config/ConfigNode.h"
#include "core/config/DescribedConfig.h"

namespace rgnav {
namespace {

// Runs `parse` on the document of `text`, its ConfigErrors prefixed with `name`.
template <class Parse>
void parseNamed(const std::string& text, const std::string& name, Parse parse) {
  try {
    const ConfigVars noVariables;
    parse(ConfigNode(parseYamlDocument(text), "", noVariables));
  } catch (const ConfigError& e) {
    throw ConfigError(name + ": " + e.what());
  }
}

DemoTask taskOf(const ConfigNode& node) {
  const std::string go = node["go"].asString();
  DemoTask task;
  if (go == "region" || go == "object") {
    node.expectKeys({"go", "name"});
    task.kind = go == "region" ? DemoTask::Kind::Region : DemoTask::Kind::Object;
    task.name = node["name"].asString();
    if (task.name.empty()) node["name"].fail("is empty");
  } else if (go == "start") {
    node.expectKeys({"go"});
    task.kind = DemoTask::Kind::Start;
  } else if (go == "point") {
    node.expectKeys({"go", "at"});
    const std::vector<ConfigNode> at = node["at"].items();
    if (at.size() != 2) node["at"].fail("is [x, y]");
    task.kind = DemoTask::Kind::Point;
    task.point = {at[0].asDouble(), at[1].asDouble()};
  } else {
    node["go"].fail("is region, object, start or point, not '" + go + "'");
  }
  return task;
}

}  // namespace

std::string DemoTask::describe() const {
  switch (kind) {
    case Kind::Region: return "region '" + name + "'";
    case Kind::Object: return "object '" + name + "'";
    case Kind::Start: return "the start";
    case Kind::Point: break;
  }
  char text[64];
  std::snprintf(text, sizeof text, "point (%.2f, %.2f)", point.x(), point.y());
  return text;
}

DemoScript parseDemoScript(const std::string& answersYaml, const std::string& tasksYaml,
                           const std::string& answersName, const std::string& tasksName) {
  DemoScript script;
  parseNamed(answersYaml, answersName, [&](const ConfigNode& answers) {
    answers.expectKeys({"regions", "object"});
    script.regionNames = answers["regions"].asStringList();
    if (script.regionNames.empty()) answers["regions"].fail("names no region");
    for (const std::string& name : script.regionNames)
      if (name.empty() || std::count(script.regionNames.begin(), script.regionNames.end(), name) > 1)
        answers["regions"].fail("has an empty or repeated name '" + name + "'");
    script.objectName = answers["object"].asString();
    if (script.objectName.empty()) answers["object"].fail("is empty");
  });
  parseNamed(tasksYaml, tasksName, [&](const ConfigNode& tasks) {
    tasks.expectKeys({"tasks"});
    const auto& names = script.regionNames;
    for (const ConfigNode& item : tasks["tasks"].items()) {
      DemoTask task = taskOf(item);
      if (task.kind == DemoTask::Kind::Region && std::find(names.begin(), names.end(), task.name) == names.end())
        item["name"].fail("'" + task.name + "' is no region name of the answers");
      if (task.kind == DemoTask::Kind::Object && task.name != script.objectName)
        item["name"].fail("'" + task.name + "' is not the object name of the answers");
      script.tasks.push_back(std::move(task));
    }
    if (script.tasks.empty()) tasks["tasks"].fail("has no task");
  });
  return script;
}

DemoScript loadDemoScript(const std::string& answersFile, const std::string& tasksFile) {
  return parseDemoScript(readConfigFile(answersFile), readConfigFile(tasksFile), answersFile, tasksFile);
}

}  // namespace rgnav
