// ServiceServant<Skeleton>: implements the Service operations (ping, status, shutdown) of
// Module.idl once for every servant; a module's servant derives from
// ServiceServant<POA_RGNav::Laser> and implements only its own operations.
#pragma once

#include "Module.hh"
#include "clientlibs/common/convert.h"
#include "servers/common/ServerRuntime.h"

namespace rgnav {

template <class Skeleton>
class ServiceServant : public Skeleton {
 public:
  explicit ServiceServant(ServerRuntime& runtime) : runtime_(runtime) {}

  void ping() override {}
  RGNav::ModuleStatus* status() override { return new RGNav::ModuleStatus(toIdl(runtime_.health().snapshot())); }
  void shutdown() override { runtime_.requestShutdown(); }

 protected:
  ServerRuntime& runtime_;
};

}  // namespace rgnav
