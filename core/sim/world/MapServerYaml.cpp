// loadMapServerYaml: strict map_server YAML reading, trinary thresholding and the task keys.
#include "core/sim/world/MapServerYaml.h"

#include "core/raster/ImageGrid.h"
#include "core/sim/world/WorldYaml.h"

namespace rgnav {
namespace {

// map_server writes 0/1; YAML booleans are accepted too.
bool readNegate(const ConfigNode& node) {
  const std::string text = node.asString();
  if (text == "0") return false;
  if (text == "1") return true;
  return node.asBool();
}

GrayToCell trinaryTable(bool negate, double occupiedThreshold, double freeThreshold) {
  GrayToCell table{};
  for (int gray = 0; gray < 256; ++gray) {
    const double occupancy = (negate ? gray : 255 - gray) / 255.0;
    table[gray] = occupancy > occupiedThreshold ? Cell::Occupied
                  : occupancy < freeThreshold   ? Cell::Free
                                                : Cell::Unknown;
  }
  return table;
}

}  // namespace

MapServerWorld loadMapServerWorld(const std::string& yamlPath) {
  return parseYamlFile(yamlPath, [&](const ConfigNode& root) {
    root.expectKeys({"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode", "start", "goal",
                     "reference_path_length_m", "cylinders"});
    const double resolution = readPositive(root["resolution"]);
    const Eigen::Vector3d origin = readPoint3(root["origin"]);
    if (origin.z() != 0.0) root["origin"].fail("a rotated map (yaw != 0) is not supported");
    const bool negate = root.has("negate") && readNegate(root["negate"]);
    const double occupiedThreshold = readFraction(root["occupied_thresh"]);
    const double freeThreshold = readFraction(root["free_thresh"]);
    if (freeThreshold >= occupiedThreshold) root["free_thresh"].fail("must be below occupied_thresh");
    if (root.has("mode") && root["mode"].asString() != "trinary") {
      root["mode"].fail("only mode trinary is supported");
    }
    const cv::Mat image = readReferencedImage(yamlPath, root["image"]);
    MapServerWorld world{gridFromImage(image, resolution, {origin.x(), origin.y()},
                                       trinaryTable(negate, occupiedThreshold, freeThreshold)),
                         std::nullopt};
    world.task = readNavigationTask(root, world.grid);
    return world;
  });
}

OccupancyGrid loadMapServerYaml(const std::string& yamlPath) { return loadMapServerWorld(yamlPath).grid; }

}  // namespace rgnav
