// ClientOrb: the process's one ORB as client libraries need it: call and connect timeouts set,
// large messages allowed, and omniORB's own silent retries turned off so that the client
// libraries decide about retries (DESIGN.md "Restarts are normal").
#pragma once

#include <omniORB4/CORBA.h>

#include <string>
#include <vector>

#include "clientlibs/common/ClientSettings.h"

namespace rgnav {

// ORB options every RG Nav process passes to ORB_init (servers add their endpoint).
std::vector<std::string> commonOrbOptions(const ClientSettings& settings);

// The process's ORB, initialized on first use with commonOrbOptions plus extraOptions (a server
// passes its endpoint); later calls return the same ORB and ignore their arguments.
CORBA::ORB_ptr processOrb(const ClientSettings& settings, const std::vector<std::string>& extraOptions = {});

}  // namespace rgnav
