// Colours of the RG Map pictures; see MapColours.h.
#include "core/rgmap/export/MapColours.h"

#include <cmath>
#include <cstdio>

namespace rgnav {
namespace {

constexpr double kGoldenRatioConjugate = 0.6180339887498949;
constexpr double kSaturation = 0.35, kValue = 0.97;

std::uint8_t channel(double v) { return std::uint8_t(std::lround(255.0 * v)); }

// HSV (hue in [0, 1)) to RGB.
Rgb fromHsv(double hue, double saturation, double value) {
  const double h = 6.0 * hue;
  const int sector = int(h) % 6;
  const double f = h - std::floor(h);
  const double p = value * (1.0 - saturation), q = value * (1.0 - saturation * f),
               t = value * (1.0 - saturation * (1.0 - f));
  const double rgb[6][3] = {{value, t, p}, {q, value, p}, {p, value, t}, {p, q, value}, {t, p, value}, {value, p, q}};
  return {channel(rgb[sector][0]), channel(rgb[sector][1]), channel(rgb[sector][2])};
}

}  // namespace

Rgb regionColour(RegionId id) {
  const double hue = std::fmod(0.08 + double(id.value() % 1000003) * kGoldenRatioConjugate, 1.0);
  return fromHsv(hue, kSaturation, kValue);
}

Rgb gatewayColour(bool door, bool neutralised) {
  if (neutralised) return kNeutralisedColour;
  return door ? kDoorColour : kHallwayAreaColour;
}

std::string hexColour(const Rgb& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

}  // namespace rgnav
