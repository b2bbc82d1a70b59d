// TaskCheckpoint: the High-Level Planning module's state as it survives a restart (DESIGN.md "State
// survives"; the watchdog's SIGKILL): the task queue (every task it keeps, with the drive request
// ID of the active one), the naming dialog (questions waiting, regions asked about), and the
// answers to the latest cancel and answer requests (so a retry that reaches the restarted module
// changes nothing). Written atomically to the module's state directory whenever any of it
// changes. The text is JSON ({"format": "rgnav-tasks", "version": 1, ...}) with every number
// written so that it reads back to exactly the same double. What the explorer had learnt (its
// gateway queue) is not kept: a restarted exploration starts its strategy anew on the kernel's map.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <utility>

#include "core/nav/tasks/NamingDialog.h"
#include "core/nav/tasks/TaskQueue.h"

namespace rgnav {

// The answers to requests that have no task of their own (cancel, answer): request ID → the task
// or question acted on, the latest kKept.
struct AnsweredRequests {
  static constexpr std::size_t kKept = 256;
  std::deque<std::pair<std::uint64_t, std::uint64_t>> answers;  // oldest first

  const std::uint64_t* find(std::uint64_t request) const;
  void add(std::uint64_t request, std::uint64_t answer);
};

struct HighLevelPlanningState {
  TaskQueue queue;
  NamingDialog dialog;
  AnsweredRequests requests;
};

std::string serializeTasks(const HighLevelPlanningState& state);
// Throws FormatError naming `source` for a text that is not such a checkpoint.
HighLevelPlanningState deserializeTasks(const std::string& text, const std::string& source);

}  // namespace rgnav
