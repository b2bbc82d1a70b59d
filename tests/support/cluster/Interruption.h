// Interruption: SIGINT, SIGTERM and SIGHUP turned into a flag that a program running a
// TestCluster polls while it waits, so that it unwinds (the cluster's destructor shuts the set
// down and removes its temporary directory) instead of dying with the directory left behind.
// The modules would stop anyway (they get SIGTERM when the harness dies); the directory would not
// go away. TestCluster::waitFor polls the flag too. A program that never calls
// catchInterruptions() (the CppUnit tests) keeps the default handlers: a signal ends it at once.
#pragma once

#include <chrono>

#include "core/common/Errors.h"

namespace rgnav::testing {

class InterruptedError : public Error {
 public:
  using Error::Error;
};

// Installs the handlers (once per process; later calls do nothing).
void catchInterruptions();
// Throws InterruptedError naming the signal if one arrived since catchInterruptions().
void throwIfInterrupted();
// Sleeps until `until` in steps of at most 50 ms, calling throwIfInterrupted() after each.
void sleepUntilOrInterrupted(std::chrono::steady_clock::time_point until);

}  // namespace rgnav::testing
