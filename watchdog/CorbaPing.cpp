// Pings by CORBA call (see CorbaPing.h).
#include "watchdog/CorbaPing.h"

namespace rgnav {

CorbaPing::CorbaPing(CORBA::ORB_ptr orb, const HostPort& endpoint, const std::string& objectKey,
                             std::chrono::milliseconds timeout)
    : object_(orb->string_to_object(("corbaloc::" + endpoint.str() + "/" + objectKey).c_str())) {
  // Timeouts belong to one object reference, so the narrowed one needs its own.
  omniORB::setClientCallTimeout(object_, static_cast<CORBA::ULong>(timeout.count()));
  if (objectKey != "NameService") {
    service_ = RGNav::Service::_unchecked_narrow(object_);
    omniORB::setClientCallTimeout(service_, static_cast<CORBA::ULong>(timeout.count()));
  }
}

bool CorbaPing::answers() {
  try {
    if (CORBA::is_nil(service_)) return !object_->_non_existent();
    service_->ping();
    return true;
  } catch (const CORBA::Exception&) {
    return false;
  }
}

}  // namespace rgnav
