// LocalizationViews: what the Localization module serves (idl/Localization.idl) as plain values
// around the region MCL's own types (core/nav/localization/RegionMcl.h): the estimate of one scan,
// a particle with its map pose, a snapshot of the particle set, the module's state. The module
// keeps these and the client library converts them to and from IDL types (convert.h).
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/Errors.h"
#include "core/nav/localization/RegionMcl.h"

namespace rgnav {

// The module holds no particles yet (neither setPose nor relocalize, nor a checkpoint resumed).
class NotLocalizedError : public NotAvailableError {
 public:
  using NotAvailableError::NotAvailableError;
};

// The estimate for scan `scanId`. estimate.scanId is the scan of the filter update it rests on;
// between updates (the robot moved less than MclConfig::updateMinTravelM) the module moves that
// update's estimate on by the odometry.
struct ScanEstimate {
  DataId scanId = 0;
  PoseEstimate estimate;
};

struct ParticleView {
  Particle particle;  // pose in its region's frame
  Pose2D mapPose;

  friend bool operator==(const ParticleView&, const ParticleView&) = default;
};

struct ParticleSnapshotView {
  DataId scanId = 0;       // the scan of the last filter update
  std::size_t total = 0;   // particles in the filter
  std::vector<ParticleView> particles;  // heaviest first

  friend bool operator==(const ParticleSnapshotView&, const ParticleSnapshotView&) = default;
};

struct LocalizationStateView {
  bool initialised = false;
  std::size_t mapRegions = 0;
  RgMapEventId mapRevision = 0;
  std::uint64_t updates = 0;
  DataId lastScan = 0;
  std::uint64_t traversalsReported = 0;

  friend bool operator==(const LocalizationStateView&, const LocalizationStateView&) = default;
};

}  // namespace rgnav
