// Strict YAML reading of the Collision Avoidance's parameters (see CollisionAvoidanceConfigYaml.h).
#include "core/nav/avoidance/CollisionAvoidanceConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

// describe() lists every field (CollisionAvoidanceConfigYaml.h): a field added to a struct stops
// the build here until it is listed there and in config/modules/collisionavoidance.yaml.
static_assert(sizeof(LaserObstacleMapConfig) == 11 * sizeof(double));
static_assert(sizeof(CandidateConfig) == 9 * sizeof(double) + 3 * sizeof(std::size_t));
static_assert(sizeof(GoalSeekingConfig) == 6 * sizeof(double));
static_assert(sizeof(CollisionAvoidanceConfig) == sizeof(LaserObstacleMapConfig) + sizeof(CandidateConfig) +
                                                      sizeof(GoalSeekingConfig) + 13 * sizeof(double));

CollisionAvoidanceConfig parseCollisionAvoidanceConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<CollisionAvoidanceConfig>(yamlText, path,
                                                [](const CollisionAvoidanceConfig& config) { validate(config); });
}

CollisionAvoidanceConfig loadCollisionAvoidanceConfig(const std::string& file) {
  return parseCollisionAvoidanceConfig(readConfigFile(file), file);
}

}  // namespace rgnav
