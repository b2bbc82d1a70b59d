// WatchdogImpl: the Watchdog.idl servant: module list, status, events and operator control of
// the SupervisedSet of this host.
#pragma once

#include <functional>

#include "Watchdog.hh"
#include "servers/common/ServiceServant.h"
#include "watchdog/SupervisedSet.h"

namespace rgnav {

class WatchdogImpl : public ServiceServant<POA_RGNav::Watchdog> {
 public:
  // shutdownSet() stops the set and then asks the runtime to exit.
  WatchdogImpl(ServerRuntime& runtime, SupervisedSet& set);

  RGNav::ModuleInfoSeq* modules() override;
  RGNav::ModuleInfo* describeModule(const char* name) override;
  void stopModule(const char* name) override;
  void startModule(const char* name) override;
  void restartModule(const char* name) override;
  RGNav::WatchdogEventSeq* eventsSince(CORBA::ULongLong afterId, CORBA::ULong maxCount) override;
  void shutdownSet() override;

 private:
  SupervisedSet& set_;
};

}  // namespace rgnav
