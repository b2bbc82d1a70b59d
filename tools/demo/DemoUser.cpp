// The navigating demo's user: answers and progress lines (see DemoUser.h).
#include "tools/demo/DemoUser.h"

#include <cstdio>
#include <thread>

#include "tools/common/QuotedText.h"

namespace rgnav {
namespace {

constexpr auto kPoll = std::chrono::milliseconds(500);

}  // namespace

DemoUser::DemoUser(HighLevelPlanningClient& hlp, RgMappingKernelClient& kernel, std::vector<std::string> regionNames,
                   std::chrono::steady_clock::time_point start)
    : hlp_(hlp), kernel_(kernel), names_(std::move(regionNames)), start_(start) {}

double DemoUser::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void DemoUser::answerWaiting() {
  if (next_ == names_.size()) return;
  for (const NamingQuestion& q : hlp_.questions()) {
    if (next_ == names_.size()) return;
    try {
      hlp_.answer(q.id, names_[next_]);
    } catch (const NotAvailableError&) {
      continue;  // answered meanwhile, or its region merged away: the name waits for the next question
    }
    std::printf("demo: %4.0f s question %llu %s: the user answers %s\n", seconds(),
                static_cast<unsigned long long>(q.id), quotedText(q.text).c_str(), quotedText(names_[next_]).c_str());
    std::fflush(stdout);
    ++next_;
  }
}

void DemoUser::print(const Task& task) {
  const MapSummaryView map = kernel_.summary();
  std::printf("demo: %4.0f s task %llu %s %s: %s (map: %zu regions, %zu gateways)\n", seconds(),
              static_cast<unsigned long long>(task.id), toString(task.kind).c_str(), toString(task.state).c_str(),
              task.reason.empty() ? task.progress.c_str() : task.reason.c_str(), map.regions, map.gateways);
  std::fflush(stdout);
}

Task DemoUser::follow(TaskId id, std::chrono::seconds limit) {
  const auto giveUp = std::chrono::steady_clock::now() + limit;
  Task shown;
  double shownAt = -kQuietS;
  while (true) {
    answerWaiting();
    const Task task = hlp_.task(id);
    const bool changed = task.state != shown.state || task.progress != shown.progress;
    if (task.state != shown.state || (changed && seconds() - shownAt >= kQuietS)) {
      print(task);
      shown = task;
      shownAt = seconds();
    }
    if (ended(task.state)) return task;
    if (std::chrono::steady_clock::now() > giveUp) {
      std::printf("demo: task %llu did not end within %lld s: cancelled\n", static_cast<unsigned long long>(id),
                  static_cast<long long>(limit.count()));
      return hlp_.cancel(id);
    }
    std::this_thread::sleep_for(kPoll);
  }
}

}  // namespace rgnav
