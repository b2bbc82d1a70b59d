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

bool ClientConnection::refresh() {
  if (direct_) {
    if (!CORBA::is_nil(object_)) return false;  // a corbaloc reference never changes
    object_ = orb_->string_to_object(("corbaloc::" + direct_->str() + "/" + objectName_).c_str());
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
    if (CORBA::is_nil(resolved)) return false;
    omniORB::setClientCallTimeout(resolved, static_cast<CORBA::ULong>(settings_.callTimeout.count()));
    object_ = resolved._retn();
    ++generation_;
    return true;
  } catch (const CORBA::Exception&) {
    return false;  // naming service away or name not bound (yet): keep what we have
  }
}

void ClientConnection::invoke(const char* operation, Idempotence idempotence,
                              const std::function<void(CORBA::Object_ptr, std::uint64_t)>& op) {
  const auto deadline = Clock::now() + settings_.retryBudget;
  auto delay = settings_.backoffInitial;
  std::string lastFailure = "not resolved";
  const std::string where = objectName_ + "." + operation;
  bool failedBefore = false;
  for (;;) {
    if (CORBA::is_nil(object_) || failedBefore) {
      if (refresh() && failedBefore) ++reconnects_;
    }
    if (!CORBA::is_nil(object_)) {
      try {
        op(object_.in(), generation_);
        state_ = ConnectionState::Connected;
        return;
      } catch (const RGNav::InvalidArgument& e) {
        state_ = ConnectionState::Connected;
        throw BadArgumentError(where + ": " + e.message.in(), e.field.in());
      } catch (const RGNav::NotAvailable& e) {
        state_ = ConnectionState::Connected;
        throw NotAvailableError(where + ": " + e.message.in());
      } catch (const RGNav::NotSupported& e) {
        state_ = ConnectionState::Connected;
        throw NotSupportedError(where + ": " + e.message.in());
      } catch (const RGNav::Failed& e) {
        state_ = ConnectionState::Connected;
        throw ModuleFailedError(where + ": " + e.message.in());
      } catch (const CORBA::SystemException& e) {
        lastFailure = describe(e);
        const bool restartLike = dynamic_cast<const CORBA::TRANSIENT*>(&e) || dynamic_cast<const CORBA::COMM_FAILURE*>(&e) ||
                                 dynamic_cast<const CORBA::TIMEOUT*>(&e) || dynamic_cast<const CORBA::OBJECT_NOT_EXIST*>(&e);
        if (!restartLike) {
          state_ = ConnectionState::Connected;
          throw Error(where + ": " + lastFailure + " (not a connection failure, not retried)");
        }
        const bool mayHaveRun = dynamic_cast<const CORBA::TIMEOUT*>(&e) || e.completed() != CORBA::COMPLETED_NO;
        if (idempotence == Idempotence::NotIdempotent && mayHaveRun)
          throw ModuleUnavailableError(where + ": " + lastFailure + "; the call may have run, not retried");
      } catch (const CORBA::UserException& e) {
        state_ = ConnectionState::Connected;
        throw Error(where + ": unexpected " + e._name());
      }
    }
    failedBefore = true;
    if (Clock::now() + delay > deadline) {
      state_ = ConnectionState::Down;
      throw ModuleUnavailableError(
          where + ": no answer within " +
          std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(settings_.retryBudget).count()) +
          " ms (last: " + lastFailure + ")");
    }
    state_ = ConnectionState::Reconnecting;
    std::this_thread::sleep_for(delay);
    delay = std::min(delay * 2, settings_.backoffMax);
  }
}

}  // namespace rgnav
