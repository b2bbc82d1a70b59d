// mapOfRun: the RG map of a run made in process from its corrected poses, for the localization
// evaluation (issue 28): every scan goes through the mapping chain with its corrected pose
// given (tests/eval/rooms MappingPipeline::addScanAt: gateway detection on the raw odometry, the
// RG Mapping Kernel with the given poses), and the final regions and gateways are taken as the
// kernel module serves them (FinalMap.h). The map frame is the corrected poses' frame, so the
// localization's estimates compare directly with them.
#pragma once

#include <map>
#include <span>
#include <string>

#include "core/common/SensorData.h"
#include "tests/eval/rooms/FinalMap.h"

namespace rgnav {

struct RunMap {
  FinalMap map;
  std::map<DataId, RegionId> scanRegions;  // the final region that holds each scan
  std::size_t gatewayEvents = 0;
  double seconds = 0.0;  // wall time of the mapping
};

// `scans`: in log order, each with its raw odometry and its corrected pose as sensorPose.
// `models`: the gateway HMMs (none if the file does not exist: narrow passages only). Throws
// what the pipeline throws.
RunMap mapOfRun(std::span<const LaserScan> scans, const std::string& models);

}  // namespace rgnav
