// Conversions between Watchdog.idl types and their plain C++ forms.
#pragma once

#include "Watchdog.hh"
#include "clientlibs/watchdog/WatchdogTypes.h"

namespace rgnav {

RGNav::ModuleInfo toIdl(const ModuleProcessInfo& info);
ModuleProcessInfo fromIdl(const RGNav::ModuleInfo& info);
RGNav::WatchdogEvent toIdl(const SupervisionEvent& event);
SupervisionEvent fromIdl(const RGNav::WatchdogEvent& event);

}  // namespace rgnav
