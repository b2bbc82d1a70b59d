// refusedField: for tests of the argument checks: runs a check or a servant operation and
// returns the field its RGNav::InvalidArgument names, or "(accepted)" if it threw none.
#pragma once

#include <string>

#include "Common.hh"

namespace rgnav {

template <class F>
std::string refusedField(F&& check) {
  try {
    check();
  } catch (const RGNav::InvalidArgument& e) {
    return e.field.in();
  }
  return "(accepted)";
}

}  // namespace rgnav
