// EventLogSink: supervision events into the watchdog's EventLog. A line that cannot be
// written (full disk) is dropped from the file but kept in memory: it must not stop supervision.
#pragma once

#include "core/common/Errors.h"
#include "core/supervision/SupervisionEvents.h"
#include "watchdog/EventLog.h"

namespace rgnav {

class EventLogSink : public SupervisionEvents {
 public:
  explicit EventLogSink(EventLog& log) : log_(log) {}

  void record(const std::string& module, const std::string& what, const std::string& detail) override {
    try {
      log_.record(module, what, detail);
    } catch (const Error&) {
      // EventLog keeps the event in memory even when the file write fails.
    }
  }

 private:
  EventLog& log_;
};

}  // namespace rgnav
