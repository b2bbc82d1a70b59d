// LocalizationMap: the data of the RG map the localization evaluates particles on (thesis 5.3):
// for each region its frame, its line map and freespace (region frame) and the likelihood field
// of its lines; for each gateway between two regions its crossing points (map frame), which say
// when a particle has passed it. A region's field is built once per region revision (the
// caller's number, e.g. the kernel's scan count of the region) and kept until its revision or
// a neighbour's changes.
// Deliberate difference: the thesis evaluates a particle on its region's data only. Beams through
// an open door end in the neighbouring region, whose walls the region's own line map lacks; the
// field of a region is therefore built from its own lines plus those of the regions it shares a
// gateway with ("the LM also requests and stacks the data for the neighboring regions"),
// transformed into its frame.
// wholeFloor() is the global-map baseline: one region (ID 1, identity frame) holding every line
// in the map frame and no gateway; RegionMcl then runs unchanged as a global-map MCL.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "core/nav/localization/LikelihoodField.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

struct LocalizationRegion {
  RegionId id;
  Pose2D frame;                  // in the map frame
  std::uint64_t revision = 0;    // the field is rebuilt when this changes
  std::vector<Segment2> lines;   // region frame
  FreespaceBitmap freespace;     // region frame
  std::vector<GatewayId> gateways;
};

struct LocalizationGateway {
  GatewayId id;
  std::array<RegionId, 2> regions;                // side A, side B (both known, different)
  std::array<Eigen::Vector2d, 2> crossingPoints;  // side A's and side B's, map frame
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // midpoint of the crossing points
};

class LocalizationMap {
 public:
  explicit LocalizationMap(const BeamModelConfig& config);

  // Adds or replaces a region (its field is rebuilt lazily if the revision changed). Gateways
  // with a side unknown, both sides in one region, or neutralised are not kept.
  void setRegion(LocalizationRegion region);
  void setGateways(const std::vector<GatewayView>& gateways);
  void removeRegion(RegionId id);

  // From the kernel's views (e.g. the Localization module's copy of the map, or an evaluation's
  // in-process kernel); a region's revision is its scan count (RegionSummaryView::scans).
  static LocalizationMap fromViews(const std::vector<RegionView>& regions, const std::vector<GatewayView>& gateways,
                                   const BeamModelConfig& config);
  // The global-map baseline (see above) of the same views.
  static LocalizationMap wholeFloor(const std::vector<RegionView>& regions, const BeamModelConfig& config);

  bool hasRegion(RegionId id) const { return regions_.count(id) != 0; }
  const LocalizationRegion& region(RegionId id) const;  // NotAvailableError if unknown
  std::vector<RegionId> regionIds() const;
  const std::map<GatewayId, LocalizationGateway>& gateways() const { return gateways_; }
  // The region's likelihood field (its own and its neighbours' lines, region frame), built on
  // first use after a change. NotAvailableError for an unknown region.
  const LikelihoodField& field(RegionId id) const;

  // The region a particle of region `from` at map position `p` belongs to after the hand-over
  // rule: if p lies within `radiusM` of the centre of a gateway of `from` and nearer to the other
  // side's crossing point than to its own side's, the other side's region; else `from`.
  RegionId handOver(RegionId from, const Eigen::Vector2d& p, double radiusM) const;

  // The region whose freespace holds map point p, preferring `hint`; none if no region's does.
  RegionId regionAt(const Eigen::Vector2d& p, RegionId hint) const;

  std::size_t fieldBytes() const;  // memory of the fields built so far

 private:
  BeamModelConfig config_;
  std::map<RegionId, LocalizationRegion> regions_;
  std::map<GatewayId, LocalizationGateway> gateways_;
  // The regions sharing a kept gateway with `id`.
  std::vector<RegionId> neighbours(RegionId id) const;

  struct CachedField {
    std::vector<std::pair<RegionId, std::uint64_t>> key;  // the revisions of the region and its neighbours
    std::unique_ptr<LikelihoodField> field;
  };
  mutable std::map<RegionId, CachedField> fields_;
};

}  // namespace rgnav
