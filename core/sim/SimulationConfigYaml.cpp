// Strict YAML reading of the simulator's parameters (see SimulationConfigYaml.h).
#include "core/sim/SimulationConfigYaml.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/config/ConfigNode.h"

namespace rgnav {

namespace {

constexpr double kDegree = M_PI / 180.0;

// Sets `target` from node[key] if the key is there.
void read(const ConfigNode& node, const std::string& key, double& target, double scale = 1.0) {
  if (node.has(key)) target = node[key].asDouble() * scale;
}

Footprint readFootprint(const ConfigNode& node) {
  node.expectKeys({"shape", "radius_m", "length_m", "width_m", "center_offset_m"});
  const std::string shape = node["shape"].asString();
  Footprint footprint;
  if (shape == "disk") {
    if (node.has("length_m") || node.has("width_m") || node.has("center_offset_m"))
      node.fail("a disk has radius_m only");
    footprint = Footprint::disk(node["radius_m"].asDouble());
  } else if (shape == "rectangle") {
    if (node.has("radius_m")) node.fail("a rectangle has length_m, width_m and center_offset_m, not radius_m");
    footprint = Footprint::rectangle(node["length_m"].asDouble(), node["width_m"].asDouble());
    read(node, "center_offset_m", footprint.centerOffset);
  } else {
    node["shape"].fail("is disk or rectangle, not '" + shape + "'");
  }
  try {
    validate(footprint);
  } catch (const ConfigError& e) {
    node.fail(e.what());
  }
  return footprint;
}

void readRobot(const ConfigNode& node, DiffDriveConfig& robot) {
  node.expectKeys({"radius_m", "footprint", "max_velocity_mps", "max_rotation_radps", "max_acceleration_mps2",
                   "max_rotation_acceleration_radps2"});
  if (node.has("radius_m") && node.has("footprint")) node.fail("give radius_m (a disk) or footprint, not both");
  if (node.has("radius_m")) robot.footprint = Footprint::disk(node["radius_m"].asDouble());
  if (node.has("footprint")) robot.footprint = readFootprint(node["footprint"]);
  read(node, "max_velocity_mps", robot.maxTranslationalVelocity);
  read(node, "max_rotation_radps", robot.maxRotationalVelocity);
  read(node, "max_acceleration_mps2", robot.maxTranslationalAcceleration);
  read(node, "max_rotation_acceleration_radps2", robot.maxRotationalAcceleration);
}

void readOdometry(const ConfigNode& node, OdometryNoiseConfig& odometry) {
  node.expectKeys({"alpha1", "alpha2", "alpha3", "alpha4", "translation_scale_error", "rotation_bias_rad_per_m"});
  read(node, "alpha1", odometry.alpha1);
  read(node, "alpha2", odometry.alpha2);
  read(node, "alpha3", odometry.alpha3);
  read(node, "alpha4", odometry.alpha4);
  read(node, "translation_scale_error", odometry.translationScaleError);
  read(node, "rotation_bias_rad_per_m", odometry.rotationBiasPerMetre);
}

void readLaser(const ConfigNode& node, LaserConfig& laser) {
  node.expectKeys({"field_of_view_deg", "resolution_deg", "max_range_m", "mounting_height_m", "forward_offset_m",
                   "range_noise_sigma_m", "dropout_probability"});
  read(node, "field_of_view_deg", laser.fieldOfView, kDegree);
  read(node, "resolution_deg", laser.angularResolution, kDegree);
  read(node, "max_range_m", laser.maxRange);
  read(node, "mounting_height_m", laser.mountingHeight);
  read(node, "forward_offset_m", laser.forwardOffset);
  read(node, "range_noise_sigma_m", laser.rangeNoiseSigma);
  read(node, "dropout_probability", laser.dropoutProbability);
}

void readPeople(const ConfigNode& node, PeopleConfig& people) {
  node.expectKeys({"count", "radius_m", "min_speed_mps", "max_speed_mps", "seed"});
  if (node.has("count")) people.count = static_cast<int>(node["count"].asInteger(0, 10000));
  read(node, "radius_m", people.radius);
  read(node, "min_speed_mps", people.minSpeed);
  read(node, "max_speed_mps", people.maxSpeed);
  if (node.has("seed")) people.seed = static_cast<std::uint64_t>(node["seed"].asInteger(0, INT64_MAX));
}

}  // namespace

SimulationConfig parseSimulationConfig(const std::string& yamlText) {
  YAML::Node document;
  try {
    document = YAML::Load(yamlText);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("not YAML: ") + e.what());
  }
  SimulationConfig config;
  if (document.IsNull()) return config;
  const ConfigVars noVariables;
  const ConfigNode root(document, "", noVariables);
  root.expectKeys({"step_s", "steps_per_scan", "seed", "robot", "odometry", "laser", "people"});
  read(root, "step_s", config.stepSeconds);
  if (root.has("steps_per_scan")) config.stepsPerScan = static_cast<int>(root["steps_per_scan"].asInteger(1, 1000));
  if (root.has("seed")) config.seed = static_cast<std::uint64_t>(root["seed"].asInteger(0, INT64_MAX));
  if (root.has("robot")) readRobot(root["robot"], config.robot);
  if (root.has("odometry")) readOdometry(root["odometry"], config.odometry);
  if (root.has("laser")) readLaser(root["laser"], config.laser);
  if (root.has("people")) readPeople(root["people"], config.people);
  validate(config);
  LaserModel{config.laser};  // validates the laser
  return config;
}

SimulationConfig loadSimulationConfig(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return parseSimulationConfig(text.str());
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

}  // namespace rgnav
