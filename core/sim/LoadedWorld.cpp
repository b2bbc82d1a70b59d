// Loading simulator worlds by file kind (see LoadedWorld.h).
#include "core/sim/LoadedWorld.h"

#include <yaml-cpp/yaml.h>

#include <filesystem>

#include "core/common/Errors.h"
#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/IpaGroundTruth.h"
#include "core/sim/world/MapServerYaml.h"
#include "core/sim/world/VectorWorldGroundTruth.h"
#include "core/sim/world/VectorWorldRaster.h"
#include "core/sim/world/VectorWorldYaml.h"

namespace fs = std::filesystem;

namespace rgnav {

IpaFiles ipaFilesOf(const std::string& floorPlanPath) {
  const fs::path path(floorPlanPath);
  std::string base = path.stem().string();
  if (const auto at = base.rfind("_furnitures"); at != std::string::npos) base = base.substr(0, at);
  const fs::path dir = path.parent_path();
  return {path.stem().string(), (dir / (base + ".png")).string(), (dir / (base + "_gt_segmentation.png")).string()};
}

LoadedWorld loadWorld(const std::string& path) {
  if (!fs::is_regular_file(path)) throw FileError(path + ": no such world file");
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".yaml" || ext == ".yml") {
    YAML::Node document;
    try {
      document = YAML::LoadFile(path);
    } catch (const YAML::Exception& e) {
      throw FormatError(path, e.mark.line + 1, e.what());
    }
    if (document.IsMap() && document["image"]) {
      MapServerWorld map = loadMapServerWorld(path);
      return {std::move(map.grid), std::nullopt, std::move(map.task)};
    }
    const VectorWorld world = loadVectorWorld(path);
    OccupancyGrid grid = rasterize(world);
    GroundTruth truth = groundTruthOf(world, grid);
    return {std::move(grid), std::move(truth), std::nullopt};
  }
  LoadedWorld loaded{loadFloorPlan(path), std::nullopt, std::nullopt};
  const IpaFiles ipa = ipaFilesOf(path);
  if (fs::exists(ipa.truth) && fs::exists(ipa.empty)) loaded.truth = loadIpaGroundTruth(ipa.truth, ipa.empty, loaded.grid);
  return loaded;
}

}  // namespace rgnav
