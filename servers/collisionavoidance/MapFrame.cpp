// The Collision Avoidance module's pose sources (see MapFrame.h).
#include "servers/collisionavoidance/MapFrame.h"

#include "core/common/Errors.h"

namespace rgnav {

PoseSource parsePoseSource(const std::string& text) {
  if (text == "odometry") return PoseSource::Odometry;
  if (text == "groundtruth") return PoseSource::GroundTruth;
  throw ConfigError("--pose-source is odometry or groundtruth, not '" + text + "'");
}

}  // namespace rgnav
