// Typed error of the watchdog's process layer: a process could not be started, signalled or
// waited for. The message names the command or PID and carries the errno text.
#pragma once

#include "core/common/Errors.h"

namespace rgnav {

class ProcessError : public Error {
 public:
  using Error::Error;
};

}  // namespace rgnav
