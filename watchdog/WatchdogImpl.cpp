// The Watchdog.idl servant (see WatchdogImpl.h).
#include "watchdog/WatchdogImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/watchdog/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {

namespace {

// Events one eventsSince call returns at most.
constexpr std::uint32_t kMaxEventBatch = 1000;

// The set's InvalidArgumentError for a name it does not have, as the IDL exception naming "name".
template <class F>
auto forModule(const char* name, F&& f) {
  const std::string checked = wire::checkedName(name, "name", false);
  try {
    return f(checked);
  } catch (const InvalidArgumentError& e) {
    throw RGNav::InvalidArgument("name", e.what());
  }
}

}  // namespace

WatchdogImpl::WatchdogImpl(ServerRuntime& runtime, SupervisedSet& set) : ServiceServant(runtime), set_(set) {}

RGNav::ModuleInfoSeq* WatchdogImpl::modules() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::ModuleInfoSeq(
        toIdlSeq<RGNav::ModuleInfoSeq>(set_.modules(), [](const ModuleProcessInfo& i) { return toIdl(i); }));
  });
}

RGNav::ModuleInfo* WatchdogImpl::describeModule(const char* name) {
  return serve(Raises::InvalidArgument, [&] {
    return new RGNav::ModuleInfo(toIdl(forModule(name, [&](const std::string& n) { return set_.describe(n); })));
  });
}

void WatchdogImpl::stopModule(const char* name) {
  serve(Raises::InvalidArgument, [&] { forModule(name, [&](const std::string& n) { set_.stopModule(n); }); });
}

void WatchdogImpl::startModule(const char* name) {
  serve(Raises::InvalidArgument, [&] { forModule(name, [&](const std::string& n) { set_.startModule(n); }); });
}

void WatchdogImpl::restartModule(const char* name) {
  serve(Raises::InvalidArgument, [&] { forModule(name, [&](const std::string& n) { set_.restartModule(n); }); });
}

RGNav::WatchdogEventSeq* WatchdogImpl::eventsSince(CORBA::ULongLong afterId, CORBA::ULong maxCount) {
  return serve(Raises::InvalidArgument, [&] {
    const std::size_t count = wire::cappedCount(maxCount, kMaxEventBatch, "maxCount");
    return new RGNav::WatchdogEventSeq(toIdlSeq<RGNav::WatchdogEventSeq>(
        set_.eventsSince(afterId, count), [](const SupervisionEvent& e) { return toIdl(e); }));
  });
}

void WatchdogImpl::shutdownSet() { runtime_.requestShutdown(); }

}  // namespace rgnav
