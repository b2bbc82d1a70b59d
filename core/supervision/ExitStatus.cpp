// Human-readable text of an exit status, for events and fatal reasons.
#include "core/supervision/ExitStatus.h"

namespace rgnav {

std::string ExitStatus::describe() const {
  switch (kind_) {
    case Kind::Exited:
      return "exited with code " + std::to_string(value_);
    case Kind::Signaled:
      return "killed by signal " + std::to_string(value_);
    case Kind::Lost:
      return "vanished (adopted process, status unknown)";
    case Kind::NotStarted:
      return cause_;
  }
  return "unknown exit";
}

}  // namespace rgnav
