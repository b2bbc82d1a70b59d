// KernelFeed: the ordering contract of the mapping chain (thesis 5.2, ScanMapper ->
// GatewayDetection -> RG Mapping Kernel), in one place for the kernel module and the in-process
// chain. It follows both inputs by ID and feeds the kernel in scan order:
//   - scan s with its pose as mapped (CorrectedScan::mapped), once the detector has processed s;
//   - then the events scan s caused (GatewayEvent::scanId), each placed with the kernel's pose of
//     the gateway's last scan;
//   - a pose revision the ScanMapper made while it took in scan s revises the kernel's scans
//     with that revision's poses just before scan s (one made after the last scan, at the end);
//   - once both inputs ended, the ScanMapper's final poses.
// So the kernel's inputs, and the map, do not depend on the modules' timing. A revision the input
// no longer keeps, or that the feed learned of only after the kernel took in its scan, is
// replaced by the latest poses and counted (posesReplaced); revisions the input forgot before
// the feed learned of them are counted (revisionsNotKept). A revision a restarted input has not
// made again yet is waited for.
// A record the kernel keeps failing on (a malformed event, a scan it refuses) can be left out with
// skipFailing(), so that one bad record does not stop the map.
// Locking: every access to the kernel and to the feed's queues happens under `kernelMutex`, which
// the owner also takes for its own use of the kernel; calls to the inputs happen outside it.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <optional>
#include <vector>

#include "core/rgmap/feed/MappingInputs.h"
#include "core/rgmap/kernel/RgMappingKernel.h"

namespace rgnav {

struct KernelFeedCounters {
  std::uint64_t scansMapped = 0;
  std::uint64_t gatewayEventsMapped = 0;
  std::uint64_t poseRevisions = 0;
  std::uint64_t posesReplaced = 0;     // revisions applied with the latest poses instead
  std::uint64_t revisionsNotKept = 0;  // revisions the input forgot before the feed learned of them
};

class KernelFeed {
 public:
  // `fetchBatch`: records asked from each input per call (at least 1: InvalidArgumentError).
  // `durableRevision` (called under kernelMutex) is the pose revision the owner's durable state
  // (its checkpoint) holds: the ScanMapper may forget the revisions up to it. Without it, the
  // kernel's own revision is durable.
  KernelFeed(RgMappingKernel& kernel, std::mutex& kernelMutex, CorrectedScanInput& scans, GatewayEventInput& events,
             std::uint32_t fetchBatch, std::function<std::uint64_t()> durableRevision = {});

  // One round: fetches what is new from both inputs, feeds the kernel as far as the contract
  // allows, and applies the final poses once both inputs ended. True if anything came or was fed.
  // Errors of the inputs (e.g. ModuleUnavailableError) and of the kernel pass through; the feed
  // stays consistent and the next step() goes on from where the kernel is.
  bool step();

  // Under kernelMutex: both inputs ended and everything was fed, final poses included.
  bool finished() const { return finished_; }
  // Under kernelMutex.
  const KernelFeedCounters& counters() const { return counters_; }
  // Under kernelMutex, after step() failed: leaves out the record the kernel was being fed when
  // it failed (a scan, an event, a revision; the final poses: the map keeps the poses as mapped
  // and is finished) and says which it was.
  std::string skipFailing();

 private:
  bool fetchScans();
  bool fetchRevisions();
  bool fetchEvents();
  // Under lock: feeds scans and events in order up to the next revision to apply, and returns
  // that one; `fed` becomes true when something was fed.
  std::optional<PoseRevisionInfo> feedPending(bool& fed);
  void feedEventsUpTo(DataId scan, bool& fed);
  // The poses of the kernel's scans after a revision, or the latest ones (nullopt).
  std::vector<CorrectedPose> posesOfKernelScans(std::optional<std::uint64_t> revision);
  // Applies the revision (false: the ScanMapper, restarted, has not made it again yet).
  bool applyRevision(const PoseRevisionInfo& revision);
  void applyFinalPoses();

  enum class Feeding { Nothing, Scan, Event, Revision, FinalPoses };

  RgMappingKernel& kernel_;
  std::mutex& mutex_;
  CorrectedScanInput& scanInput_;
  GatewayEventInput& eventInput_;
  std::uint32_t fetchBatch_;
  std::deque<CorrectedScan> scans_;         // fetched, not fed yet
  std::deque<PoseRevisionInfo> revisions_;  // known, not applied yet
  std::deque<GatewayEvent> events_;         // fetched, not fed yet
  DataId detectionLastScan_ = 0;            // the detector has processed every scan up to this one
  bool scansEnded_ = false, eventsEnded_ = false, finished_ = false;
  std::function<std::uint64_t()> durableRevision_;
  Feeding feeding_ = Feeding::Nothing;  // what the kernel is being fed
  KernelFeedCounters counters_;
};

}  // namespace rgnav
