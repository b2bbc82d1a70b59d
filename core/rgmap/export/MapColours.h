// The colours of the RG Map pictures, shared by the SVG and the PNG export so that both look the
// same: a pale colour per region for its freespace, chosen from its ID alone (hues spaced by the
// golden angle, so neighbouring IDs differ clearly and a region keeps its colour however the map
// grows), and fixed colours for line maps, gateways and the RG Graph.
#pragma once

#include <cstdint>
#include <string>

#include "core/rgmap/graph/RgGraphKeys.h"

namespace rgnav {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;

  friend bool operator==(const Rgb&, const Rgb&) = default;
};

inline constexpr Rgb kBackgroundColour{255, 255, 255};
inline constexpr Rgb kLineColour{40, 40, 40};         // line maps
inline constexpr Rgb kDoorColour{255, 140, 0};        // narrow passages (doors)
inline constexpr Rgb kHallwayAreaColour{0, 110, 200};  // hallway areas (turns, junctions, crossings)
inline constexpr Rgb kNeutralisedColour{150, 150, 150};  // gateways with one region on both sides
inline constexpr Rgb kCrossingColour{0, 0, 0};        // crossing points
inline constexpr Rgb kGraphColour{220, 0, 0};         // RG Graph edges
inline constexpr Rgb kLabelColour{0, 0, 0};
inline constexpr Rgb kObjectColour{120, 60, 160};     // 2D objects

// The freespace colour of region `id`.
Rgb regionColour(RegionId id);

// The colour of a gateway's line or square.
Rgb gatewayColour(bool door, bool neutralised);

// "#rrggbb".
std::string hexColour(const Rgb& c);

}  // namespace rgnav
