// Resolution, timeouts and the retry loop of ClientConnection (see ClientConnection.h).
#include "clientlibs/common/ClientConnection.h"

#include <omniORB4/Naming.hh>

#include <algorithm>
#include <chrono>
#include <thread>

#include "Common.hh"
#include "clientlibs/common/ClientOrb.h"

namespace rgnav {

namespace {

using Clock = std::chrono::steady_clock;

CosNaming::Name objectPath(const std::string& robot, const std::string& object) {
  CosNaming::Name name;
  name.length(3);
  name[0].id = "RGNav";
  name[1].id = robot.c_str();
  name[2].id = object.c_str();
  return name;
}

constexpr const char* kNotRetried = " (not a connection failure, not retried)";
// CORBA::UNKNOWN carries no message: say what it means and where the cause is.
constexpr const char* kUnknownHint =
    ": the module failed without saying why (an error its interface does not declare); its log has the cause";

std::string describe(const CORBA::SystemException& e) {
  std::string text = e._name();
  if (const char* minor = e.NP_minorString()) text += std::string(" (") + minor + ")";
  return text;
}

}  // namespace

const char* toString(ConnectionState state) {
  switch (state) {
    case ConnectionState::Connected: return "connected";
    case ConnectionState::Reconnecting: return "reconnecting";
    case ConnectionState::Down: return "down";
  }
  return "unknown";
}

ClientConnection::ClientConnection(std::string objectName, ClientSettings settings, std::optional<HostPort> direct)
    : objectName_(std::move(objectName)),
      settings_(std::move(settings)),
      direct_(std::move(direct)),
      orb_(CORBA::ORB::_duplicate(processOrb(settings_))) {}

std::string ClientConnection::target() const {
  if (direct_) return "corbaloc::" + direct_->str() + "/" + objectName_;
  return "RGNav/" + settings_.robot + "/" + objectName_ + " in the naming service at " + settings_.namingHost + ":" +
         std::to_string(settings_.namingPort);
}

bool ClientConnection::refresh(std::string& failure) {
  if (direct_) {
    if (!CORBA::is_nil(object_)) return false;  // a corbaloc reference never changes
    try {
      object_ = orb_->string_to_object(("corbaloc::" + direct_->str() + "/" + objectName_).c_str());
    } catch (const CORBA::SystemException& e) {
      failure = "not a usable address: " + describe(e);
      return false;
    }
    omniORB::setClientCallTimeout(object_, static_cast<CORBA::ULong>(settings_.callTimeout.count()));
    ++generation_;
    return true;
  }
  try {
    CORBA::Object_var namingObj = orb_->string_to_object(
        ("corbaloc::" + settings_.namingHost + ":" + std::to_string(settings_.namingPort) + "/NameService").c_str());
    omniORB::setClientCallTimeout(namingObj, static_cast<CORBA::ULong>(settings_.callTimeout.count()));
    CosNaming::NamingContext_var naming = CosNaming::NamingContext::_unchecked_narrow(namingObj);
    CORBA::Object_var resolved = naming->resolve(objectPath(settings_.robot, objectName_));
    if (CORBA::is_nil(resolved)) {
      failure = "the name is bound to nothing";
      return false;
    }
    omniORB::setClientCallTimeout(resolved, static_cast<CORBA::ULong>(settings_.callTimeout.count()));
    object_ = resolved._retn();
    ++generation_;
    return true;
  } catch (const CosNaming::NamingContext::NotFound&) {
    failure = "the name is not bound (the module is not registered)";
  } catch (const CORBA::SystemException& e) {
    failure = "naming service not reachable: " + describe(e);
  } catch (const CORBA::Exception& e) {
    failure = std::string("naming service refused the lookup: ") + e._name();
  }
  return false;  // naming service away or name not bound (yet): keep what we have
}

void ClientConnection::invoke(const char* operation, Idempotence idempotence,
                              const std::function<void(CORBA::Object_ptr, std::uint64_t)>& op) {
  const auto start = Clock::now();
  const auto budget = [this] {
    return reached_ ? settings_.retryBudget : settings_.firstContactBudget.value_or(settings_.retryBudget);
  };
  const auto answered = [this] {
    reached_ = true;
    state_ = ConnectionState::Connected;
  };
  auto delay = settings_.backoffInitial;
  std::string lastFailure = "not resolved";
  const std::string where = objectName_ + "." + operation;
  bool failedBefore = false;
  for (;;) {
    if (CORBA::is_nil(object_) || failedBefore) {
      if (refresh(lastFailure) && failedBefore) ++reconnects_;
    }
    if (!CORBA::is_nil(object_)) {
      try {
        op(object_.in(), generation_);
        answered();
        return;
      } catch (const RGNav::InvalidArgument& e) {
        answered();
        throw BadArgumentError(where + ": " + e.message.in(), e.field.in());
      } catch (const RGNav::NotAvailable& e) {
        answered();
        throw NotAvailableError(where + ": " + e.message.in());
      } catch (const RGNav::NotSupported& e) {
        answered();
        throw NotSupportedError(where + ": " + e.message.in());
      } catch (const RGNav::Failed& e) {
        answered();
        throw ModuleFailedError(where + ": " + e.message.in());
      } catch (const CORBA::SystemException& e) {
        lastFailure = describe(e);
        const bool reachedProcess = dynamic_cast<const CORBA::TIMEOUT*>(&e) || dynamic_cast<const CORBA::COMM_FAILURE*>(&e);
        const bool restartLike = reachedProcess || dynamic_cast<const CORBA::TRANSIENT*>(&e) ||
                                 dynamic_cast<const CORBA::OBJECT_NOT_EXIST*>(&e);
        if (!restartLike) {
          answered();
          throw Error(where + ": " + lastFailure + (dynamic_cast<const CORBA::UNKNOWN*>(&e) ? kUnknownHint : kNotRetried));
        }
        reached_ = reached_ || reachedProcess;
        const bool mayHaveRun = dynamic_cast<const CORBA::TIMEOUT*>(&e) || e.completed() != CORBA::COMPLETED_NO;
        if (idempotence == Idempotence::NotIdempotent && mayHaveRun)
          throw ModuleUnavailableError(where + ": " + lastFailure + " from " + target() +
                                       "; the call may have run, not retried");
      } catch (const CORBA::UserException& e) {
        answered();
        throw Error(where + ": unexpected " + e._name() + " (" + e._rep_id() + ")");
      }
    }
    failedBefore = true;
    if (Clock::now() + delay > start + budget()) {
      state_ = ConnectionState::Down;
      throw ModuleUnavailableError(
          where + ": no answer within " +
          std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(budget()).count()) + " ms from " +
          target() + " (last: " + lastFailure + ")");
    }
    state_ = ConnectionState::Reconnecting;
    std::this_thread::sleep_for(delay);
    delay = std::min(delay * 2, settings_.backoffMax);
  }
}

}  // namespace rgnav
