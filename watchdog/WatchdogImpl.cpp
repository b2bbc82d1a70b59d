// The Watchdog.idl servant (see WatchdogImpl.h).
#include "watchdog/WatchdogImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/watchdog/convert.h"

namespace rgnav {

namespace {
template <class F>
auto forModule(F&& f) {
  try {
    return f();
  } catch (const InvalidArgumentError& e) {
    throw RGNav::UnknownModule(e.what());
  }
}
}  // namespace

WatchdogImpl::WatchdogImpl(ServerRuntime& runtime, SupervisedSet& set) : ServiceServant(runtime), set_(set) {}

RGNav::ModuleInfoSeq* WatchdogImpl::modules() {
  return new RGNav::ModuleInfoSeq(
      toIdlSeq<RGNav::ModuleInfoSeq>(set_.modules(), [](const ModuleProcessInfo& i) { return toIdl(i); }));
}

RGNav::ModuleInfo* WatchdogImpl::describeModule(const char* name) {
  return new RGNav::ModuleInfo(toIdl(forModule([&] { return set_.describe(name); })));
}

void WatchdogImpl::stopModule(const char* name) {
  forModule([&] { set_.stopModule(name); });
}

void WatchdogImpl::startModule(const char* name) {
  forModule([&] { set_.startModule(name); });
}

void WatchdogImpl::restartModule(const char* name) {
  forModule([&] { set_.restartModule(name); });
}

RGNav::WatchdogEventSeq* WatchdogImpl::eventsSince(CORBA::ULongLong afterId, CORBA::ULong maxCount) {
  return new RGNav::WatchdogEventSeq(toIdlSeq<RGNav::WatchdogEventSeq>(
      set_.eventsSince(afterId, maxCount), [](const SupervisionEvent& e) { return toIdl(e); }));
}

void WatchdogImpl::shutdownSet() { runtime_.requestShutdown(); }

}  // namespace rgnav
