// HallwayScenarios: the generated worlds and labelled approach poses for gateway classification
// (thesis 4.1.4). The thesis used eight environments that differ in hallway width (2, 2.5, 3 m)
// and clutter; it names "2m uncluttered" (figure 4.1), the slightly and strongly cluttered 2 m
// variants (figure 4.8), "2m/2.5m cluttered" and "3m uncluttered" (tables 4.2/4.3) without listing
// all eight. Our choice: every width uncluttered and slightly cluttered, and strongly cluttered
// at 2 m and 2.5 m (strong clutter matters most where hallways are narrow):
//   2m uncluttered, 2m slightly cluttered, 2m strongly cluttered,
//   2.5m uncluttered, 2.5m slightly cluttered, 2.5m strongly cluttered,
//   3m uncluttered, 3m slightly cluttered.
// A scenario is one gateway of one class in one environment: the world grid (gateway centre at
// the origin, approach along +x), its clutter, and the approaches from every start distance and
// lateral offset, all labelled. Scenario sets are listed deterministically from a seed; worlds
// are built on demand. The laser is rendered elsewhere (world/ raycaster).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/scenarios/ApproachTrajectory.h"
#include "core/sim/scenarios/Clutter.h"

namespace rgnav {

struct HallwayEnvironment {
  std::string name;  // e.g. "2m uncluttered"
  double width = 0.0;  // m
  ClutterLevel clutter = ClutterLevel::None;
};

// The eight environments above, in that order.
const std::array<HallwayEnvironment, 8>& thesisEnvironments();

struct ScenarioSpec {
  HallwayEnvironment environment;
  GatewayClass gatewayClass = GatewayClass::Hallway;
  std::uint64_t seed = 0;  // clutter placement
};

struct HallwayScenarioConfig {
  std::vector<double> startDistances{4.0, 6.0, 8.0, 10.0};  // m before the gateway centre
  // Lateral start offsets as fractions of half the hallway width (+-W/8 for +-0.25).
  std::vector<double> lateralOffsetFractions{-0.25, 0.0, 0.25};
  double sampleSpacing = 0.2;   // m between labelled poses
  double approachMargin = 2.0;  // m of approach hallway behind the farthest start
  double armLength = 8.0;       // m of each hallway leaving the gateway area
  double resolution = 0.05;     // m per cell (as the floor plans)
  double wallThickness = 0.3;   // m
  double robotRadius = 0.25;    // m; approach lanes of this radius (+5 cm) stay free of clutter
};

// Throws ConfigError for empty lists, non-positive lengths, fractions outside [-1, 1] or lanes
// that would not fit between the walls.
void validate(const HallwayScenarioConfig& config);

// Every environment x every gateway class x `layoutsPerClass` clutter layouts, environments
// outermost; the clutter seeds are drawn from std::mt19937_64(seed). Throws InvalidArgumentError
// for layoutsPerClass < 1.
std::vector<ScenarioSpec> scenarioSet(std::uint64_t seed, int layoutsPerClass);

struct HallwayScenario {
  ScenarioSpec spec;
  OccupancyGrid world;
  WorldPoint gatewayCentre;  // the origin of the gateway frame
  std::vector<ClutterObject> clutter;
  std::vector<Approach> approaches;  // start distances outer, lateral offsets inner
};

// Throws ConfigError for a bad configuration.
HallwayScenario buildScenario(const ScenarioSpec& spec, const HallwayScenarioConfig& config = {});

}  // namespace rgnav
