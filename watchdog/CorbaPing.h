// CorbaPing: the watchdog's ping of one module, which judges it alive by an answer, not by its
// PID (DESIGN.md, supervisors): Service::ping() at corbaloc::host:port/<object>, or, for the
// naming service, a _non_existent() call on its root context; each bounded by the heartbeat
// timeout. PingThreads runs it for the supervision's LivenessProbe.
#pragma once

#include <omniORB4/CORBA.h>

#include <chrono>
#include <string>

#include "Module.hh"
#include "core/common/HostPort.h"

namespace rgnav {

class CorbaPing {
 public:
  // objectKey "NameService" probes a naming service; anything else a Service object.
  CorbaPing(CORBA::ORB_ptr orb, const HostPort& endpoint, const std::string& objectKey,
            std::chrono::milliseconds timeout);
  // True if the module answered within the timeout.
  bool answers();

 private:
  CORBA::Object_var object_;
  RGNav::Service_var service_;  // null for a naming service
};

}  // namespace rgnav
