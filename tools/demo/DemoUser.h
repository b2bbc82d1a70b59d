// DemoUser: the navigating demo's user at the GUI, acting on the High-Level Planning module while
// a task runs: answers the naming questions waiting (thesis 6.1.3) with the script's region names,
// one per question in the order asked, until the names are used up (later questions stay waiting,
// which holds the robot up in nothing), and follows a task to its end with a progress line on
// stdout whenever its state or what it does changes (at most one per kQuietS unless the state
// changes), each with the map's counts.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "clientlibs/highlevelplanning/HighLevelPlanningClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"

namespace rgnav {

class DemoUser {
 public:
  static constexpr double kQuietS = 5.0;

  // `start`: the demo's start, from which the lines count seconds.
  DemoUser(HighLevelPlanningClient& hlp, RgMappingKernelClient& kernel, std::vector<std::string> regionNames,
           std::chrono::steady_clock::time_point start);

  // Answers the questions waiting while names are left.
  void answerWaiting();
  std::size_t answered() const { return next_; }
  // Follows task `id` (answering questions meanwhile) until it ends or `limit` has passed; then
  // the task is cancelled. Returns the task as it ended.
  Task follow(TaskId id, std::chrono::seconds limit);

 private:
  double seconds() const;
  void print(const Task& task);

  HighLevelPlanningClient& hlp_;
  RgMappingKernelClient& kernel_;
  std::vector<std::string> names_;
  std::size_t next_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace rgnav
