// A room tour mapped by the real server set; see ServerSetRun.h.
#include "tests/eval/rooms/ServerSetRun.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "core/sim/GroundTruthTour.h"
#include "core/sim/StartPose.h"
#include "tests/support/cluster/Interruption.h"
#include "tests/support/cluster/TestCluster.h"

namespace rgnav {
namespace {

using testing::ClusterModule;
using testing::TestCluster;
using testing::throwIfInterrupted;

std::string absolute(const std::string& path) { return std::filesystem::absolute(path).string(); }

std::vector<ClusterModule> mappingSet(const std::string& floorPlanPath, const ServerSetSetup& setup) {
  std::vector<std::string> simulator{TestCluster::program("rgnav-sim"), "--world", absolute(floorPlanPath), "--clock",
                                     "lockstep", "--tour", "--seed", std::to_string(setup.seed)};
  if (!setup.simConfig.empty()) simulator.insert(simulator.end(), {"--config", absolute(setup.simConfig)});
  std::vector<std::string> detection{TestCluster::program("rgnav-gatewaydetection"), "--config",
                                     TestCluster::moduleConfig("gatewaydetection")};
  if (!setup.models.empty()) detection.insert(detection.end(), {"--models", absolute(setup.models)});
  return {{"Simulator", simulator, {"Laser", "Base", "GroundTruth"}},
          {"ScanMapper", {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
           {"ScanMapper"},
           {"Simulator"}},
          {"GatewayDetection", detection, {"GatewayDetection"}, {"Simulator"}},
          {"RGMappingKernel",
           {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
           {"RGMappingKernel"},
           {"ScanMapper", "GatewayDetection"}}};
}

FinalMap finishedMap(RgMappingKernelClient& kernel, double limitSeconds) {
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::duration<double>(limitSeconds);
  while (!kernel.summary().endOfData) {
    throwIfInterrupted();
    if (std::chrono::steady_clock::now() > giveUp)
      throw std::runtime_error("the kernel module did not finish the map within " + std::to_string(limitSeconds) + " s");
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  FinalMap map;
  map.summary = kernel.summary();
  for (const RegionSummaryView& r : kernel.regions()) map.regions.push_back(kernel.region(r.id));
  std::sort(map.regions.begin(), map.regions.end(),
            [](const RegionView& a, const RegionView& b) { return a.summary.id < b.summary.id; });
  map.gateways = kernel.gateways();
  return map;
}

// Rooms visited: those the true path entered, of the rooms the planner visits.
TourRunResult tourOf(const Tour& plan, const GroundTruth& truth, const std::vector<Eigen::Vector2d>& path) {
  TourRunResult run;
  for (const Eigen::Vector2d& p : path)
    if (const int room = truth.roomAt({p.x(), p.y()}); room >= 0) run.roomsEntered.insert(room);
  for (const RoomVisit& visit : plan.visits)
    if (run.roomsEntered.contains(visit.room))
      run.roomsVisited.insert(visit.room);
    else
      run.roomsMissed.push_back(visit.room);
  run.scans = path.size();
  return run;
}

}  // namespace

MappingRun mapRoomTourOnServerSet(const std::string& floorPlanPath, const OccupancyGrid& grid, const GroundTruth& truth,
                                  const ServerSetSetup& setup) {
  TestCluster cluster(mappingSet(floorPlanPath, setup));
  const auto started = std::chrono::steady_clock::now();
  cluster.start();
  RgMappingKernelClient kernel(cluster.clientSettings());
  MappingRun out;
  out.map = finishedMap(kernel, setup.limitSeconds);
  out.mappingSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  const DataId last = out.map.summary.lastScan;
  ScanMapperClient mapper(cluster.clientSettings());
  GroundTruthClient world(cluster.clientSettings());
  std::vector<Pose2D> corrected(last), truePoses(last);
  for (DataId next = 1; next <= last;) {  // the module returns at most its cap per call
    const std::vector<PoseUpdate> batch = mapper.poses(next, last);
    if (batch.empty()) throw std::runtime_error("the ScanMapper has no pose for scan " + std::to_string(next));
    for (const PoseUpdate& p : batch)
      if (p.id >= 1 && p.id <= last) corrected[p.id - 1] = p.corrected;
    next = batch.back().id + 1;
  }
  for (DataId id = 1; id <= last; ++id) {
    truePoses[id - 1] = world.truePose(id);
    out.truePath.emplace_back(truePoses[id - 1].x, truePoses[id - 1].y);
  }
  if (last > 0) {
    const WorldPlacement placement = placeInWorld(corrected, truePoses);
    out.mapToWorld = placement.mapToWorld;
    out.poseErrors = placement.errors;
  }
  const Tour plan = planTour(grid, truth, openestPose(grid));  // as the Simulator module plans it
  out.tour = tourOf(plan, truth, out.truePath);
  out.unreachableRooms = plan.unreachableRooms;
  out.counts.scans = last;
  return out;
}

}  // namespace rgnav
