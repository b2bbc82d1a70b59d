// The inverse of gatewayClassName (core/gateways/classes/GatewayClass.h): the thesis' class names
// ("X-Crossing", ..., "Hallway") back to GatewayClass, for model files and evaluation input.
#pragma once

#include <optional>
#include <string_view>

#include "core/gateways/classes/GatewayClass.h"

namespace rgnav {

// The class whose name is exactly `name`, or nullopt.
std::optional<GatewayClass> parseGatewayClass(std::string_view name);

}  // namespace rgnav
