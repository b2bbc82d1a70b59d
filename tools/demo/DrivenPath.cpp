// The navigating demo's driven path (see DrivenPath.h).
#include "tools/demo/DrivenPath.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/common/AtomicFile.h"
#include "core/rgmap/export/RgMapPng.h"
#include "core/rgmap/export/RgMapSvg.h"
#include "tools/plan/PlanPicture.h"

namespace rgnav {
namespace {

constexpr Rgb kPathColour{200, 30, 30};

std::vector<MapPolyline> pathOverlay(const DrivenPath& path) {
  std::vector<Eigen::Vector2d> points;
  for (const PoseUpdate& p : path.poses) points.push_back({p.corrected.x, p.corrected.y});
  return {{points, kPathColour, 0.05, 0.0, "driven-path"}};
}

}  // namespace

double DrivenPath::lengthM() const {
  double length = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i)
    length += std::hypot(poses[i].corrected.x - poses[i - 1].corrected.x, poses[i].corrected.y - poses[i - 1].corrected.y);
  return length;
}

DrivenPath fetchDrivenPath(ScanMapperClient& scanMapper, DataId firstId) {
  const DataId last = scanMapper.latestCorrectedId();
  DrivenPath path;
  for (DataId next = firstId; next <= last;) {
    const std::vector<PoseUpdate> portion = scanMapper.poses(next, last);
    if (portion.empty()) break;
    path.poses.insert(path.poses.end(), portion.begin(), portion.end());
    next = portion.back().id + 1;
  }
  return path;
}

void writeDrivenPathJson(const std::string& file, const DrivenPath& path) {
  nlohmann::json poses = nlohmann::json::array();
  for (const PoseUpdate& p : path.poses)
    poses.push_back({{"scan", p.id}, {"x", p.corrected.x}, {"y", p.corrected.y}, {"theta", p.corrected.theta}});
  const nlohmann::json document{{"frame", "map"}, {"length_m", path.lengthM()}, {"poses", poses}};
  writeFileAtomically(file, document.dump(1) + "\n");
}

void writeDrivenPathPictures(const std::string& base, const PlanningMap& map, const DrivenPath& path) {
  const RgMapSnapshot snapshot = snapshotOf(map);
  writeRgMapSvg(base + ".svg", snapshot, pathOverlay(path));
  exportRgMapPng(base + ".png", snapshot, 0.05, pathOverlay(path));
}

}  // namespace rgnav
