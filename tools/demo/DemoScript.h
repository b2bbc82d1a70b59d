// DemoScript: the scripted user of the navigating demo (`rgctl demo`): the names a user at the GUI
// gives in the naming dialog (config/demo/answers.yaml: the first three regions asked about, one
// object of the map) and the tasks given once the floor is explored (config/demo/tasks.yaml: a
// named room, a named object, back to the start). Both files are described in their comments.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace rgnav {

struct DemoTask {
  enum class Kind { Region, Object, Start, Point };
  Kind kind = Kind::Start;
  std::string name;                                  // Region, Object
  Eigen::Vector2d point = Eigen::Vector2d::Zero();   // Point: map frame

  std::string describe() const;  // "region 'Ada'", "object 'the cabinet'", "the start", "point (1.00, 2.00)"
};

struct DemoScript {
  std::vector<std::string> regionNames;  // answers to the questions, in the order asked
  std::string objectName;
  std::vector<DemoTask> tasks;
};

// Throws ConfigError naming the file (`answersName`, `tasksName`) and key, also for a task naming a
// region or an object the answers do not name; loadDemoScript also FileError for a file that
// cannot be read.
DemoScript parseDemoScript(const std::string& answersYaml, const std::string& tasksYaml,
                           const std::string& answersName = "answers", const std::string& tasksName = "tasks");
DemoScript loadDemoScript(const std::string& answersFile, const std::string& tasksFile);

}  // namespace rgnav
