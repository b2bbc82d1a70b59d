// ScanMapperService: the ScanMapper module's work behind its servant (thesis 5.2): follows the
// Laser module by ID (as consumer "<module>"), feeds every scan to the SLAM core, keeps the
// scans it served for consumers (with their poses as mapped, and the poses of the revisions its
// followers may still need: ScanMapper.idl, RevisionFollowers.h), and checkpoints the SLAM state
// atomically at most once per checkpointIntervalS (less often as it grows) while mapping and at
// the end (DESIGN.md "State survives"; CheckpointPacer.h). A checkpoint that cannot be written
// degrades the module and is retried with backoff, also after the end (CheckpointRetry.h).
// After a restart it reloads the checkpoint, refills its scan buffer from the Laser module and
// goes on after the last scan the checkpoint holds: the mapper continues bit for bit as if it had
// not stopped, so no scan is lost, and the scans it maps again give the same corrected scans
// under the same IDs.
#pragma once

#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "clientlibs/laser/LaserClient.h"
#include "core/slam/CorrectedScans.h"
#include "core/common/DataBuffer.h"
#include "core/slam/ScanMapper.h"
#include "servers/common/CheckpointPacer.h"
#include "servers/common/CheckpointRetry.h"
#include "servers/common/InputFollower.h"
#include "servers/scanmapper/RevisionFollowers.h"

namespace rgnav {

struct ScanMapperServiceOptions {
  std::string checkpointFile;           // empty: no checkpoints
  std::size_t bufferCapacity = 20000;   // scans held for consumers
  std::uint32_t fetchBatch = 100;       // scans asked from the Laser module per call
  double checkpointIntervalS = 1.0;     // at least this long between checkpoints while mapping (CheckpointPacer.h)
  std::set<std::string> revisionFollowers{"RGMappingKernel"};  // whose revisionsSince calls count (RevisionFollowers.h)
};

class ScanMapperService {
 public:
  // Loads the checkpoint if there is one (CorruptStateError if it is damaged: the module then
  // fails at start and the operator decides). Does not contact the Laser module yet.
  ScanMapperService(const SlamConfig& config, const ClientSettings& laserSettings, const std::string& laserObject,
                    ScanMapperServiceOptions options, ModuleHealth& health);
  ~ScanMapperService();

  // Starts / stops the thread that follows the Laser module.
  void start();
  void stop();

  CorrectedBatch correctedSince(DataId afterId, std::size_t maxCount);
  // InvalidArgumentError for ID 0, NotAvailableError for a scan not mapped (yet).
  Pose2D correctedPose(DataId id);
  Pose2D odomToMap(DataId id, const Pose2D& odometryPose);
  // Current poses of scans first..last (at most cap of them).
  std::vector<PoseUpdate> poses(DataId first, DataId last, std::size_t cap);
  // The kept revisions after `afterRevision`, oldest first; `follower` (empty: anonymous) has
  // durably applied every revision up to it, and those every active follower is past are
  // forgotten (RevisionFollowers.h).
  std::vector<PoseRevisionInfo> revisionsSince(std::uint64_t afterRevision, const std::string& follower);
  // Poses of the scans first..last right after a kept revision (at most cap of them);
  // NotAvailableError for a revision not kept, InvalidArgumentError unless first <= last < its atScan.
  std::vector<PoseUpdate> revisedPoses(std::uint64_t revision, DataId first, DataId last, std::size_t cap);
  DataId latestCorrectedId();
  std::uint64_t revision();

 private:
  bool step();                  // refills the buffer once, then followOnce()
  bool followOnce();            // false when there was nothing new
  void refillBuffer();          // after a restart: the scans the checkpoint covers
  void keep(const LaserScan& scan);  // under lock
  // A scan the mapper failed on kAttemptsPerRecord times (InputFollower.h) is taken in without
  // its ranges (and with the odometry before it if its own is not finite).
  std::string skipFailingScan();
  void checkpoint();            // under lock

  ScanMapperServiceOptions options_;
  LaserClient laser_;
  ModuleHealth& health_;
  std::mutex mutex_;
  ScanMapper mapper_;
  RevisionFollowers followers_;
  CheckpointPacer pacer_;
  CheckpointRetry retry_;  // after a failed checkpoint
  DataBuffer<LaserScan> scans_;
  bool finished_ = false;  // the input ended and the final optimisation ran
  bool refilled_ = false;
  DataId processing_ = 0;       // the scan being taken in
  DataId skipScan_ = 0;         // the scan to take in without its ranges
  Pose2D previousOdometry_{};   // of the scan taken in last
  InputFollower follower_;  // last: it stops before the rest goes
};

}  // namespace rgnav
