// SetLeftovers: a server set's processes as the operating system knows them, without asking its
// watchdog (which may be gone, after SIGKILL, or stopped): the modules its state file names that
// still run with the recorded start time, their orderly stop in reverse start order, and the
// set's ports that some process already holds. rgnav-ctl uses it for `status` and `down` of a
// set whose watchdog is gone, and to refuse `up` of a set whose ports are taken.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "core/supervision/ProcessRecord.h"
#include "core/supervision/SetConfig.h"
#include "watchdog/PortHolder.h"

namespace rgnav {

struct LeftoverModule {
  ProcessRecord record;
  std::chrono::nanoseconds age{0};  // how long it has run
};

struct HeldPort {
  std::string user;  // what of the set listens there: "watchdog", "NameService", a module name
  int port = 0;
  PortHolder holder;
};

// The modules of the state file (run_dir/watchdog.state) that still run, in start order. Throws
// FileError or FormatError for a state file that cannot be read.
std::vector<LeftoverModule> leftoverModules(const SetConfig& set);

// Stops them in reverse start order (SIGTERM to each process group, SIGKILL after the module's
// stop timeout) and empties the state file. Throws ProcessError for one that survives SIGKILL.
void stopLeftovers(const SetConfig& set, const std::vector<LeftoverModule>& leftovers);

// The set's ports (watchdog, managed naming service, modules) that a process holds, except those
// held by the process groups of `own` (which a watchdog adopts).
std::vector<HeldPort> heldPorts(const SetConfig& set, const std::vector<LeftoverModule>& own);

}  // namespace rgnav
