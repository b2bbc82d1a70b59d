// The Collision Avoidance module's pose sources (see MapFrame.h).
#include "servers/collisionavoidance/MapFrame.h"

#include "core/common/Errors.h"

namespace rgnav {

PoseSource parsePoseSource(const std::string& text) {
  if (text == "odometry") return PoseSource::Odometry;
  if (text == "groundtruth") return PoseSource::GroundTruth;
  if (text == "scanmapper") return PoseSource::ScanMapper;
  if (text == "localization") return PoseSource::Localization;
  throw ConfigError("--pose-source is odometry, groundtruth, scanmapper or localization, not '" + text + "'");
}

}  // namespace rgnav
