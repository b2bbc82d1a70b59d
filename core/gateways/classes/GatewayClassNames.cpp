// Gateway class names back to classes (see GatewayClassNames.h).
#include "core/gateways/classes/GatewayClassNames.h"

namespace rgnav {

std::optional<GatewayClass> parseGatewayClass(std::string_view name) {
  for (const GatewayClass c : kGatewayClasses) {
    if (gatewayClassName(c) == name) return c;
  }
  return std::nullopt;
}

}  // namespace rgnav
