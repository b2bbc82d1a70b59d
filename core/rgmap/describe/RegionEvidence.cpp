// Evidence for a region's description; see RegionEvidence.h.
#include "core/rgmap/describe/RegionEvidence.h"

namespace rgnav {

RegionEvidence::RegionEvidence(const RegionEvidenceConfig& config)
    : freespace_(config.freespace), sample_(config.samplePoints) {}

void RegionEvidence::addScan(const LaserScan& scan, const Pose2D& sensorPose,
                             std::span<const GatewaySegment> gateways) {
  const RegionBeams beams = regionBeams(scan, sensorPose, gateways, freespace_.config().noReturnFreeRangeM);
  if (!freespace_.addBeams(beams)) return;  // taken beyond the largest freespace grid: left out
  hull_.addBeams(beams);
  sample_.addBeams(beams);
}

void RegionEvidence::mergeFrom(const RegionEvidence& other, const Pose2D& otherInThis) {
  freespace_.mergeFrom(other.freespace_, otherInThis);  // checks the input first
  hull_.mergeFrom(other.hull_, otherInThis);
  sample_.mergeFrom(other.sample_, otherInThis);
}

}  // namespace rgnav
