// ServiceServant<Skeleton>: implements the Service operations (ping, status, shutdown) of
// Module.idl once for every servant; a module's servant derives from
// ServiceServant<POA_RGNav::Laser> and implements only its own operations, each through serve():
// its errors become the IDL exceptions the operation declares (IdlErrors.h), and an unexpected
// failure is counted in status() ("calls_failed") and logged.
#pragma once

#include <iostream>

#include "Module.hh"
#include "clientlibs/common/convert.h"
#include "servers/common/IdlErrors.h"
#include "servers/common/ServerRuntime.h"

namespace rgnav {

template <class Skeleton>
class ServiceServant : public Skeleton {
 public:
  explicit ServiceServant(ServerRuntime& runtime) : runtime_(runtime) {}

  void ping() override {}
  RGNav::ModuleStatus* status() override {
    return serve(Raises::FailedOnly, [&] { return new RGNav::ModuleStatus(toIdl(runtime_.health().snapshot())); });
  }
  void shutdown() override { runtime_.requestShutdown(); }

 protected:
  // Runs one operation's work; `declared` is what its raises clause has besides Failed.
  template <class F>
  auto serve(Raises declared, F&& work) {
    try {
      return withIdlErrors(declared, std::forward<F>(work));
    } catch (const RGNav::Failed& e) {
      runtime_.health().add("calls_failed");
      std::cerr << runtime_.server().module << ": a call failed: " << e.message.in() << std::endl;
      throw;
    }
  }

  ServerRuntime& runtime_;
};

}  // namespace rgnav
