// The two inputs of the RG Mapping Kernel as its feed sees them (thesis 5.2: the kernel requests
// scans and gateway hypotheses from the ScanMapper and GatewayDetection modules by ID). The
// kernel module implements them with its client libraries, the in-process chain with the core
// objects themselves (InProcessInputs.h), tests with fakes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/gateways/detection/GatewayEventBatch.h"
#include "core/slam/CorrectedScans.h"

namespace rgnav {

// The ScanMapper: aligned scans by ID and the pose revisions (optimisations) it made.
class CorrectedScanInput {
 public:
  virtual ~CorrectedScanInput() = default;
  // Up to maxCount scans after afterId, in ID order; endOfData once no scan will follow.
  virtual CorrectedBatch correctedSince(DataId afterId, std::uint32_t maxCount) = 0;
  // The revisions after afterRevision the input still keeps, oldest first. afterRevision is what
  // the follower holds durably: the input may forget the revisions up to it.
  virtual std::vector<PoseRevisionInfo> revisionsSince(std::uint64_t afterRevision) = 0;
  // The poses of the scans firstId..lastId right after `revision` (at most a chunk; call again
  // after the last ID returned). NotAvailableError if the revision is not kept (or, after a
  // restart of the input, not made again yet).
  virtual std::vector<PoseUpdate> revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId) = 0;
  // The latest poses of the scans firstId..lastId (at most a chunk, as above).
  virtual std::vector<PoseUpdate> poses(DataId firstId, DataId lastId) = 0;
  // The latest revision made.
  virtual std::uint64_t revision() = 0;
};

// GatewayDetection: its gateway events by ID.
class GatewayEventInput {
 public:
  virtual ~GatewayEventInput() = default;
  // Up to maxCount events after afterId; batch.lastScan is the last scan the detector processed.
  virtual GatewayEventBatch eventsSince(GatewayEventId afterId, std::uint32_t maxCount) = 0;
};

}  // namespace rgnav
