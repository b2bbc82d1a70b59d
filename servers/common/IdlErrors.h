// withIdlErrors: runs a core call inside a servant and turns the typed errors of core libraries
// into the IDL exceptions of Common.idl, so a bad argument is an answer, never a crash.
#pragma once

#include "Common.hh"
#include "core/common/Errors.h"

namespace rgnav {

template <class F>
auto withIdlErrors(F&& f) {
  try {
    return f();
  } catch (const InvalidArgumentError& e) {
    throw RGNav::InvalidArgument(e.what());
  } catch (const NotAvailableError& e) {
    throw RGNav::NotAvailable(e.what());
  } catch (const NotSupportedError& e) {
    throw RGNav::NotSupported(e.what());
  }
}

}  // namespace rgnav
