// WatchdogClient calls through the retrying connection (see WatchdogClient.h).
#include "clientlibs/watchdog/WatchdogClient.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/watchdog/convert.h"

namespace rgnav {

WatchdogClient::WatchdogClient(const HostPort& endpoint, ClientSettings settings)
    : ModuleClientOf("Watchdog", std::move(settings), endpoint) {}

std::vector<ModuleProcessInfo> WatchdogClient::modules() {
  return connection_.call("modules", [](RGNav::Watchdog_ptr w) {
    RGNav::ModuleInfoSeq_var infos = w->modules();
    return fromIdlSeq<std::vector<ModuleProcessInfo>>(infos.in(), [](const RGNav::ModuleInfo& i) { return fromIdl(i); });
  });
}

ModuleProcessInfo WatchdogClient::describeModule(const std::string& name) {
  return connection_.call("describeModule", [&](RGNav::Watchdog_ptr w) {
    RGNav::ModuleInfo_var info = w->describeModule(name.c_str());
    return fromIdl(info.in());
  });
}

void WatchdogClient::stopModule(const std::string& name) {
  connection_.call("stopModule", [&](RGNav::Watchdog_ptr w) { w->stopModule(name.c_str()); }, Idempotence::NotIdempotent);
}

void WatchdogClient::startModule(const std::string& name) {
  connection_.call("startModule", [&](RGNav::Watchdog_ptr w) { w->startModule(name.c_str()); },
                   Idempotence::NotIdempotent);
}

void WatchdogClient::restartModule(const std::string& name) {
  connection_.call("restartModule", [&](RGNav::Watchdog_ptr w) { w->restartModule(name.c_str()); },
                   Idempotence::NotIdempotent);
}

std::vector<SupervisionEvent> WatchdogClient::eventsSince(std::uint64_t afterId, std::uint32_t maxCount) {
  return connection_.call("eventsSince", [&](RGNav::Watchdog_ptr w) {
    RGNav::WatchdogEventSeq_var events = w->eventsSince(afterId, maxCount);
    return fromIdlSeq<std::vector<SupervisionEvent>>(events.in(), [](const RGNav::WatchdogEvent& e) { return fromIdl(e); });
  });
}

void WatchdogClient::shutdownSet() {
  connection_.call("shutdownSet", [](RGNav::Watchdog_ptr w) { w->shutdownSet(); }, Idempotence::NotIdempotent);
}

}  // namespace rgnav
