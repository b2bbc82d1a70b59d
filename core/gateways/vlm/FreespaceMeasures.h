// FreespaceMeasures: the measures of a VLM hypothesis with respect to a specific gateway class,
// thesis 4.1.2.2. The gateway points divide the scan into the left, front and right sector (the
// beams between the bearings of the pair of gateway points on the left, front and right line).
// Per sector, over its N_S beams:
//   On Line FSM:   W_on^S = C_ol / N_S, C_ol the beams whose range d(P_i) differs from the
//                  range d(P_i^vl) at which the beam meets the sector's virtual line by a value
//                  within [onLineLowerM, onLineUpperM];
//   Over Line FSM: W_over^S = C_over / N_S, C_over the beams that cross l_par, the line parallel
//                  to the sector's virtual line set back (away from the robot) by a distance.
// Both are computed for every sector; the gateway class picks one per sector (GatewayWeights).
// Where we differ:
// - The thesis applies Over Line only to the front sector; we also apply it to a side sector
//   whose hallway is open (with its own, smaller setback: seen from afar, the beams through a
//   side opening end just behind the side line), which is what tells L from R.
// - We divide by the beams of the sector that are not occluded (that do not end before the
//   virtual line, d(P_i) - d(P_i^vl) < onLineLowerM) instead of by all N_S beams: a person or a
//   box in front of a line says nothing about whether the line is a wall or an opening. This
//   changes no argmax over the classes (every sector is scaled for all of them alike), but makes
//   the weight vectors of cluttered and clear views alike, which the HMMs need (thesis 4.1.4:
//   "the recognition rate decreases in the presence of clutter").
// Beams without return cross every line ahead of them; invalid beams (NaN) are not counted.
#pragma once

#include <array>
#include <cstddef>

#include "core/common/SensorData.h"
#include "core/gateways/vlm/VlmHypotheses.h"

namespace rgnav {

enum class Sector : std::size_t { Left = 0, Front = 1, Right = 2 };
inline constexpr std::size_t kSectorCount = 3;

struct FreespaceParams {
  double onLineLowerM = -0.15;  // d(P_i) - d(P_i^vl), lower threshold
  double onLineUpperM = 0.15;   // upper threshold
  double frontSetbackM = 0.5;   // l_par behind the front line
  double sideSetbackM = 0.1;    // l_par behind the left or right line
};

template <class V>
void describe(V& v, FreespaceParams& c) {
  v.field("on_line_lower_m", c.onLineLowerM);
  v.field("on_line_upper_m", c.onLineUpperM);
  v.field("front_setback_m", c.frontSetbackM);
  v.field("side_setback_m", c.sideSetbackM);
}

struct SectorFreespace {
  std::array<double, kSectorCount> onLine{};    // W_on line per sector, indexed by Sector
  std::array<double, kSectorCount> overLine{};  // W_over line per sector
  std::array<std::size_t, kSectorCount> beams{};      // N_S
  std::array<std::size_t, kSectorCount> seenBeams{};  // N_S without the occluded beams

  double on(Sector s) const { return onLine[static_cast<std::size_t>(s)]; }
  double over(Sector s) const { return overLine[static_cast<std::size_t>(s)]; }
};

// `scan` in the sensor frame the hypothesis was made in. Throws InvalidArgumentError if the
// on-line thresholds are not ordered or a setback is negative.
SectorFreespace freespaceMeasures(const VlmHypothesis& vlm, const LaserScan& scan, const FreespaceParams& params = {});

}  // namespace rgnav
