// The Localization module's follower, map copy, filter, history and checkpoints (see
// LocalizationService.h).
#include "servers/localization/LocalizationService.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <set>

#include "core/common/AtomicFile.h"
#include "servers/localization/FreespaceSeeding.h"
#include "servers/localization/ParticleRehoming.h"

namespace rgnav {
namespace {

std::optional<ParticleSetCheckpoint> loadCheckpoint(const std::string& file) {
  const std::optional<std::string> saved = readCheckpoint(file);
  if (!saved) return std::nullopt;
  return deserializeParticles(*saved, file);
}

// The estimate of a filter update moved on by the odometry's motion since that update.
PoseEstimate movedOn(const PoseEstimate& e, const Pose2D& odometryAtUpdate, const Pose2D& odometryNow,
                     const LocalizationMap& map) {
  const Pose2D motion = between(odometryAtUpdate, odometryNow);
  PoseEstimate out = e;
  out.mapPose = compose(e.mapPose, motion);
  out.bestParticle = compose(e.bestParticle, motion);
  out.regionPose = between(map.region(e.region).frame, out.mapPose);
  return out;
}

}  // namespace

LocalizationService::LocalizationService(const MclConfig& config, const ClientSettings& settings,
                                         const std::string& laserObject, const std::string& kernelObject,
                                         LocalizationServiceOptions options, ModuleHealth& health)
    : config_(config),
      options_(std::move(options)),
      health_(health),
      laser_(settings, laserObject),
      kernel_(settings, kernelObject),
      copy_(kernel_),
      map_(config.beam),
      mcl_(config, map_, options_.seed),
      rng_(options_.seed ^ 0x5851F42D4C957F2Dull),
      resume_(loadCheckpoint(options_.checkpointFile)),
      pacer_(options_.checkpointIntervalS),
      retry_(health),
      follower_(health, "laser", [this] { return followOnce(); }, [this] { return skipFailingScan(); }) {
  health_.set("resumed_after_scan", resume_ ? resume_->scanId : 0);
}

LocalizationService::~LocalizationService() { stop(); }

void LocalizationService::start() { follower_.start(); }

void LocalizationService::stop() { follower_.stop(); }

bool LocalizationService::followOnce() {
  DataId after;
  {
    std::lock_guard lock(mutex_);
    after = std::max(lastScan_, skipScan_);
  }
  refreshMapIfDue(options_.mappedScansOnly && after >= copy_.mappedScan());
  reportTraversals();
  bool idle;
  {
    std::lock_guard lock(mutex_);
    if (!resumeIfDue()) return false;
    after = std::max(lastScan_, skipScan_);
    idle = !mcl_.initialised() && !(options_.startAtOdometry && !started_);
  }
  // Only scans that exist are asked for: a lock-step simulator is paced by its other consumers
  // (the mapping chain), never by the localizer.
  DataId latest = laser_.latestId();
  if (options_.mappedScansOnly) latest = std::min(latest, copy_.mappedScan());
  if (idle) {
    // Nothing to localize: the scan after setPose is the next one.
    std::lock_guard lock(mutex_);
    lastScan_ = std::max(lastScan_, latest);
    return false;
  }
  if (after >= latest) return false;
  const auto count = static_cast<std::uint32_t>(std::min<DataId>(options_.fetchBatch, latest - after));
  const DataBatch<LaserScan> batch = laser_.scansSince(after, count);
  if (batch.records.empty()) return false;
  if (batch.records.front().id != after + 1) health_.add("scans_missed", batch.records.front().id - after - 1);
  std::lock_guard lock(mutex_);
  for (const LaserScan& scan : batch.records) {
    if (scan.id == skipScan_) continue;
    processing_ = scan.id;
    take(scan);
  }
  if (pacer_.due() && retry_.due()) checkpoint();
  return true;
}

void LocalizationService::refreshMapIfDue(bool now) {
  const auto time = std::chrono::steady_clock::now();
  if (!now && time < nextRefresh_) return;
  nextRefresh_ = time + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(options_.mapRefreshS));
  try {
    const std::optional<KernelMapChanges> changes = copy_.refresh();
    health_.clearError("kernel");
    if (!changes) return;
    std::lock_guard lock(mutex_);
    applyMap(*changes);
  } catch (const Error& e) {
    health_.setError("kernel", e.what());
  }
}

void LocalizationService::applyMap(const KernelMapChanges& changes) {
  // The map poses of the particles in regions merged away, taken before their frames go.
  std::vector<Orphan> orphans;
  const std::set<RegionId> removed(changes.removed.begin(), changes.removed.end());
  for (std::size_t i = 0; i < mcl_.particles().size(); ++i)
    if (removed.count(mcl_.particles()[i].region)) orphans.push_back({i, mcl_.mapPose(mcl_.particles()[i])});
  for (const RegionId id : changes.removed) map_.removeRegion(id);
  for (const RegionView& r : changes.regions) map_.setRegion(localizationRegion(r));
  map_.setGateways(changes.gateways);
  mapRevision_ = changes.revision;
  health_.add("map_refreshes");
  health_.set("regions_fetched", copy_.regionsFetched());
  health_.set("map_regions", map_.regionIds().size());
  if (lastUpdate_ && !map_.hasRegion(lastUpdate_->region)) lastUpdate_.reset();
  if (orphans.empty()) return;
  std::vector<RegionId> fetched;
  for (const RegionView& r : changes.regions) fetched.push_back(r.summary.id);
  const std::size_t before = mcl_.particles().size();
  std::vector<Particle> kept = rehomedParticles(mcl_.particles(), orphans, map_, fetched);
  health_.add("particles_rehomed", orphans.size());
  health_.add("particles_dropped_with_regions", before - kept.size());
  lastUpdate_.reset();
  mcl_.setParticles(kept.empty() ? globalParticles() : std::move(kept));
}

bool LocalizationService::resumeIfDue() {
  if (!resume_) return true;
  std::vector<Particle> held;
  for (const Particle& p : resume_->particles)
    if (map_.hasRegion(p.region)) held.push_back(p);
  if (held.empty() && map_.regionIds().empty()) return false;  // the map is not fetched yet
  if (held.empty()) {
    health_.setError("checkpoint", "no region of the checkpoint's particles is in the map; waiting for setPose");
  } else {
    health_.add("particles_resumed", held.size());
    mcl_.setParticles(std::move(held));
    lastScan_ = std::max<DataId>(resume_->scanId, 1) - 1;  // takes the checkpoint's scan again as the odometry reference
    std::cerr << "localization: resumed " << mcl_.particles().size() << " particles of scan " << resume_->scanId
              << std::endl;
  }
  resume_.reset();
  return true;
}

void LocalizationService::take(const LaserScan& scan) {
  lastScan_ = scan.id;
  health_.add("scans_taken");
  if (!mcl_.initialised() && options_.startAtOdometry && !started_ && !map_.regionIds().empty()) {
    try {
      mcl_.setPose(scan.odometry, options_.startSigma, RegionId());
      started_ = true;
    } catch (const NotAvailableError&) {
      // the odometry pose lies in no region yet: the next scan tries again
    }
  }
  if (!mcl_.initialised()) return;
  if (mcl_.update(scan)) {
    ++updates_;
    health_.add("updates");
    lastUpdate_ = mcl_.estimate();
    lastUpdateOdometry_ = scan.odometry;
    for (const ConfirmedTraversal& t : mcl_.takeTraversals()) pendingTraversals_.push_back(t);
  }
  if (!lastUpdate_) return;
  history_[scan.id] = {scan.id, movedOn(*lastUpdate_, lastUpdateOdometry_, scan.odometry, map_)};
  while (history_.size() > options_.historyScans) history_.erase(history_.begin());
}

void LocalizationService::reportTraversals() {
  std::vector<ConfirmedTraversal> pending;
  {
    std::lock_guard lock(mutex_);
    pending.swap(pendingTraversals_);
  }
  for (std::size_t i = 0; i < pending.size(); ++i) {
    const ConfirmedTraversal& t = pending[i];
    try {
      kernel_.reportTraversal(t.gateway, t.from, t.to, t.scanId);
      health_.add("traversals_reported");
      std::lock_guard lock(mutex_);
      ++traversalsReported_;
    } catch (const InvalidArgumentError& e) {
      // the kernel's map changed meanwhile (a merge): the evidence no longer applies
      health_.add("traversals_refused");
      std::cerr << "localization: traversal of gateway " << t.gateway.value() << " refused: " << e.what() << std::endl;
    } catch (const Error& e) {
      health_.setError("kernel", e.what());
      std::lock_guard lock(mutex_);
      pendingTraversals_.insert(pendingTraversals_.begin(), pending.begin() + static_cast<std::ptrdiff_t>(i),
                                pending.end());
      return;
    }
  }
}

void LocalizationService::checkpoint() {
  if (options_.checkpointFile.empty() || !lastUpdate_) return;
  try {
    const auto began = pacer_.now();
    writeFileAtomically(options_.checkpointFile, serializeParticles({lastUpdate_->scanId, mcl_.particles()}));
    pacer_.written(began);
    health_.add("checkpoints_written");
    health_.set("checkpoint_scan", lastUpdate_->scanId);
    retry_.succeeded();
  } catch (const FileError& e) {
    retry_.failed(e.what());
  }
}

std::string LocalizationService::skipFailingScan() {
  std::lock_guard lock(mutex_);
  skipScan_ = processing_;
  health_.add("scans_skipped");
  return "scan " + std::to_string(skipScan_);
}

void LocalizationService::requireLocalized() const {
  if (!mcl_.initialised()) throw NotLocalizedError("no particles: call setPose or relocalize");
  if (!lastUpdate_) throw NotLocalizedError("no scan weighed since the particles were set");
}

ScanEstimate LocalizationService::latestEstimate() {
  std::lock_guard lock(mutex_);
  requireLocalized();
  return std::prev(history_.end())->second;
}

ScanEstimate LocalizationService::estimateByScan(DataId scanId) {
  std::lock_guard lock(mutex_);
  const auto found = history_.find(scanId);
  if (found != history_.end()) return found->second;
  if (history_.empty()) requireLocalized();
  throw NotAvailableError("no estimate of scan " + std::to_string(scanId) + " is held (held: " +
                          (history_.empty() ? std::string("none")
                                            : std::to_string(history_.begin()->first) + " to " +
                                                  std::to_string(std::prev(history_.end())->first)) +
                          ")");
}

ParticleSnapshotView LocalizationService::particles(std::size_t maxCount) {
  std::lock_guard lock(mutex_);
  if (!mcl_.initialised()) throw NotLocalizedError("no particles: call setPose or relocalize");
  const std::vector<Particle>& all = mcl_.particles();
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  const std::size_t count = std::min(maxCount, all.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end(),
                    [&](std::size_t a, std::size_t b) { return all[a].weight > all[b].weight; });
  ParticleSnapshotView out{lastUpdate_ ? lastUpdate_->scanId : 0, all.size(), {}};
  for (std::size_t i = 0; i < count; ++i) out.particles.push_back({all[order[i]], mcl_.mapPose(all[order[i]])});
  return out;
}

void LocalizationService::setPose(const Pose2D& mapPose, const Eigen::Vector3d& sigma, RegionId hint) {
  std::lock_guard lock(mutex_);
  if (map_.regionIds().empty()) throw NotAvailableError("no map yet: the kernel's map has no region");
  mcl_.setPose(mapPose, sigma, hint);
  lastUpdate_.reset();
  resume_.reset();
  health_.clearError("particles");
  health_.clearError("checkpoint");
  health_.add("poses_set");
}

void LocalizationService::relocalize() {
  std::lock_guard lock(mutex_);
  mcl_.setParticles(globalParticles());
  lastUpdate_.reset();
  resume_.reset();
  health_.clearError("particles");
  health_.clearError("checkpoint");
  health_.add("relocalizations");
}

std::vector<Particle> LocalizationService::globalParticles() {
  // The one call site of global seeding: the region-recognition seeder (GlobalLocalizer) goes here.
  return uniformFreespaceParticles(map_, config_.kld.maxParticles, rng_);
}

LocalizationStateView LocalizationService::state() {
  std::lock_guard lock(mutex_);
  return {mcl_.initialised(), map_.regionIds().size(), mapRevision_, updates_, lastScan_, traversalsReported_};
}

}  // namespace rgnav
