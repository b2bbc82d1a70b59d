// The RG Mapping Kernel module's follower, ordering and checkpoints (see RgMappingKernelService.h).
#include "servers/rgmappingkernel/RgMappingKernelService.h"

#include <algorithm>
#include <optional>

#include "core/common/AtomicFile.h"
#include "core/rgmap/kernel/RgMapCodec.h"

namespace rgnav {
namespace {

constexpr DataId kPoseChunk = 5000;  // poses asked per call when the ScanMapper revised them

// The scan journal beside the checkpoint file (RgMapCodec.h).
std::string journalOf(const std::string& checkpointFile) { return checkpointFile + ".scans"; }

RgMapState loadCheckpoint(const std::string& file) {
  const std::optional<std::string> saved = readCheckpoint(file);
  if (!saved) return {};
  try {
    return deserializeRgMap(*saved, readCheckpoint(journalOf(file)).value_or(""));
  } catch (const FormatError& e) {
    throw FormatError(file, 0, e.what());
  }
}

}  // namespace

RgMappingKernelService::RgMappingKernelService(const RgMappingKernelConfig& config, const ClientSettings& settings,
                                               const std::string& scanMapperObject, const std::string& detectionObject,
                                               RgMappingKernelServiceOptions options, ModuleHealth& health)
    : options_(std::move(options)),
      scanMapper_(settings, scanMapperObject),
      detection_(settings, detectionObject),
      health_(health),
      kernel_(std::make_unique<RgMappingKernel>(config, loadCheckpoint(options_.checkpointFile))),
      writer_([file = options_.checkpointFile](const std::string& journal, const std::string& map) {
                if (!journal.empty()) appendToFileDurably(journalOf(file), journal);
                writeFileAtomically(file, map);
              },
              health, kernel_->state().lastPoseRevision),
      follower_(health, "inputs", [this] { return followOnce(); }, [this] { return skipFailingRecord(); }) {
  checkpointedScan_ = kernel_->state().lastScanId;
  checkpointedEvent_ = kernel_->state().events.empty() ? 0 : kernel_->state().events.back().id;
  // The journal with exactly the checkpoint's scans: what a crash appended ahead of the map goes.
  if (!options_.checkpointFile.empty())
    writeFileAtomically(journalOf(options_.checkpointFile), scanJournalLines(kernel_->state()));
  health_.set("resumed_after_scan", checkpointedScan_);
  health_.set("resumed_after_gateway_event", kernel_->state().lastGatewayEventId);
}

RgMappingKernelService::~RgMappingKernelService() { stop(); }

void RgMappingKernelService::start() { follower_.start(); }

void RgMappingKernelService::stop() {
  follower_.stop();
  writer_.flush();
}

bool RgMappingKernelService::fetchScans() {
  DataId after;
  {
    std::lock_guard lock(mutex_);
    after = scans_.empty() ? kernel_->state().lastScanId : scans_.back().scan.id;
  }
  CorrectedBatch batch = scanMapper_.correctedSince(after, options_.fetchBatch);
  std::lock_guard lock(mutex_);
  scansEnded_ = batch.scans.empty() && batch.endOfData;
  for (CorrectedScan& s : batch.scans) scans_.push_back(std::move(s));
  return !batch.scans.empty();
}

bool RgMappingKernelService::fetchRevisions() {
  std::uint64_t durable, known;
  {
    std::lock_guard lock(mutex_);
    // What a restart from the checkpoint would have applied: the ScanMapper keeps what is after it.
    durable = options_.checkpointFile.empty() ? kernel_->state().lastPoseRevision : writer_.durableRevision();
    known = revisions_.empty() ? kernel_->state().lastPoseRevision : revisions_.back().revision;
  }
  const std::vector<PoseRevisionInfo> revisions = scanMapper_.revisionsSince(durable);
  std::lock_guard lock(mutex_);
  bool any = false;
  for (const PoseRevisionInfo& r : revisions) {
    if (r.revision <= known) continue;
    if (r.revision > known + 1) health_.add("pose_revisions_not_kept", r.revision - known - 1);
    revisions_.push_back(r);
    known = r.revision;
    any = true;
  }
  return any;
}

bool RgMappingKernelService::fetchEvents() {
  bool any = false;
  for (;;) {
    GatewayEventId after;
    {
      std::lock_guard lock(mutex_);
      after = events_.empty() ? kernel_->state().lastGatewayEventId : events_.back().id;
    }
    GatewayEventBatch batch = detection_.eventsSince(after, options_.fetchBatch);
    std::lock_guard lock(mutex_);
    // Every event of the scans up to batch.lastScan is in the buffer once this batch reached its end.
    const bool complete = batch.events.empty() || batch.events.back().id >= batch.latestId;
    if (complete) detectionLastScan_ = batch.lastScan;
    eventsEnded_ = batch.events.empty() && batch.endOfData;
    any = any || !batch.events.empty();
    for (GatewayEvent& e : batch.events) events_.push_back(std::move(e));
    if (complete) return any;
  }
}

std::vector<CorrectedPose> RgMappingKernelService::posesOfKernelScans(std::optional<std::uint64_t> revision) {
  DataId last;
  {
    std::lock_guard lock(mutex_);
    last = kernel_->state().lastScanId;
  }
  std::vector<CorrectedPose> poses;
  for (DataId first = 1; first <= last;) {
    const std::vector<PoseUpdate> chunk = revision ? scanMapper_.revisedPoses(*revision, first, last)
                                                   : scanMapper_.poses(first, std::min(last, first + kPoseChunk - 1));
    if (chunk.empty()) break;
    for (const PoseUpdate& u : chunk) poses.push_back({u.id, u.corrected});
    first = chunk.back().id + 1;
  }
  return poses;
}

bool RgMappingKernelService::applyRevision(const PoseRevisionInfo& revision) {
  bool replaced;
  {
    std::lock_guard lock(mutex_);
    feeding_ = Feeding::Revision;
    replaced = kernel_->state().lastScanId >= revision.atScan;  // learned of too late
  }
  std::vector<CorrectedPose> poses;
  if (!replaced) {
    try {
      poses = posesOfKernelScans(revision.revision);
    } catch (const NotAvailableError&) {
      // A restarted ScanMapper has not made it again yet: later. Otherwise it no longer keeps it.
      if (scanMapper_.revision() < revision.revision) return false;
      replaced = true;
    }
  }
  if (replaced) {
    poses = posesOfKernelScans(std::nullopt);
    health_.add("pose_revisions_replaced");
  }
  std::lock_guard lock(mutex_);
  kernel_->revisePoses(poses, revision.revision);
  revisions_.pop_front();
  health_.add("pose_revisions");
  return true;
}

void RgMappingKernelService::applyFinalPoses() {
  {
    std::lock_guard lock(mutex_);
    feeding_ = Feeding::FinalPoses;
  }
  std::vector<CorrectedPose> poses = posesOfKernelScans(std::nullopt);
  const std::uint64_t revision = scanMapper_.revision();
  std::lock_guard lock(mutex_);
  kernel_->revisePoses(poses, revision);
}

Pose2D RgMappingKernelService::correctedPoseOf(DataId scan) const {
  const auto& stored = kernel_->state().scans;
  const auto found = stored.find(scan);
  if (found == stored.end()) throw NotAvailableError("kernel: a gateway event names scan " + std::to_string(scan) +
                                                     ", which the kernel does not hold");
  return found->second.corrected;
}

std::optional<PoseRevisionInfo> RgMappingKernelService::mapPending(bool& fed) {
  const auto feedEventsUpTo = [&](DataId scan) {
    while (!events_.empty() && events_.front().scanId <= scan) {
      const GatewayEvent& e = events_.front();
      feeding_ = Feeding::Event;
      kernel_->addGatewayEvent(e, correctedPoseOf(e.gateway.lastScan));
      health_.add("gateway_events_mapped");
      events_.pop_front();
      fed = true;
    }
  };
  while (!scans_.empty() && (scans_.front().scan.id <= detectionLastScan_ || eventsEnded_)) {
    const CorrectedScan& s = scans_.front();
    feedEventsUpTo(s.scan.id - 1);
    if (!revisions_.empty() && revisions_.front().atScan <= s.scan.id) return revisions_.front();
    feeding_ = Feeding::Scan;
    kernel_->addScan(s.scan, s.mapped);
    health_.add("scans_mapped");
    const DataId id = s.scan.id;
    scans_.pop_front();
    feedEventsUpTo(id);
    fed = true;
  }
  if (scans_.empty() && scansEnded_ && eventsEnded_) {
    feedEventsUpTo(kernel_->state().lastScanId);
    if (!revisions_.empty()) return revisions_.front();  // made after the last scan
  }
  return std::nullopt;
}

bool RgMappingKernelService::followOnce() {
  {
    std::lock_guard lock(mutex_);
    if (finished_) return false;
    feeding_ = Feeding::Nothing;
  }
  // Scans before revisions: a revision made while a scan was taken in is known once that scan is.
  const bool scans = fetchScans();
  const bool revisions = fetchRevisions();
  const bool events = fetchEvents();
  bool fed = false;
  for (;;) {
    std::optional<PoseRevisionInfo> due;
    {
      std::lock_guard lock(mutex_);
      due = mapPending(fed);
    }
    if (!due || !applyRevision(*due)) break;
    fed = true;
  }
  bool ended;
  {
    std::lock_guard lock(mutex_);
    ended = scans_.empty() && events_.empty() && revisions_.empty() && scansEnded_ && eventsEnded_;
  }
  if (ended) applyFinalPoses();
  std::lock_guard lock(mutex_);
  const RgMapEventId lastEvent = kernel_->state().events.empty() ? 0 : kernel_->state().events.back().id;
  if (ended) finished_ = true;
  if (ended || lastEvent != checkpointedEvent_ ||
      kernel_->state().lastScanId >= checkpointedScan_ + options_.checkpointScans)
    checkpoint();
  return scans || revisions || events || fed;
}

std::string RgMappingKernelService::skipFailingRecord() {
  std::lock_guard lock(mutex_);
  health_.add("input_records_left_out");
  switch (feeding_) {
    case Feeding::Scan:
      if (scans_.empty()) break;
      {
        const DataId id = scans_.front().scan.id;
        scans_.pop_front();
        return "corrected scan " + std::to_string(id);
      }
    case Feeding::Event:
      if (events_.empty()) break;
      {
        const GatewayEventId id = events_.front().id;
        events_.pop_front();
        return "gateway event " + std::to_string(id);
      }
    case Feeding::Revision:
      if (revisions_.empty()) break;
      {
        const std::uint64_t number = revisions_.front().revision;
        revisions_.pop_front();
        return "pose revision " + std::to_string(number);
      }
    case Feeding::FinalPoses:
      finished_ = true;  // the map keeps the poses as mapped
      checkpoint();
      return "the final poses";
    case Feeding::Nothing:
      break;
  }
  return "nothing (the step failed while fetching, not while mapping)";
}

void RgMappingKernelService::checkpoint() {
  if (options_.checkpointFile.empty()) return;
  writer_.submit(scanJournalLines(kernel_->state(), checkpointedScan_), serializeRgMap(kernel_->state()),
                 kernel_->state().lastPoseRevision);
  checkpointedScan_ = kernel_->state().lastScanId;
  checkpointedEvent_ = kernel_->state().events.empty() ? 0 : kernel_->state().events.back().id;
}

MapSummaryView RgMappingKernelService::summary() {
  std::lock_guard lock(mutex_);
  MapSummaryView s = mapSummary(*kernel_);
  s.endOfData = finished_;
  return s;
}

RegionView RgMappingKernelService::currentRegion() {
  std::lock_guard lock(mutex_);
  if (kernel_->currentRegionId() == 0) throw NotAvailableError("no scan mapped yet");
  return regionView(*kernel_, kernel_->currentRegionId());
}

RegionView RgMappingKernelService::region(RegionId id) {
  std::lock_guard lock(mutex_);
  return regionView(*kernel_, id);
}

std::vector<RegionSummaryView> RgMappingKernelService::regions() {
  std::lock_guard lock(mutex_);
  std::vector<RegionSummaryView> out;
  for (const auto& [id, r] : kernel_->state().regions) out.push_back(summaryOf(r));
  return out;
}

std::vector<GatewayView> RgMappingKernelService::gateways() {
  std::lock_guard lock(mutex_);
  return gatewayViews(*kernel_);
}

GraphView RgMappingKernelService::graph() {
  std::lock_guard lock(mutex_);
  return graphView(kernel_->graph());
}

PathView RgMappingKernelService::findPath(const RgPlace& start, const RgPlace& goal) {
  std::lock_guard lock(mutex_);
  return pathView(rgnav::findPath(kernel_->graph(), start, goal));
}

void RgMappingKernelService::nameRegion(std::uint64_t requestId, RegionId id, const std::string& name) {
  std::lock_guard lock(mutex_);
  if (requests_.answered(requestId)) return;
  kernel_->nameRegion(id, name);
  requests_.record(requestId, 0);
  checkpoint();
}

RegionId RgMappingKernelService::regionByName(const std::string& name) {
  std::lock_guard lock(mutex_);
  const std::optional<RegionId> id = kernel_->regionByName(name);
  if (!id) throw NotAvailableError("no region is named '" + name + "'");
  return *id;
}

void RgMappingKernelService::nameObject(std::uint64_t requestId, RegionId region, const Eigen::Vector2d& atInRegion,
                                        const std::string& name) {
  std::lock_guard lock(mutex_);
  if (requests_.answered(requestId)) return;
  kernel_->nameObject(region, atInRegion, name);
  requests_.record(requestId, 0);
  checkpoint();
}

RgMappingKernel::NamedObject RgMappingKernelService::objectByName(const std::string& name) {
  std::lock_guard lock(mutex_);
  const std::optional<RgMappingKernel::NamedObject> found = kernel_->objectByName(name);
  if (!found) throw NotAvailableError("no object is named '" + name + "'");
  return *found;
}

RegionId RgMappingKernelService::mergeRegions(std::uint64_t requestId, RegionId a, RegionId b) {
  std::lock_guard lock(mutex_);
  if (const std::optional<std::uint64_t> merged = requests_.answered(requestId)) return *merged;
  const RegionId merged = kernel_->mergeRegions(a, b);
  requests_.record(requestId, merged);
  checkpoint();
  return merged;
}

MapExportData RgMappingKernelService::exportData(bool occupancy) {
  std::lock_guard lock(mutex_);
  return exportDataOf(*kernel_, occupancy);
}

RgMapEventBatch RgMappingKernelService::eventsSince(RgMapEventId afterId, std::size_t maxCount) {
  if (maxCount == 0) throw InvalidArgumentError("maxCount must be at least 1");
  std::lock_guard lock(mutex_);
  RgMapEventBatch out;
  out.events = kernel_->eventsSince(afterId);
  if (out.events.size() > maxCount) out.events.resize(maxCount);
  out.latestId = kernel_->state().events.empty() ? 0 : kernel_->state().events.back().id;
  out.lastScan = kernel_->state().lastScanId;
  out.endOfData = finished_ && (out.events.empty() ? afterId : out.events.back().id) >= out.latestId;
  return out;
}

}  // namespace rgnav
