// ScanBeams: the beams of a laser scan the measurement model uses: at most BeamModelConfig::beams
// beams evenly spread over the scan, only those with a return shorter than maxRangeM, as end
// points in the robot frame (the laser sits at the robot's pose, as everywhere in RG Nav).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/SensorData.h"
#include "core/nav/localization/MclConfig.h"

namespace rgnav {

struct ScanBeams {
  std::vector<Eigen::Vector2d> endpoints;  // robot frame
};

ScanBeams selectBeams(const LaserScan& scan, const BeamModelConfig& config);

}  // namespace rgnav
