// The RG Mapping Kernel module's follower, ordering and checkpoints (see RgMappingKernelService.h).
#include "servers/rgmappingkernel/RgMappingKernelService.h"

#include <algorithm>
#include <optional>
#include <set>

#include "core/common/AtomicFile.h"
#include "core/rgmap/kernel/RgMapCodec.h"

namespace rgnav {
namespace {

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
      writer_({[file = journalOf(options_.checkpointFile)](const std::string& lines) { appendToFileDurably(file, lines); },
               [file = options_.checkpointFile](const std::string& map) { writeFileAtomically(file, map); }},
              health, kernel_->state().lastPoseRevision),
      feed_(*kernel_, mutex_, scanMapper_, detection_, options_.fetchBatch,
            [this] {
              // What a restart from the checkpoint would have applied: the ScanMapper keeps what is after it.
              return options_.checkpointFile.empty() ? kernel_->state().lastPoseRevision : writer_.durableRevision();
            }),
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

bool RgMappingKernelService::followOnce() {
  {
    std::lock_guard lock(mutex_);
    if (feed_.finished()) return false;
  }
  const bool progress = feed_.step();
  std::lock_guard lock(mutex_);
  publishCounters();
  const RgMapEventId lastEvent = kernel_->state().events.empty() ? 0 : kernel_->state().events.back().id;
  if (feed_.finished() || lastEvent != checkpointedEvent_ ||
      kernel_->state().lastScanId >= checkpointedScan_ + options_.checkpointScans)
    checkpoint();
  return progress;
}

void RgMappingKernelService::publishCounters() {
  const KernelFeedCounters& c = feed_.counters();
  health_.set("scans_mapped", c.scansMapped);
  health_.set("gateway_events_mapped", c.gatewayEventsMapped);
  health_.set("pose_revisions", c.poseRevisions);
  health_.set("pose_revisions_replaced", c.posesReplaced);
  health_.set("pose_revisions_not_kept", c.revisionsNotKept);
}

std::string RgMappingKernelService::skipFailingRecord() {
  std::lock_guard lock(mutex_);
  health_.add("input_records_left_out");
  const std::string what = feed_.skipFailing();
  if (feed_.finished()) checkpoint();
  return what;
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
  s.endOfData = feed_.finished();
  return s;
}

RegionView RgMappingKernelService::currentRegion() {
  std::lock_guard lock(mutex_);
  if (kernel_->currentRegionId().isNone()) throw NotAvailableError("no scan mapped yet");
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
  {
    std::lock_guard lock(mutex_);
    if (requests_.answered(requestId)) return;
    kernel_->nameRegion(id, name);
    requests_.record(requestId, 0);
    checkpoint();
  }
  writer_.flush();  // a name answered for is the user's word: nobody asks again, a restart must keep it
}

RegionId RgMappingKernelService::regionByName(const std::string& name) {
  std::lock_guard lock(mutex_);
  const std::optional<RegionId> id = kernel_->regionByName(name);
  if (!id) throw NotAvailableError("no region is named '" + name + "'");
  return *id;
}

void RgMappingKernelService::nameObject(std::uint64_t requestId, RegionId region, const Eigen::Vector2d& atInRegion,
                                        const std::string& name) {
  {
    std::lock_guard lock(mutex_);
    if (requests_.answered(requestId)) return;
    kernel_->nameObject(region, atInRegion, name);
    requests_.record(requestId, 0);
    checkpoint();
  }
  writer_.flush();  // as nameRegion
}

RgMappingKernel::NamedObject RgMappingKernelService::objectByName(const std::string& name) {
  std::lock_guard lock(mutex_);
  const std::optional<RgMappingKernel::NamedObject> found = kernel_->objectByName(name);
  if (!found) throw NotAvailableError("no object is named '" + name + "'");
  return *found;
}

RegionId RgMappingKernelService::mergeRegions(std::uint64_t requestId, RegionId a, RegionId b, bool force) {
  std::lock_guard lock(mutex_);
  if (const std::optional<std::uint64_t> merged = requests_.answered(requestId)) return RegionId(*merged);
  const RegionId merged = kernel_->mergeRegions(a, b, force);
  requests_.record(requestId, merged.value());
  checkpoint();
  return merged;
}

RegionId RgMappingKernelService::unmergeRegions(std::uint64_t requestId, RegionId merged) {
  std::lock_guard lock(mutex_);
  if (const std::optional<std::uint64_t> restored = requests_.answered(requestId)) return RegionId(*restored);
  const RegionId restored = kernel_->unmergeRegions(merged);
  requests_.record(requestId, restored.value());
  checkpoint();
  return restored;
}

void RgMappingKernelService::reportDoorState(std::uint64_t requestId, GatewayId door, bool traversable) {
  std::lock_guard lock(mutex_);
  if (requests_.answered(requestId)) return;
  kernel_->recordDoorState(door, traversable);
  requests_.record(requestId, 0);
  checkpoint();
}

void RgMappingKernelService::reportTraversal(std::uint64_t requestId, GatewayId gateway, RegionId from, RegionId to,
                                             DataId scanId) {
  std::lock_guard lock(mutex_);
  if (requests_.answered(requestId)) return;
  const auto& gateways = kernel_->state().gateways;
  const auto g = gateways.find(gateway);
  if (g == gateways.end() || !g->second.inMap())
    throw InvalidArgumentError("gateway " + std::to_string(gateway.value()) + " is not in the map");
  const std::set<RegionId> sides{g->second.sides[0].region, g->second.sides[1].region};
  if (from == to || sides != std::set<RegionId>{from, to})
    throw InvalidArgumentError("regions " + std::to_string(from.value()) + " and " + std::to_string(to.value()) +
                               " are not the sides of gateway " + std::to_string(gateway.value()));
  health_.add("traversals_reported");
  health_.set("last_traversal_scan", scanId);
  requests_.record(requestId, 0);
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
  out.endOfData = feed_.finished() && (out.events.empty() ? afterId : out.events.back().id) >= out.latestId;
  return out;
}

}  // namespace rgnav
