// RgMappingKernelService: the RG Mapping Kernel module's work behind its servant (thesis 5.2):
// follows the ScanMapper's corrected scans and pose revisions and the GatewayDetection module's
// events by ID and feeds them to the kernel core in scan order - scan s with its pose as mapped,
// then the events scan s caused (GatewayEvent::scanId); a revision the ScanMapper made while it
// took in scan s revises the kernel's scans with that revision's poses just before scan s - and,
// once the input ended, the ScanMapper's final poses. So the kernel's inputs, and the map, do not
// depend on the modules' timing: the server set maps a log as the in-process chain does
// (tests/eval/rooms MappingPipeline), also across restarts of either module (a revision a
// restarted ScanMapper has not made again yet is waited for). Only a kernel that lags so far
// that the ScanMapper no longer keeps a revision (SlamConfig graph.keptRevisions) or a scan (its
// buffer) maps differently: it takes the latest poses instead and counts it (health
// "pose_revisions_replaced"; revisions it never learned of: "pose_revisions_not_kept"). It tells
// the ScanMapper which revision its last checkpoint holds, so that the ScanMapper keeps only the
// revisions after it (RevisionFollowers.h). It checkpoints the map atomically after every batch
// that changed its structure, after every name or merge, at least every `checkpointScans` scans,
// and at the end, with the scans' laser data in a journal beside it (`checkpointFile`.scans,
// RgMapCodec.h): each checkpoint appends the new scans to the journal, then replaces the map. The
// files are written by a thread of their own (CheckpointWriter.h), so no call waits for them.
// After a restart it resumes after the last scan, event and pose revision the checkpoint holds.
// Names and merges carry request IDs and act once per ID (RequestLog.h).
#pragma once

#include <deque>
#include <mutex>
#include <optional>
#include <string>

#include "clientlibs/gatewaydetection/GatewayDetectionClient.h"
#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "core/rgmap/kernel/RgMapViews.h"
#include "servers/common/InputFollower.h"
#include "servers/common/RequestLog.h"
#include "servers/rgmappingkernel/CheckpointWriter.h"
#include "servers/rgmappingkernel/MapExport.h"

namespace rgnav {

struct RgMappingKernelServiceOptions {
  std::string checkpointFile;         // empty: no checkpoints; the scan journal lies beside it
  std::uint32_t fetchBatch = 100;     // records asked from each input per call
  std::size_t checkpointScans = 500;  // at most this many scans between checkpoints
};

class RgMappingKernelService {
 public:
  // Loads the checkpoint if there is one (FormatError if it is damaged: the module then fails at
  // start and the operator decides). Does not contact other modules yet.
  RgMappingKernelService(const RgMappingKernelConfig& config, const ClientSettings& settings,
                         const std::string& scanMapperObject, const std::string& detectionObject,
                         RgMappingKernelServiceOptions options, ModuleHealth& health);
  ~RgMappingKernelService();

  void start();
  void stop();

  MapSummaryView summary();
  RegionView currentRegion();
  RegionView region(RegionId id);
  std::vector<RegionSummaryView> regions();
  std::vector<GatewayView> gateways();
  GraphView graph();
  PathView findPath(const RgPlace& start, const RgPlace& goal);
  // Names, name removals and merges act once per requestId: a repeated ID gets the first answer.
  void nameRegion(std::uint64_t requestId, RegionId id, const std::string& name);
  RegionId regionByName(const std::string& name);
  void nameObject(std::uint64_t requestId, RegionId region, const Eigen::Vector2d& atInRegion, const std::string& name);
  // Throws NotAvailableError if no object has the name.
  RgMappingKernel::NamedObject objectByName(const std::string& name);
  RegionId mergeRegions(std::uint64_t requestId, RegionId a, RegionId b);
  RgMapEventBatch eventsSince(RgMapEventId afterId, std::size_t maxCount);
  // What an export writes, taken under the lock (the files are written outside it).
  MapExportData exportData(bool occupancy);

 private:
  bool followOnce();          // false when there was nothing new
  bool fetchScans();          // true when scans came
  bool fetchRevisions();      // true when revisions came
  bool fetchEvents();         // true when events came
  // Under lock: feeds scans and events in order up to the next revision to apply, and returns
  // that one; `fed` becomes true when something was fed.
  std::optional<PoseRevisionInfo> mapPending(bool& fed);
  // The poses of the kernel's scans after a revision, or the latest ones (nullopt).
  std::vector<CorrectedPose> posesOfKernelScans(std::optional<std::uint64_t> revision);
  // Applies the revision (false: the ScanMapper, restarted, has not made it again yet).
  bool applyRevision(const PoseRevisionInfo& revision);
  void applyFinalPoses();     // once the input ended: the ScanMapper's final poses
  Pose2D correctedPoseOf(DataId scan) const;  // under lock; the kernel's pose of a scan it holds
  void checkpoint();          // under lock: hands the checkpoint to the writer
  // Leaves out the input record the kernel failed on kAttemptsPerRecord times (InputFollower.h).
  std::string skipFailingRecord();

  RgMappingKernelServiceOptions options_;
  ScanMapperClient scanMapper_;
  GatewayDetectionClient detection_;
  ModuleHealth& health_;
  std::mutex mutex_;
  std::unique_ptr<RgMappingKernel> kernel_;
  std::deque<CorrectedScan> scans_;    // fetched, not fed yet
  std::deque<PoseRevisionInfo> revisions_;  // known, not applied yet
  std::deque<GatewayEvent> events_;    // fetched, not fed yet
  DataId detectionLastScan_ = 0;       // the detector has processed every scan up to this one
  bool scansEnded_ = false, eventsEnded_ = false, finished_ = false;
  enum class Feeding { Nothing, Scan, Event, Revision, FinalPoses };
  Feeding feeding_ = Feeding::Nothing;  // what the kernel is being fed
  RgMapEventId checkpointedEvent_ = 0;  // as of the last checkpoint handed to the writer
  DataId checkpointedScan_ = 0;
  RequestLog requests_;
  CheckpointWriter writer_;
  InputFollower follower_;  // last: it stops before the rest goes
};

}  // namespace rgnav
