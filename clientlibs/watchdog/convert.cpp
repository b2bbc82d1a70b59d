// Conversions between Watchdog.idl types and their plain C++ forms (see convert.h).
#include "clientlibs/watchdog/convert.h"

namespace rgnav {

namespace {
constexpr std::pair<ProcessState, RGNav::ProcessState> kStates[] = {
    {ProcessState::Stopped, RGNav::PROCESS_STOPPED}, {ProcessState::Starting, RGNav::PROCESS_STARTING},
    {ProcessState::Running, RGNav::PROCESS_RUNNING}, {ProcessState::Hung, RGNav::PROCESS_HUNG},
    {ProcessState::Backoff, RGNav::PROCESS_BACKOFF}, {ProcessState::Fatal, RGNav::PROCESS_FATAL}};
}  // namespace

const char* toString(ProcessState state) {
  switch (state) {
    case ProcessState::Stopped: return "STOPPED";
    case ProcessState::Starting: return "STARTING";
    case ProcessState::Running: return "RUNNING";
    case ProcessState::Hung: return "HUNG";
    case ProcessState::Backoff: return "BACKOFF";
    case ProcessState::Fatal: return "FATAL";
  }
  return "UNKNOWN";
}

RGNav::ModuleInfo toIdl(const ModuleProcessInfo& info) {
  RGNav::ModuleInfo out;
  out.name = info.name.c_str();
  out.state = RGNav::PROCESS_STOPPED;
  for (const auto& [plain, idl] : kStates)
    if (plain == info.state) out.state = idl;
  out.pid = static_cast<CORBA::Long>(info.pid);
  out.uptimeSeconds = info.uptimeSeconds;
  out.restarts = info.restarts;
  out.lastEvent = info.lastEvent.c_str();
  return out;
}

ModuleProcessInfo fromIdl(const RGNav::ModuleInfo& info) {
  ModuleProcessInfo out;
  out.name = info.name.in();
  for (const auto& [plain, idl] : kStates)
    if (idl == info.state) out.state = plain;
  out.pid = info.pid;
  out.uptimeSeconds = info.uptimeSeconds;
  out.restarts = info.restarts;
  out.lastEvent = info.lastEvent.in();
  return out;
}

RGNav::WatchdogEvent toIdl(const SupervisionEvent& event) {
  RGNav::WatchdogEvent out;
  out.id = event.id;
  out.time = event.time.c_str();
  out.moduleName = event.module.c_str();
  out.what = event.what.c_str();
  out.detail = event.detail.c_str();
  return out;
}

SupervisionEvent fromIdl(const RGNav::WatchdogEvent& event) {
  return SupervisionEvent{event.id, event.time.in(), event.moduleName.in(), event.what.in(), event.detail.in()};
}

}  // namespace rgnav
