// The process-wide client ORB (see ClientOrb.h).
#include "clientlibs/common/ClientOrb.h"

#include <mutex>
#include <string>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {

namespace {
// Returning false hands the exception to the caller at once.
template <class Exception>
CORBA::Boolean noRetry(void*, CORBA::ULong, const Exception&) {
  return false;
}
}  // namespace

std::vector<std::string> commonOrbOptions(const ClientSettings& settings) {
  return {"-ORBclientCallTimeOutPeriod", std::to_string(settings.callTimeout.count()),
          "-ORBclientConnectTimeOutPeriod", std::to_string(settings.connectTimeout.count()),
          "-ORBgiopMaxMsgSize", std::to_string(64u << 20),
          "-ORBverifyObjectExistsAndType", "0",
          "-ORBInitRef", "NameService=corbaloc::" + settings.namingHost + ":" +
                             std::to_string(settings.namingPort) + "/NameService"};
}

CORBA::ORB_ptr processOrb(const ClientSettings& settings, const std::vector<std::string>& extraOptions) {
  static std::once_flag once;
  static CORBA::ORB_var orb;
  std::call_once(once, [&] {
    std::vector<std::string> args{"rgnav"};
    for (auto& option : commonOrbOptions(settings)) args.push_back(option);
    args.insert(args.end(), extraOptions.begin(), extraOptions.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    int argc = static_cast<int>(argv.size());
    try {
      orb = CORBA::ORB_init(argc, argv.data());
    } catch (const CORBA::SystemException& e) {
      const char* minor = e.NP_minorString();
      throw ConfigError(std::string("the ORB refused its options (omniORB's message above says which): ") + e._name() +
                        (minor ? std::string(" (") + minor + ")" : std::string()));
    }
    omniORB::installTransientExceptionHandler(nullptr, noRetry<CORBA::TRANSIENT>);
    omniORB::installCommFailureExceptionHandler(nullptr, noRetry<CORBA::COMM_FAILURE>);
    omniORB::installSystemExceptionHandler(nullptr, noRetry<CORBA::SystemException>);
  });
  return orb.in();
}

}  // namespace rgnav
