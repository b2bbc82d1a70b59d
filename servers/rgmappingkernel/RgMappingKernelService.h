// RgMappingKernelService: the RG Mapping Kernel module's work behind its servant (thesis 5.2):
// follows the ScanMapper's corrected scans and pose revisions and the GatewayDetection module's
// events by ID through their client libraries and feeds them to the kernel core in the order of
// the mapping chain's contract (core/rgmap/feed/KernelFeed.h), as the in-process chain does
// (tests/eval/rooms MappingPipeline). So the map does not depend on the modules' timing, also
// across restarts of either module. Only a kernel that lags so far that the ScanMapper no longer
// keeps a revision (SlamConfig graph.keptRevisions) or a scan (its buffer) maps differently: it
// takes the latest poses instead and counts it (health "pose_revisions_replaced"; revisions it
// never learned of: "pose_revisions_not_kept"). It tells
// the ScanMapper which revision its last checkpoint holds, so that the ScanMapper keeps only the
// revisions after it (RevisionFollowers.h). It checkpoints the map atomically after every batch
// that changed its structure, after every name, merge or undone merge, at least every `checkpointScans` scans,
// and at the end, with the scans' laser data in a journal beside it (`checkpointFile`.scans,
// RgMapCodec.h): each checkpoint appends the new scans to the journal, then replaces the map. The
// files are written by a thread of their own (CheckpointWriter.h), so no call waits for them but
// a name's (nameRegion, nameObject): it answers once its checkpoint is written (or failed), since
// a user's name is given once and a kill before the write would lose it. One that cannot be
// written degrades the module and is retried with backoff.
// After a restart it resumes after the last scan, event and pose revision the checkpoint holds.
// Names, merges, undone merges and door states carry request IDs and act once per ID (RequestLog.h).
// Gateway traversals the Localization module confirms (thesis 5.3) are checked against the map
// and counted, once per request ID; the map itself does not take them in yet.
#pragma once

#include <mutex>
#include <string>

#include "clientlibs/gatewaydetection/GatewayDetectionClient.h"
#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "core/rgmap/feed/KernelFeed.h"
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
  // Names, name removals, merges and undone merges act once per requestId: a repeated ID gets the first answer.
  void nameRegion(std::uint64_t requestId, RegionId id, const std::string& name);
  RegionId regionByName(const std::string& name);
  void nameObject(std::uint64_t requestId, RegionId region, const Eigen::Vector2d& atInRegion, const std::string& name);
  // Throws NotAvailableError if no object has the name.
  RgMappingKernel::NamedObject objectByName(const std::string& name);
  RegionId mergeRegions(std::uint64_t requestId, RegionId a, RegionId b, bool force);
  RegionId unmergeRegions(std::uint64_t requestId, RegionId merged);
  // A door found open or blocked (RgMappingKernel::recordDoorState), once per requestId.
  void reportDoorState(std::uint64_t requestId, GatewayId door, bool traversable);
  // A traversal the Localization module confirmed: counted (health "traversals_reported"), once
  // per requestId. InvalidArgumentError for a gateway the map does not have or regions that are
  // not its sides.
  void reportTraversal(std::uint64_t requestId, GatewayId gateway, RegionId from, RegionId to, DataId scanId);
  RgMapEventBatch eventsSince(RgMapEventId afterId, std::size_t maxCount);
  // What an export writes, taken under the lock (the files are written outside it).
  MapExportData exportData(bool occupancy);

 private:
  bool followOnce();          // false when there was nothing new
  void publishCounters();     // under lock: the feed's counters as health figures
  void checkpoint();          // under lock: hands the checkpoint to the writer
  // Leaves out the input record the kernel failed on kAttemptsPerRecord times (InputFollower.h).
  std::string skipFailingRecord();

  RgMappingKernelServiceOptions options_;
  ScanMapperClient scanMapper_;
  GatewayDetectionClient detection_;
  ModuleHealth& health_;
  std::mutex mutex_;
  std::unique_ptr<RgMappingKernel> kernel_;
  RgMapEventId checkpointedEvent_ = 0;  // as of the last checkpoint handed to the writer
  DataId checkpointedScan_ = 0;
  RequestLog requests_;
  CheckpointWriter writer_;
  KernelFeed feed_;
  InputFollower follower_;  // last: it stops before the rest goes
};

}  // namespace rgnav
