// SupervisionEvents: where supervision reports what it does (start, exit, restart, hang,
// FATAL, ...). The watchdog appends to run/<set>/logs/events.log; tests keep a list.
#pragma once

#include <string>

namespace rgnav {

class SupervisionEvents {
 public:
  virtual ~SupervisionEvents() = default;

  // module "-" for events of the watchdog itself; `what` is one word. Never throws: an event
  // that cannot be written must not stop supervision.
  virtual void record(const std::string& module, const std::string& what, const std::string& detail) = 0;
};

}  // namespace rgnav
