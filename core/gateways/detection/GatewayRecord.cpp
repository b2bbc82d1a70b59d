// GatewayRecord's class test (see GatewayRecord.h).
#include "core/gateways/detection/GatewayRecord.h"

#include "core/gateways/classes/GatewayClassNames.h"

namespace rgnav {

bool GatewayRecord::isTransition() const {
  if (label() == kWiderTwinClass) return false;
  const std::optional<GatewayClass> hallwayClass = parseGatewayClass(label());
  return !hallwayClass || rgnav::isTransition(*hallwayClass);
}

}  // namespace rgnav
