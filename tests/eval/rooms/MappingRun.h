// mapRoomTour: one map of the room evaluation (issue 7, "rgctl eval rooms") produced in process:
// the simulator drives the standard room tour (driveRoomTour: every ground-truth room) and every
// scan goes, as the Laser module would serve it, through the MappingPipeline (SLAM -> gateway
// detection -> RG Mapping Kernel); the pipeline revises the kernel's poses after every SLAM
// optimisation and at the end, and the final RG Map is taken as the kernel module would serve it
// (FinalMap.h). The map frame is the SLAM frame, which the first keyframe fixes at the first
// scan's odometry pose; mapToWorld puts it into the simulator's world frame by the first scan's
// true pose (the robot starts with its odometry at its true pose, so this is the identity up to
// the first scan's odometry noise).
// Nothing the simulator knows about the truth reaches the pipeline: each scan's sensorPose (the
// simulator's true laser pose) is replaced by its odometry pose, as in a raw log. Only with
// truePoses (to measure what SLAM errors cost) does the kernel get each scan's true pose as its
// corrected pose, in place of SLAM; the gateway detector still works on odometry.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "core/sim/GroundTruth.h"
#include "core/sim/TourRun.h"
#include "tests/eval/rooms/FinalMap.h"
#include "tests/eval/rooms/MappingPipeline.h"

namespace rgnav {

struct MappingRunSetup {
  MappingPipelineConfig pipeline;
  SimulationConfig simulation;
  double maxTourSeconds = kRoomTourMaxSeconds;  // simulated; a shorter tour for smoke runs
  bool truePoses = false;                       // the kernel gets true poses, SLAM is not run
  // Called with the kernel once the tour is mapped (e.g. to take its RG graph or occupancy map).
  std::function<void(const RgMappingKernel&)> atEnd;
};

// How far the final corrected poses, placed by mapToWorld, lie from the true ones (positions).
struct PoseErrors {
  double meanM = 0.0;
  double maxM = 0.0;
};

// The map frame in the world frame, fixed by the first scan (its true pose times its corrected
// pose's inverse), and the pose errors of all scans so placed; corrected[i] and truePoses[i] are
// scan i + 1's, and both are non-empty and of one length.
struct WorldPlacement {
  Pose2D mapToWorld;
  PoseErrors errors;
};
WorldPlacement placeInWorld(const std::vector<Pose2D>& corrected, const std::vector<Pose2D>& truePoses);

struct MappingRun {
  FinalMap map;
  Pose2D mapToWorld;  // the map frame's pose in the world frame
  PoseErrors poseErrors;
  TourRunResult tour;
  std::vector<int> unreachableRooms;  // of the tour plan: no free path from the start
  MappingCounts counts;
  double mappingSeconds = 0.0;  // wall time spent in the pipeline and taking the final map
  std::vector<Eigen::Vector2d> truePath;  // true robot positions at the scans, index = scan ID - 1
  std::map<RegionId, std::vector<DataId>> regionScans;  // the scans each final region holds
};

// Throws what the simulator, the tour planner and the pipeline throw.
MappingRun mapRoomTour(const OccupancyGrid& grid, const GroundTruth& truth, const MappingRunSetup& setup,
                       const std::optional<HmmClassifier>& classifier);

}  // namespace rgnav
