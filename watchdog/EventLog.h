// The watchdog's event log: every event (start, exit, restart, hang, FATAL, ...) is appended as
// one line "<ISO-8601 UTC ms> <id> <module> <event> <detail>" to a file, and the last N events
// are kept in memory for "events since ID" queries. IDs increase by one per event and continue
// after the last ID found in an existing file. Thread-safe.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

#include "watchdog/UniqueFd.h"

namespace rgnav {

struct Event {
  std::uint64_t id;
  std::chrono::system_clock::time_point time;
  std::string module;  // "-" for events of the watchdog itself
  std::string event;   // one word, e.g. "exited"
  std::string detail;  // free text on one line
};

struct EventsSince {
  std::vector<Event> events;  // oldest first
  bool missed = false;        // some events after the asked ID are no longer held in memory
};

class EventLog {
 public:
  // Opens (creates) `path` for appending. FileError if it cannot; InvalidArgumentError for a
  // zero capacity.
  EventLog(const std::string& path, std::size_t capacity);

  // Stamps the event with the current time and the next ID, keeps it and appends its line.
  // Line breaks become spaces, blanks in module and event become '_'. Returns the ID; throws
  // FileError if the line cannot be written (the event is still kept in memory).
  std::uint64_t record(const std::string& module, const std::string& event, const std::string& detail);
  // Events with an ID greater than `id` that are still held.
  EventsSince since(std::uint64_t id) const;
  // ID of the newest event, 0 if there has never been one.
  std::uint64_t lastId() const;

 private:
  std::string path_;
  std::size_t capacity_;
  UniqueFd fd_;
  mutable std::mutex mutex_;
  std::deque<Event> events_;
  std::uint64_t lastId_;
};

}  // namespace rgnav
