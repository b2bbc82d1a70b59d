// GatewayClass: the classes of crossing gateways of thesis section 4.1 (figure 4.1, 1-5) plus the
// two counterbalance classes of 4.1.3 (Deadend, Hallway), and which hallways leave the gateway
// area as seen by a robot that enters it from behind.
#pragma once

#include <array>
#include <string_view>

namespace rgnav {

enum class GatewayClass { XCrossing, TJunction, LTJunction, RTJunction, LTurn, RTurn, DeadEnd, Hallway };

inline constexpr std::array<GatewayClass, 8> kGatewayClasses = {
    GatewayClass::XCrossing, GatewayClass::TJunction, GatewayClass::LTJunction,
    GatewayClass::RTJunction, GatewayClass::LTurn,    GatewayClass::RTurn,
    GatewayClass::DeadEnd,   GatewayClass::Hallway};

// The thesis' names: "X-Crossing", "T-Junction", "LT-Junction", "RT-Junction", "L-Turn",
// "R-Turn", "Deadend", "Hallway".
std::string_view gatewayClassName(GatewayClass c);

struct GatewayOpenings {
  bool left = false;
  bool straight = false;
  bool right = false;
};

GatewayOpenings openingsOf(GatewayClass c);

// False for the two counter-classes (Deadend, Hallway): no transition between regions.
bool isTransition(GatewayClass c);

}  // namespace rgnav
