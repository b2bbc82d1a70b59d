// GatewayClass: names and openings per class.
#include "core/gateways/classes/GatewayClass.h"

namespace rgnav {

std::string_view gatewayClassName(GatewayClass c) {
  switch (c) {
    case GatewayClass::XCrossing: return "X-Crossing";
    case GatewayClass::TJunction: return "T-Junction";
    case GatewayClass::LTJunction: return "LT-Junction";
    case GatewayClass::RTJunction: return "RT-Junction";
    case GatewayClass::LTurn: return "L-Turn";
    case GatewayClass::RTurn: return "R-Turn";
    case GatewayClass::DeadEnd: return "Deadend";
    case GatewayClass::Hallway: return "Hallway";
  }
  return "unknown";
}

bool isTransition(GatewayClass c) { return c != GatewayClass::DeadEnd && c != GatewayClass::Hallway; }

GatewayOpenings openingsOf(GatewayClass c) {
  switch (c) {
    case GatewayClass::XCrossing: return {true, true, true};
    case GatewayClass::TJunction: return {true, false, true};
    case GatewayClass::LTJunction: return {true, true, false};
    case GatewayClass::RTJunction: return {false, true, true};
    case GatewayClass::LTurn: return {true, false, false};
    case GatewayClass::RTurn: return {false, false, true};
    case GatewayClass::DeadEnd: return {false, false, false};
    case GatewayClass::Hallway: return {false, true, false};
  }
  return {};
}

}  // namespace rgnav
