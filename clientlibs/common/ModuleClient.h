// ModuleClient: the operations every module offers (Module.idl), for any module object name;
// the per-module clients derive from it.
#pragma once

#include "Module.hh"
#include "clientlibs/common/ClientConnection.h"
#include "clientlibs/common/ModuleStatusInfo.h"

namespace rgnav {

template <class Iface>
class ModuleClientOf {
 public:
  ModuleClientOf(std::string objectName, ClientSettings settings, std::optional<HostPort> direct = std::nullopt)
      : connection_(std::move(objectName), std::move(settings), std::move(direct)) {}

  void ping() {
    connection_.call("ping", [](typename Iface::_ptr_type m) { m->ping(); });
  }
  ModuleStatusInfo status();
  ConnectionState state() const { return connection_.connection().state(); }
  std::uint64_t reconnects() const { return connection_.connection().reconnects(); }

 protected:
  TypedConnection<Iface> connection_;
};

using ModuleClient = ModuleClientOf<RGNav::Service>;

}  // namespace rgnav

#include "clientlibs/common/convert.h"

template <class Iface>
rgnav::ModuleStatusInfo rgnav::ModuleClientOf<Iface>::status() {
  return connection_.call("status", [](typename Iface::_ptr_type m) {
    RGNav::ModuleStatus_var s = m->status();
    return fromIdl(s.in());
  });
}
