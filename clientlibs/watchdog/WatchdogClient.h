// WatchdogClient: reads and controls the watchdog of one host's server set. It reaches the
// watchdog directly at its fixed endpoint (corbaloc), because that watchdog may be the one that
// runs the naming service.
#pragma once

#include <vector>

#include "Watchdog.hh"
#include "clientlibs/common/ModuleClient.h"
#include "clientlibs/watchdog/WatchdogTypes.h"

namespace rgnav {

class WatchdogClient : public ModuleClientOf<RGNav::Watchdog> {
 public:
  WatchdogClient(const HostPort& endpoint, ClientSettings settings = ClientSettings::fromEnvironment());

  std::vector<ModuleProcessInfo> modules();
  // BadArgumentError (field "name") for a module the set does not have.
  ModuleProcessInfo describeModule(const std::string& name);
  // Stopping, starting and restarting a module and shutting the set down are not idempotent:
  // they are not retried once a call may have reached the watchdog (a timeout, a connection lost
  // after sending); ModuleUnavailableError then says so, and the caller looks at the module's
  // state before it asks again. Retried only when the call surely did not arrive.
  void stopModule(const std::string& name);
  void startModule(const std::string& name);
  void restartModule(const std::string& name);
  // At most maxCount events, and at most the watchdog's cap: ask again after the last one.
  std::vector<SupervisionEvent> eventsSince(std::uint64_t afterId, std::uint32_t maxCount);
  void shutdownSet();
};

}  // namespace rgnav
