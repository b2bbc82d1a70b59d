// LocalizationService: the Localization module's work behind its servant (thesis 5.3): follows the
// Laser module's scans (with their odometry poses) by ID, keeps a copy of the RG Mapping Kernel's
// map (KernelMapCopy.h) as the LocalizationMap the region MCL (RegionMcl.h) weighs particles on,
// runs the filter on every scan and keeps the estimate of each scan in a bounded history (between
// filter updates the last update's estimate moved on by the odometry). Gateway traversals the
// filter confirms are reported to the kernel as evidence (RGMappingKernel::reportTraversal).
// It asks only for scans the Laser has (never for the next one, which would advance a lock-step
// simulator: the mapping chain paces it, as in the demo set). Until setPose or relocalize (or a
// checkpoint) gives it particles it only follows the Laser's latest scan ID; with `startAtOdometry` the first scan's odometry pose (once the map has a region) is
// its initial guess - right where the map frame is the ScanMapper's, which starts at the first
// scan's odometry pose, as in the demo set. With `mappedScansOnly` (the demo set, where the map is
// made online while the simulator runs many times faster than real time) it takes only scans the
// kernel has mapped (its summary's lastScan), refreshing its map copy as soon as it has taken all
// of them: a scan is weighed on a map that holds its surroundings, not on one that lags behind.
// Checkpoints: the particle set of the last filter update and that update's scan
// (ParticleSetCodec.h), written atomically at most once per checkpointIntervalS (less often as
// writes take longer, CheckpointPacer.h); one that cannot be written degrades the module and is
// retried with backoff (CheckpointRetry.h). After a restart the module waits for the map to hold
// the particles' regions, sets the particles and takes that scan again as its odometry reference
// (weighing it a second time), then the scans after it. If the Laser no longer holds that scan it
// goes on from the oldest it holds; the motion in between is then lost and the filter must
// recover from it like from a large odometry error.
// One lock guards the filter, the map copy's LocalizationMap and the history; calls to the other
// modules are made outside it.
#pragma once

#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <string>

#include "clientlibs/laser/LaserClient.h"
#include "clientlibs/localization/LocalizationViews.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/nav/localization/ParticleSetCodec.h"
#include "servers/common/CheckpointPacer.h"
#include "servers/common/CheckpointRetry.h"
#include "servers/common/InputFollower.h"
#include "servers/localization/KernelMapCopy.h"

namespace rgnav {

struct LocalizationServiceOptions {
  std::string checkpointFile;         // empty: no checkpoints
  std::uint32_t fetchBatch = 20;      // scans asked from the Laser module per call
  double checkpointIntervalS = 1.0;   // at least this long between checkpoints (CheckpointPacer.h)
  double mapRefreshS = 1.0;           // the kernel's summary is asked at most this often
  std::size_t historyScans = 10000;   // estimates kept for estimateByScan
  bool startAtOdometry = false;       // the first scan's odometry pose is the initial guess (see above)
  bool mappedScansOnly = false;       // take only scans the kernel has mapped (see above)
  Eigen::Vector3d startSigma{0.1, 0.1, 0.05};
  std::uint64_t seed = 1;
};

class LocalizationService {
 public:
  // Loads the checkpoint if there is one (FormatError if it is damaged: the module then fails at
  // start and the operator decides). Does not contact other modules yet.
  LocalizationService(const MclConfig& config, const ClientSettings& settings, const std::string& laserObject,
                      const std::string& kernelObject, LocalizationServiceOptions options, ModuleHealth& health);
  ~LocalizationService();

  void start();
  void stop();

  // NotLocalizedError without particles or before the first scan weighed after setPose/relocalize.
  ScanEstimate latestEstimate();
  // Also NotAvailableError for a scan not in the history.
  ScanEstimate estimateByScan(DataId scanId);
  ParticleSnapshotView particles(std::size_t maxCount);
  // InvalidArgumentError for a non-finite pose or a negative or non-finite sigma; NotAvailableError
  // without a map or when no region holds the pose.
  void setPose(const Pose2D& mapPose, const Eigen::Vector3d& sigma, RegionId hint);
  // NotAvailableError while the map has no freespace.
  void relocalize();
  LocalizationStateView state();

 private:
  bool followOnce();             // false when there was nothing new
  // Kernel errors are the health error "kernel", not the scans'. `now`: whatever the refresh period.
  void refreshMapIfDue(bool now);
  void applyMap(const KernelMapChanges& changes);  // under lock
  bool resumeIfDue();            // under lock: false while the checkpoint waits for the map
  void take(const LaserScan& scan);  // under lock
  void reportTraversals();       // to the kernel, outside the lock
  void checkpoint();             // under lock
  std::string skipFailingScan();  // the scan the filter failed on kAttemptsPerRecord times
  void requireLocalized() const;  // under lock
  std::vector<Particle> globalParticles();  // under lock: particles for a global localization

  const MclConfig config_;
  LocalizationServiceOptions options_;
  ModuleHealth& health_;
  LaserClient laser_;
  RgMappingKernelClient kernel_;
  KernelMapCopy copy_;
  std::chrono::steady_clock::time_point nextRefresh_{};

  std::mutex mutex_;
  LocalizationMap map_;
  RegionMcl mcl_;  // weighs on map_
  std::mt19937_64 rng_;
  RgMapEventId mapRevision_ = 0;
  std::optional<ParticleSetCheckpoint> resume_;  // loaded, not yet applied
  DataId lastScan_ = 0;
  DataId processing_ = 0, skipScan_ = 0;
  std::optional<PoseEstimate> lastUpdate_;  // of the last filter update since the particles were set
  Pose2D lastUpdateOdometry_;
  std::map<DataId, ScanEstimate> history_;
  std::uint64_t updates_ = 0, traversalsReported_ = 0;
  std::vector<ConfirmedTraversal> pendingTraversals_;
  bool started_ = false;  // startAtOdometry: the initial guess was made
  CheckpointPacer pacer_;
  CheckpointRetry retry_;
  InputFollower follower_;  // last: it stops before the rest goes
};

}  // namespace rgnav
