// Names of the restart policies as written in server-set files.
#include "core/supervision/ModulePolicy.h"

namespace rgnav {

std::optional<RestartPolicy> parseRestartPolicy(std::string_view text) {
  for (RestartPolicy p : {RestartPolicy::Permanent, RestartPolicy::Transient, RestartPolicy::Temporary}) {
    if (text == toString(p)) return p;
  }
  return std::nullopt;
}

const char* toString(RestartPolicy policy) {
  switch (policy) {
    case RestartPolicy::Permanent:
      return "permanent";
    case RestartPolicy::Transient:
      return "transient";
    case RestartPolicy::Temporary:
      return "temporary";
  }
  return "unknown";
}

}  // namespace rgnav
