// The mapping chain's ordering contract (see KernelFeed.h).
#include "core/rgmap/feed/KernelFeed.h"

#include <algorithm>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

constexpr DataId kPoseChunk = 5000;  // latest poses asked per call

}  // namespace

KernelFeed::KernelFeed(RgMappingKernel& kernel, std::mutex& kernelMutex, CorrectedScanInput& scans,
                       GatewayEventInput& events, std::uint32_t fetchBatch,
                       std::function<std::uint64_t()> durableRevision)
    : kernel_(kernel),
      mutex_(kernelMutex),
      scanInput_(scans),
      eventInput_(events),
      fetchBatch_(fetchBatch),
      durableRevision_(std::move(durableRevision)) {
  if (fetchBatch == 0) throw InvalidArgumentError("kernel feed: the fetch batch must be at least 1");
}

bool KernelFeed::step() {
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
      due = feedPending(fed);
    }
    if (!due || !applyRevision(*due)) break;
    fed = true;
  }
  bool ended;
  {
    std::lock_guard lock(mutex_);
    ended = scans_.empty() && events_.empty() && revisions_.empty() && scansEnded_ && eventsEnded_;
  }
  if (ended) {
    applyFinalPoses();
    std::lock_guard lock(mutex_);
    finished_ = true;
  }
  return scans || revisions || events || fed || ended;
}

bool KernelFeed::fetchScans() {
  DataId after;
  {
    std::lock_guard lock(mutex_);
    after = scans_.empty() ? kernel_.state().lastScanId : scans_.back().scan.id;
  }
  CorrectedBatch batch = scanInput_.correctedSince(after, fetchBatch_);
  std::lock_guard lock(mutex_);
  scansEnded_ = batch.scans.empty() && batch.endOfData;
  for (CorrectedScan& s : batch.scans) scans_.push_back(std::move(s));
  return !batch.scans.empty();
}

bool KernelFeed::fetchRevisions() {
  std::uint64_t durable, known;
  {
    std::lock_guard lock(mutex_);
    // What a restart from the durable state would have applied: the input keeps what is after it.
    durable = durableRevision_ ? durableRevision_() : kernel_.state().lastPoseRevision;
    known = revisions_.empty() ? kernel_.state().lastPoseRevision : revisions_.back().revision;
  }
  const std::vector<PoseRevisionInfo> revisions = scanInput_.revisionsSince(durable);
  std::lock_guard lock(mutex_);
  bool any = false;
  for (const PoseRevisionInfo& r : revisions) {
    if (r.revision <= known) continue;
    if (r.revision > known + 1) counters_.revisionsNotKept += r.revision - known - 1;
    revisions_.push_back(r);
    known = r.revision;
    any = true;
  }
  return any;
}

bool KernelFeed::fetchEvents() {
  bool any = false;
  for (;;) {
    GatewayEventId after;
    {
      std::lock_guard lock(mutex_);
      after = events_.empty() ? kernel_.state().lastGatewayEventId : events_.back().id;
    }
    GatewayEventBatch batch = eventInput_.eventsSince(after, fetchBatch_);
    std::lock_guard lock(mutex_);
    // Every event of the scans up to batch.lastScan is in the queue once this batch reached its end.
    const bool complete = batch.events.empty() || batch.events.back().id >= batch.latestId;
    if (complete) detectionLastScan_ = batch.lastScan;
    eventsEnded_ = batch.events.empty() && batch.endOfData;
    any = any || !batch.events.empty();
    for (GatewayEvent& e : batch.events) events_.push_back(std::move(e));
    if (complete) return any;
  }
}

void KernelFeed::feedEventsUpTo(DataId scan, bool& fed) {
  while (!events_.empty() && events_.front().scanId <= scan) {
    const GatewayEvent& e = events_.front();
    feeding_ = Feeding::Event;
    const auto& stored = kernel_.state().scans;
    const auto lastScan = stored.find(e.gateway.lastScan);
    if (lastScan == stored.end())
      throw NotAvailableError("kernel feed: gateway event " + std::to_string(e.id) + " names scan " +
                              std::to_string(e.gateway.lastScan) + ", which the kernel does not hold");
    kernel_.addGatewayEvent(e, lastScan->second.corrected);
    ++counters_.gatewayEventsMapped;
    events_.pop_front();
    fed = true;
  }
}

std::optional<PoseRevisionInfo> KernelFeed::feedPending(bool& fed) {
  while (!scans_.empty() && (scans_.front().scan.id <= detectionLastScan_ || eventsEnded_)) {
    const CorrectedScan& s = scans_.front();
    feedEventsUpTo(s.scan.id - 1, fed);
    if (!revisions_.empty() && revisions_.front().atScan <= s.scan.id) return revisions_.front();
    feeding_ = Feeding::Scan;
    kernel_.addScan(s.scan, s.mapped);
    ++counters_.scansMapped;
    const DataId id = s.scan.id;
    scans_.pop_front();
    feedEventsUpTo(id, fed);
    fed = true;
  }
  if (scans_.empty() && scansEnded_ && eventsEnded_) {
    feedEventsUpTo(kernel_.state().lastScanId, fed);
    if (!revisions_.empty()) return revisions_.front();  // made after the last scan
  }
  return std::nullopt;
}

std::vector<CorrectedPose> KernelFeed::posesOfKernelScans(std::optional<std::uint64_t> revision) {
  DataId last;
  {
    std::lock_guard lock(mutex_);
    last = kernel_.state().lastScanId;
  }
  std::vector<CorrectedPose> poses;
  for (DataId first = 1; first <= last;) {
    const std::vector<PoseUpdate> chunk = revision ? scanInput_.revisedPoses(*revision, first, last)
                                                   : scanInput_.poses(first, std::min(last, first + kPoseChunk - 1));
    if (chunk.empty()) break;
    for (const PoseUpdate& u : chunk) poses.push_back({u.id, u.corrected});
    first = chunk.back().id + 1;
  }
  return poses;
}

bool KernelFeed::applyRevision(const PoseRevisionInfo& revision) {
  bool replaced;
  {
    std::lock_guard lock(mutex_);
    feeding_ = Feeding::Revision;
    replaced = kernel_.state().lastScanId >= revision.atScan;  // learned of too late
  }
  std::vector<CorrectedPose> poses;
  if (!replaced) {
    try {
      poses = posesOfKernelScans(revision.revision);
    } catch (const NotAvailableError&) {
      // A restarted input has not made it again yet: later. Otherwise it no longer keeps it.
      if (scanInput_.revision() < revision.revision) return false;
      replaced = true;
    }
  }
  if (replaced) poses = posesOfKernelScans(std::nullopt);
  std::lock_guard lock(mutex_);
  kernel_.revisePoses(poses, revision.revision);
  revisions_.pop_front();
  ++counters_.poseRevisions;
  counters_.posesReplaced += replaced;
  return true;
}

void KernelFeed::applyFinalPoses() {
  {
    std::lock_guard lock(mutex_);
    feeding_ = Feeding::FinalPoses;
  }
  std::vector<CorrectedPose> poses = posesOfKernelScans(std::nullopt);
  const std::uint64_t revision = scanInput_.revision();
  std::lock_guard lock(mutex_);
  kernel_.revisePoses(poses, revision);
}

std::string KernelFeed::skipFailing() {
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
      return "the final poses";
    case Feeding::Nothing:
      break;
  }
  return "nothing (the step failed while fetching, not while mapping)";
}

}  // namespace rgnav
