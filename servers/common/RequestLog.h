// RequestLog: exactly-once answers to calls that are not idempotent (RGMappingKernel names and
// merges, RGMappingKernel.idl). A client sends a request ID with such a call and keeps it when it
// retries after a timeout; the server looks the ID up before acting, and if it already acted on
// it, answers as it did then instead of acting again. It keeps the answers of the latest
// kKeptRequests requests: a client retries within seconds, long before so many other requests
// came. Not persisted: a retry that reaches a restarted server acts again. Not thread-safe: the
// server's own lock guards it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <unordered_map>

namespace rgnav {

class RequestLog {
 public:
  static constexpr std::size_t kKeptRequests = 1024;

  explicit RequestLog(std::size_t kept = kKeptRequests) : kept_(kept) {}

  // The answer given to request `id`, if it was answered and is still kept.
  std::optional<std::uint64_t> answered(std::uint64_t id) const;
  // Request `id` was acted on with this answer; forgets the oldest one beyond the bound.
  void record(std::uint64_t id, std::uint64_t answer);
  std::size_t size() const { return answers_.size(); }

 private:
  std::size_t kept_;
  std::unordered_map<std::uint64_t, std::uint64_t> answers_;
  std::deque<std::uint64_t> order_;  // oldest first
};

}  // namespace rgnav
