// The exploration strategies by name (ExplorationStrategy.h).
#include "core/nav/exploration/ExplorationStrategy.h"

#include "core/common/Errors.h"
#include "core/nav/exploration/NearestFrontierExploration.h"
#include "core/nav/exploration/RgExploration.h"

namespace rgnav {

std::unique_ptr<ExplorationStrategy> makeExplorationStrategy(const std::string& name, const ExplorationConfig& config) {
  if (name == "rg") return std::make_unique<RgExploration>(config);
  if (name == "frontier") return std::make_unique<NearestFrontierExploration>(config);
  throw ConfigError("unknown exploration strategy \"" + name + "\" (rg or frontier)");
}

}  // namespace rgnav
