// The GatewayDetection module's follower, event buffer and checkpoints (see
// GatewayDetectionService.h).
#include "servers/gatewaydetection/GatewayDetectionService.h"

#include <algorithm>

#include "core/common/AtomicFile.h"
#include "core/gateways/detection/DetectionStateCodec.h"

namespace rgnav {
namespace {

DetectionCheckpoint loadCheckpoint(const std::string& file) {
  const std::optional<std::string> saved = readCheckpoint(file);
  if (!saved) return {};
  try {
    return deserializeDetection(*saved);
  } catch (const FormatError& e) {
    throw FormatError(file, 0, e.what());
  }
}

}  // namespace

GatewayDetectionService::GatewayDetectionService(const GatewayDetectorConfig& config,
                                                 std::optional<HmmClassifier> classifier,
                                                 const ClientSettings& laserSettings, const std::string& laserObject,
                                                 GatewayDetectionServiceOptions options, ModuleHealth& health)
    : options_(std::move(options)), laser_(laserSettings, laserObject),
      health_(health),
      events_(options_.eventCapacity),
      pacer_(options_.checkpointIntervalS),
      retry_(health),
      follower_(health, "laser", [this] { return followOnce(); }, [this] { return skipFailingScan(); }) {
  DetectionCheckpoint saved = loadCheckpoint(options_.checkpointFile);
  for (GatewayEvent& e : saved.events) events_.push(std::move(e));
  detector_ = std::make_unique<GatewayDetector>(config, std::move(classifier), std::move(saved.detector));
  health_.set("resumed_after_scan", detector_->lastScan());
}

GatewayDetectionService::~GatewayDetectionService() { stop(); }

void GatewayDetectionService::start() { follower_.start(); }

void GatewayDetectionService::stop() { follower_.stop(); }

bool GatewayDetectionService::followOnce() {
  DataId last;
  {
    std::lock_guard lock(mutex_);
    if (finished_) {
      if (retry_.failing() && retry_.due()) checkpoint();  // the final checkpoint is still owed
      return false;
    }
    last = std::max(detector_->lastScan(), skipScan_);  // a skipped last scan counts as processed
  }
  const DataBatch<LaserScan> batch = laser_.scansSince(last, options_.fetchBatch);
  if (batch.records.empty()) {
    if (batch.endOfData && last >= batch.latestId) {
      std::lock_guard lock(mutex_);
      finished_ = true;
      events_.markEndOfData();
      checkpoint();
    }
    return false;
  }
  if (batch.records.front().id != last + 1) health_.add("scans_missed", batch.records.front().id - last - 1);
  std::lock_guard lock(mutex_);
  for (const LaserScan& scan : batch.records) {
    if (scan.id == skipScan_) continue;
    processing_ = scan.id;
    for (GatewayEvent& e : detector_->addScan(scan, scan.odometry)) {
      health_.add(e.kind == GatewayEventKind::Traversed ? "traversals" : "gateway_reports");
      events_.push(std::move(e));
    }
    health_.add("scans_processed");
  }
  if (pacer_.due() && retry_.due()) checkpoint();
  return true;
}

std::string GatewayDetectionService::skipFailingScan() {
  std::lock_guard lock(mutex_);
  skipScan_ = processing_;
  health_.add("scans_skipped");
  return "scan " + std::to_string(skipScan_);
}

void GatewayDetectionService::checkpoint() {
  if (options_.checkpointFile.empty()) return;
  try {
    const auto began = pacer_.now();
    const std::vector<GatewayEvent> events(events_.records().begin(), events_.records().end());
    writeFileAtomically(options_.checkpointFile, serializeDetection({detector_->state(), events}));
    pacer_.written(began);
    retry_.succeeded();
  } catch (const FileError& e) {
    retry_.failed(e.what());
  }
}

GatewayEventBatch GatewayDetectionService::eventsSince(GatewayEventId afterId, std::size_t maxCount) {
  std::lock_guard lock(mutex_);
  const DataBatch<GatewayEvent> batch = events_.since(afterId, maxCount);
  GatewayEventBatch out{batch.records, batch.latestId, detector_->lastScan(), false};
  out.endOfData = finished_ && (out.events.empty() ? afterId : out.events.back().id) >= out.latestId;
  return out;
}

std::vector<GatewayRecord> GatewayDetectionService::gateways() {
  std::lock_guard lock(mutex_);
  return detector_->gateways();
}

GatewayRecord GatewayDetectionService::gateway(DetectorGatewayId id) {
  std::lock_guard lock(mutex_);
  for (GatewayRecord& g : detector_->gateways())
    if (g.id == id) return g;
  throw NotAvailableError("no gateway " + std::to_string(id.value()) + " (yet)");
}

DataId GatewayDetectionService::lastProcessedScan() {
  std::lock_guard lock(mutex_);
  return detector_->lastScan();
}

bool GatewayDetectionService::detectsHallways() {
  std::lock_guard lock(mutex_);
  return detector_->detectsHallways();
}

}  // namespace rgnav
