// ClientConnection: the caller's side of one module object (DESIGN.md "Restarts are normal"):
// resolves RGNav/<robot>/<Object> in the naming service, runs calls with timeouts, and on
// TRANSIENT, COMM_FAILURE, TIMEOUT or OBJECT_NOT_EXIST re-resolves and retries with bounded
// exponential backoff, then fails with ModuleUnavailableError naming the module, the call, where
// it looked for the module and the last failure. Until the module has been reached once, the
// settings' firstContactBudget bounds the retries instead of retryBudget.
#pragma once

#include <omniORB4/CORBA.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>

#include "clientlibs/common/ClientSettings.h"
#include "core/common/Errors.h"
#include "core/common/HostPort.h"

namespace rgnav {

enum class ConnectionState { Connected, Reconnecting, Down };
const char* toString(ConnectionState state);

// A module did not answer within the retry budget. The message names the call, the object looked
// up (RGNav/<robot>/<Object> and the naming service's host:port, or the direct corbaloc address)
// and the last failure; a tool adds what the user can do about it.
class ModuleUnavailableError : public Error {
 public:
  using Error::Error;
};

// The module refused an argument (IDL InvalidArgument); field() names it ("" for the arguments
// together).
class BadArgumentError : public InvalidArgumentError {
 public:
  BadArgumentError(const std::string& what, std::string field) : InvalidArgumentError(what), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// The module failed inside the call (IDL Failed: an unexpected error there, e.g. a file it could
// not write); the message is the module's.
class ModuleFailedError : public Error {
 public:
  using Error::Error;
};

// Whether a call may run twice without harm; only idempotent calls are retried after a
// failure that may have reached the server.
enum class Idempotence { Idempotent, NotIdempotent };

class ClientConnection {
 public:
  // Resolves objectName in the naming service, or, with a direct endpoint, reaches it as
  // corbaloc::host:port/<objectName> without the naming service (for the watchdog, which may be
  // the one that runs the naming service).
  ClientConnection(std::string objectName, ClientSettings settings, std::optional<HostPort> direct = std::nullopt);

  // Calls op(object, generation) until it succeeds or the retry budget is spent. generation
  // changes whenever the object reference was replaced, so callers can cache narrowed refs.
  // IDL user exceptions of Common.idl become the matching rgnav::*Error with the module's
  // message: InvalidArgument -> BadArgumentError, NotAvailable -> NotAvailableError,
  // NotSupported -> NotSupportedError, Failed -> ModuleFailedError.
  void invoke(const char* operation, Idempotence idempotence,
              const std::function<void(CORBA::Object_ptr, std::uint64_t generation)>& op);

  ConnectionState state() const { return state_.load(); }
  const std::string& objectName() const { return objectName_; }
  std::chrono::milliseconds callTimeout() const { return settings_.callTimeout; }
  std::uint64_t reconnects() const { return reconnects_.load(); }

 private:
  // Re-resolves the name; keeps the old reference if the naming service is away. On false,
  // `failure` says why (naming service unreachable, name not bound).
  bool refresh(std::string& failure);
  // Where the module is looked for, for messages: "RGNav/<robot>/<Object> in the naming service
  // at host:port" or "corbaloc::host:port/<Object>".
  std::string target() const;

  std::string objectName_;
  ClientSettings settings_;
  std::optional<HostPort> direct_;
  CORBA::ORB_var orb_;
  CORBA::Object_var object_;
  std::uint64_t generation_ = 0;
  bool reached_ = false;  // the module answered (or took a call) at least once
  std::atomic<ConnectionState> state_{ConnectionState::Reconnecting};
  std::atomic<std::uint64_t> reconnects_{0};
};

// A connection with the reference narrowed to the IDL interface Iface. Not thread-safe: one
// client object per thread.
template <class Iface>
class TypedConnection {
 public:
  using Ptr = typename Iface::_ptr_type;
  using Var = typename Iface::_var_type;

  TypedConnection(std::string objectName, ClientSettings settings, std::optional<HostPort> direct = std::nullopt)
      : connection_(std::move(objectName), std::move(settings), std::move(direct)) {}

  template <class F>
  auto call(const char* operation, F&& f, Idempotence idempotence = Idempotence::Idempotent) {
    using R = std::invoke_result_t<F, Ptr>;
    if constexpr (std::is_void_v<R>) {
      connection_.invoke(operation, idempotence, [&](CORBA::Object_ptr obj, std::uint64_t gen) { f(typed(obj, gen)); });
    } else {
      std::optional<R> result;
      connection_.invoke(operation, idempotence,
                         [&](CORBA::Object_ptr obj, std::uint64_t gen) { result.emplace(f(typed(obj, gen))); });
      return std::move(*result);
    }
  }

  const ClientConnection& connection() const { return connection_; }

 private:
  Ptr typed(CORBA::Object_ptr obj, std::uint64_t generation) {
    if (generation != generation_) {
      // Timeouts belong to one object reference, so the narrowed one needs its own.
      typed_ = Iface::_unchecked_narrow(obj);
      omniORB::setClientCallTimeout(typed_.in(), static_cast<CORBA::ULong>(connection_.callTimeout().count()));
      generation_ = generation;
    }
    return typed_.in();
  }

  ClientConnection connection_;
  Var typed_;
  std::uint64_t generation_ = 0;
};

}  // namespace rgnav
