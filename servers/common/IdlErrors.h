// withIdlErrors: runs the work of a servant operation and turns every error it throws into an
// IDL exception the operation declares (the rules are in Common.idl): the typed errors of core
// libraries into InvalidArgument, NotAvailable or NotSupported where the operation's raises
// clause has them, every other error (any rgnav::Error, any std::exception, anything else) into
// Failed with its message. IDL exceptions thrown by the work itself (WireChecks.h) pass as they
// are. So a client never sees CORBA::UNKNOWN for an error of the server's, and a bad request is
// an answer, never a crash. ServiceServant::serve adds the module's bookkeeping.
#pragma once

#include <exception>
#include <string>

#include "Common.hh"
#include "core/common/Errors.h"

namespace rgnav {

// The Common.idl exceptions an operation's raises clause declares besides Failed, which every
// operation declares.
enum class Raises : unsigned { FailedOnly = 0, InvalidArgument = 1, NotAvailable = 2, NotSupported = 4 };

constexpr Raises operator|(Raises a, Raises b) {
  return static_cast<Raises>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
constexpr bool declares(Raises declared, Raises one) {
  return (static_cast<unsigned>(declared) & static_cast<unsigned>(one)) != 0;
}

template <class F>
auto withIdlErrors(Raises declared, F&& f) {
  try {
    return f();
  } catch (const CORBA::Exception&) {
    throw;
  } catch (const InvalidArgumentError& e) {
    if (declares(declared, Raises::InvalidArgument)) throw RGNav::InvalidArgument("", e.what());
    throw RGNav::Failed(e.what());
  } catch (const NotAvailableError& e) {
    if (declares(declared, Raises::NotAvailable)) throw RGNav::NotAvailable(e.what());
    throw RGNav::Failed(e.what());
  } catch (const NotSupportedError& e) {
    if (declares(declared, Raises::NotSupported)) throw RGNav::NotSupported(e.what());
    throw RGNav::Failed(e.what());
  } catch (const std::exception& e) {
    throw RGNav::Failed(e.what());
  } catch (...) {
    throw RGNav::Failed("an exception of unknown type");
  }
}

}  // namespace rgnav
