// The answers to recent requests (see RequestLog.h).
#include "servers/common/RequestLog.h"

namespace rgnav {

std::optional<std::uint64_t> RequestLog::answered(std::uint64_t id) const {
  const auto found = answers_.find(id);
  if (found == answers_.end()) return std::nullopt;
  return found->second;
}

void RequestLog::record(std::uint64_t id, std::uint64_t answer) {
  if (!answers_.emplace(id, answer).second) return;
  order_.push_back(id);
  while (order_.size() > kept_) {
    answers_.erase(order_.front());
    order_.pop_front();
  }
}

}  // namespace rgnav
