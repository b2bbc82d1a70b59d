// HallwayScenarios: the environment table, seeded listing, and the assembly of one scenario.
#include "core/sim/scenarios/HallwayScenarios.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"
#include "core/sim/scenarios/HallwayLayout.h"

namespace rgnav {

namespace {

constexpr double kLaneMargin = 0.05;  // m beyond the robot radius kept free of clutter

double maxStartDistance(const HallwayScenarioConfig& c) {
  return *std::max_element(c.startDistances.begin(), c.startDistances.end());
}

double maxOffsetFraction(const HallwayScenarioConfig& c) {
  double m = 0.0;
  for (const double f : c.lateralOffsetFractions) {
    m = std::max(m, std::abs(f));
  }
  return m;
}

}  // namespace

const std::array<HallwayEnvironment, 8>& thesisEnvironments() {
  static const std::array<HallwayEnvironment, 8> environments = {{
      {"2m uncluttered", 2.0, ClutterLevel::None},
      {"2m slightly cluttered", 2.0, ClutterLevel::Slight},
      {"2m strongly cluttered", 2.0, ClutterLevel::Strong},
      {"2.5m uncluttered", 2.5, ClutterLevel::None},
      {"2.5m slightly cluttered", 2.5, ClutterLevel::Slight},
      {"2.5m strongly cluttered", 2.5, ClutterLevel::Strong},
      {"3m uncluttered", 3.0, ClutterLevel::None},
      {"3m slightly cluttered", 3.0, ClutterLevel::Slight},
  }};
  return environments;
}

void validate(const HallwayScenarioConfig& c) {
  if (c.startDistances.empty() || c.lateralOffsetFractions.empty()) {
    throw ConfigError("hallway scenarios need at least one start distance and one lateral offset");
  }
  for (const double d : c.startDistances) {
    requirePositive(d, "approach start distance");
  }
  for (const double f : c.lateralOffsetFractions) {
    if (!(std::abs(f) <= 1.0)) {
      throw ConfigError("lateral offset fractions must lie in [-1, 1]");
    }
  }
  requirePositive(c.sampleSpacing, "approach sample spacing");
  requirePositive(c.approachMargin, "approach margin");
  requirePositive(c.armLength, "hallway arm length");
  requirePositive(c.resolution, "grid resolution");
  requirePositive(c.wallThickness, "wall thickness");
  requirePositive(c.robotRadius, "robot radius");
}

std::vector<ScenarioSpec> scenarioSet(std::uint64_t seed, int layoutsPerClass) {
  if (layoutsPerClass < 1) {
    throw InvalidArgumentError("scenarioSet: at least one layout per class");
  }
  std::mt19937_64 rng(seed);
  std::vector<ScenarioSpec> specs;
  for (const HallwayEnvironment& environment : thesisEnvironments()) {
    for (const GatewayClass c : kGatewayClasses) {
      for (int layout = 0; layout < layoutsPerClass; ++layout) {
        specs.push_back({environment, c, rng()});
      }
    }
  }
  return specs;
}

HallwayScenario buildScenario(const ScenarioSpec& spec, const HallwayScenarioConfig& config) {
  validate(config);
  const double width = spec.environment.width;
  const double h = width / 2.0;
  const double maxOffset = maxOffsetFraction(config) * h;
  const double laneHalfWidth = maxOffset + config.robotRadius + kLaneMargin;
  if (laneHalfWidth > h) {
    throw ConfigError("approach lanes do not fit into a " + spec.environment.name + " hallway");
  }
  const double farthest = maxStartDistance(config);
  if (farthest <= h) {
    throw ConfigError("approach start distances must lie beyond the gateway area");
  }
  const HallwayLayout layout =
      makeHallwayLayout(spec.gatewayClass, width, farthest - h + config.approachMargin, config.armLength);

  HallwayScenario scenario;
  scenario.spec = spec;
  scenario.gatewayCentre = {0.0, 0.0};
  scenario.world = rasterize(layout, config.resolution, config.wallThickness);
  const WorldRect lanes{-farthest - config.robotRadius - kLaneMargin, -laneHalfWidth,
                        -h + config.robotRadius + kLaneMargin, laneHalfWidth};
  std::mt19937_64 rng(spec.seed);
  scenario.clutter = placeClutter(layout, spec.environment.clutter, lanes, rng);
  drawClutter(scenario.world, scenario.clutter);
  for (const double distance : config.startDistances) {
    for (const double fraction : config.lateralOffsetFractions) {
      scenario.approaches.push_back(
          makeApproach(spec.gatewayClass, width, distance, fraction * h, config.sampleSpacing));
    }
  }
  return scenario;
}

}  // namespace rgnav
