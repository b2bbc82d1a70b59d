// The ScanMapper module's follower, buffer and checkpoints (see ScanMapperService.h).
#include "servers/scanmapper/ScanMapperService.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "clientlibs/common/ClientConnection.h"
#include "core/common/AtomicFile.h"
#include "core/slam/PoseQueries.h"
#include "core/slam/SlamStateCodec.h"

namespace rgnav {

namespace {

// A scan the mapper failed on, as it takes it in instead: no ranges (nothing to align), and the
// odometry of the scan before if its own is not finite.
LaserScan withoutMeasurements(LaserScan scan, const Pose2D& previousOdometry) {
  std::fill(scan.ranges.begin(), scan.ranges.end(), std::numeric_limits<float>::quiet_NaN());
  if (!std::isfinite(scan.odometry.x) || !std::isfinite(scan.odometry.y) || !std::isfinite(scan.odometry.theta))
    scan.odometry = previousOdometry;
  return scan;
}

SlamState loadCheckpoint(const std::string& file) {
  const std::optional<std::string> saved = readCheckpoint(file);
  if (!saved) return {};
  try {
    return deserializeState(*saved);
  } catch (const CorruptStateError& e) {
    throw CorruptStateError(file + ": " + e.what());
  }
}

}  // namespace

ScanMapperService::ScanMapperService(const SlamConfig& config, const ClientSettings& laserSettings,
                                     const std::string& laserObject, ScanMapperServiceOptions options, ModuleHealth& health)
    : options_(std::move(options)),
      laser_(laserSettings, laserObject),
      health_(health),
      mapper_(config, loadCheckpoint(options_.checkpointFile)),
      followers_(options_.revisionFollowers),
      pacer_(options_.checkpointIntervalS),
      retry_(health),
      scans_(options_.bufferCapacity),
      follower_(health, "laser", [this] { return step(); }, [this] { return skipFailingScan(); }) {
  health_.set("resumed_after_scan", mapper_.lastInputId());
}

ScanMapperService::~ScanMapperService() { stop(); }

void ScanMapperService::start() { follower_.start(); }

void ScanMapperService::stop() { follower_.stop(); }

bool ScanMapperService::step() {
  if (!refilled_) {
    refillBuffer();
    refilled_ = true;
  }
  return followOnce();
}

void ScanMapperService::refillBuffer() {
  DataId last;
  {
    std::lock_guard lock(mutex_);
    last = mapper_.lastInputId();
  }
  DataId after = last > options_.bufferCapacity ? last - options_.bufferCapacity : 0;
  while (after < last && !follower_.stopping()) {
    const auto batch = laser_.scansSince(after, std::min<std::uint32_t>(options_.fetchBatch, static_cast<std::uint32_t>(last - after)));
    if (batch.records.empty()) break;  // no longer held by the Laser module
    std::lock_guard lock(mutex_);
    for (const LaserScan& scan : batch.records) {
      if (scan.id > last) break;
      keep(scan);
      after = scan.id;
    }
  }
}

void ScanMapperService::keep(const LaserScan& scan) {
  if (!scans_.records().empty() && scan.id <= scans_.latestId()) return;  // kept before a failed attempt
  if (!scans_.records().empty() && scan.id != scans_.latestId() + 1) {
    health_.add("scan_gaps");
    scans_ = DataBuffer<LaserScan>(options_.bufferCapacity);
  }
  scans_.push(scan);
}

bool ScanMapperService::followOnce() {
  DataId last;
  {
    std::lock_guard lock(mutex_);
    if (finished_) {
      if (retry_.failing() && retry_.due()) checkpoint();  // the final checkpoint is still owed
      return false;
    }
    last = mapper_.lastInputId();
  }
  const auto batch = laser_.scansSince(last, options_.fetchBatch);
  if (batch.records.empty()) {
    if (batch.endOfData && last >= batch.latestId) {
      std::lock_guard lock(mutex_);
      mapper_.optimize();
      finished_ = true;
      checkpoint();
    }
    return false;
  }
  for (const LaserScan& fetched : batch.records) {
    std::lock_guard lock(mutex_);
    processing_ = fetched.id;
    const LaserScan scan = fetched.id == skipScan_ ? withoutMeasurements(fetched, previousOdometry_) : fetched;
    keep(scan);
    const ScanOutcome outcome = mapper_.addScan(scan);
    previousOdometry_ = scan.odometry;
    health_.add("scans_mapped");
    health_.add("keyframes", outcome.keyframe);
    health_.add("loop_constraints", outcome.loopsAdded);
  }
  std::lock_guard lock(mutex_);
  if (pacer_.due() && retry_.due()) checkpoint();
  return true;
}

std::string ScanMapperService::skipFailingScan() {
  std::lock_guard lock(mutex_);
  skipScan_ = processing_;
  health_.add("scans_without_ranges");
  return "the ranges of scan " + std::to_string(skipScan_);
}

void ScanMapperService::checkpoint() {
  if (options_.checkpointFile.empty()) return;
  try {
    const auto began = pacer_.now();
    writeFileAtomically(options_.checkpointFile, serializeState(mapper_.state()));
    pacer_.written(began);
    retry_.succeeded();
  } catch (const FileError& e) {
    retry_.failed(e.what());
  }
}

CorrectedBatch ScanMapperService::correctedSince(DataId afterId, std::size_t maxCount) {
  std::lock_guard lock(mutex_);
  CorrectedBatch out;
  out.latestId = std::min(mapper_.lastInputId(), scans_.latestId());
  out.revision = mapper_.state().counters.optimizations;
  for (const LaserScan& scan : scans_.since(afterId, maxCount).records) {
    if (scan.id > out.latestId) break;
    out.scans.push_back(
        CorrectedScan{scan, mapper_.correctedPose(scan.id), mapper_.mappedPose(scan.id),
                      isKeyframe(mapper_.state(), scan.id)});
  }
  out.endOfData = finished_ && (out.scans.empty() ? afterId : out.scans.back().scan.id) >= out.latestId;
  return out;
}

Pose2D ScanMapperService::correctedPose(DataId id) {
  if (id == 0) throw InvalidArgumentError("ID 0 names no scan; IDs start at 1");
  std::lock_guard lock(mutex_);
  return mapper_.correctedPose(id);
}

Pose2D ScanMapperService::odomToMap(DataId id, const Pose2D& odometryPose) {
  if (id == 0) throw InvalidArgumentError("ID 0 names no scan; IDs start at 1");
  std::lock_guard lock(mutex_);
  return mapper_.odomToMap(id, odometryPose);
}

std::vector<PoseUpdate> ScanMapperService::poses(DataId first, DataId last, std::size_t cap) {
  std::lock_guard lock(mutex_);
  return latestPoses(mapper_.state(), first, last, cap);
}

std::vector<PoseRevisionInfo> ScanMapperService::revisionsSince(std::uint64_t afterRevision,
                                                                const std::string& follower) {
  const double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  std::lock_guard lock(mutex_);
  followers_.asked(follower, afterRevision, now);
  if (const std::optional<std::uint64_t> applied = followers_.appliedByAll(now)) mapper_.forgetRevisionsUpTo(*applied);
  return revisionsAfter(mapper_.state(), afterRevision);
}

std::vector<PoseUpdate> ScanMapperService::revisedPoses(std::uint64_t revision, DataId first, DataId last,
                                                        std::size_t cap) {
  std::lock_guard lock(mutex_);
  return rgnav::revisedPoses(mapper_.state(), revision, first, last, cap);
}

DataId ScanMapperService::latestCorrectedId() {
  std::lock_guard lock(mutex_);
  return mapper_.lastInputId();
}

std::uint64_t ScanMapperService::revision() {
  std::lock_guard lock(mutex_);
  return mapper_.state().counters.optimizations;
}

}  // namespace rgnav
