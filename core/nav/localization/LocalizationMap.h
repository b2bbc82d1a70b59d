// LocalizationMap: the data of the RG map the localization evaluates particles on (thesis 5.3):
// for each region its frame, its line map and freespace (region frame) and the likelihood field
// of its lines; for each gateway between two regions its crossing points (map frame), which say
// when a particle has passed it. A region's field is built once per region revision (the
// caller's number, e.g. the kernel's scan count of the region) and kept until its revision or
// a neighbour's changes.
// Deliberate difference: the thesis evaluates a particle on its region's data only. Beams through
// an open door end in the neighbouring region, whose walls the region's own line map lacks; the
// field of a region is therefore built from its own lines plus those of the regions it shares a
// gateway with ("the LM also requests and stacks the data for the neighboring regions") and of
// the regions whose freespace overlaps its own (a place the kernel mapped twice, e.g. a corridor
// ring whose return was not recognised), transformed into its frame.
// wholeFloor() is the global-map baseline: one region (ID 1, identity frame) holding every line
// in the map frame and no gateway; RegionMcl then runs unchanged as a global-map MCL.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
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

// A region of the kernel's view as the localization keeps it; its revision is its scan count
// (RegionSummaryView::scans).
LocalizationRegion localizationRegion(const RegionView& region);

class LocalizationMap {
 public:
  explicit LocalizationMap(const BeamModelConfig& config);

  // Adds or replaces a region (its field is rebuilt lazily if the revision changed).
  void setRegion(LocalizationRegion region);
  // Replaces the gateways. Those with a side unknown, both sides in one region, or neutralised
  // are not kept; one with a side whose region is not in the map joins nothing until that
  // region is set.
  void setGateways(const std::vector<GatewayView>& gateways);
  void removeRegion(RegionId id);

  // From the kernel's views (e.g. an evaluation's in-process kernel), each region as
  // localizationRegion gives it.
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

  // The region a particle of region `from` at map position `p` belongs to (thesis 5.3: the quick
  // check "if a given particle lies in the current region" on the 1-bit freespace): `from` while
  // its freespace holds p; else the first gateway neighbour whose freespace holds p; else any
  // region whose freespace holds p (regions may overlap where the kernel mapped a place twice);
  // else, within `radiusM` of a gateway of `from`, the other side's region if p is nearer to
  // that side's crossing point; else `from`.
  RegionId handOver(RegionId from, const Eigen::Vector2d& p, double radiusM) const;

  // The region whose freespace holds map point p, preferring `hint`; none if no region's does.
  RegionId regionAt(const Eigen::Vector2d& p, RegionId hint) const;
  // Whether region `id`'s freespace holds map point p (false for an unknown region).
  bool freeIn(RegionId id, const Eigen::Vector2d& p) const;

  std::size_t fieldBytes() const;  // memory of the fields built so far

 private:
  // Map point -> region frame, with the rotation's cosine and sine computed once.
  struct ToRegion {
    double c = 1.0, s = 0.0, x = 0.0, y = 0.0;
    Eigen::Vector2d operator()(const Eigen::Vector2d& p) const {
      const double dx = p.x() - x, dy = p.y() - y;
      return {c * dx + s * dy, -s * dx + c * dy};
    }
  };
  struct Entry {
    LocalizationRegion region;
    ToRegion toRegion;
    std::vector<RegionId> neighbours;  // regions sharing a kept gateway
    // The regions whose lines the field stacks: the neighbours and the overlapping regions;
    // worked out on first use after a change of the map.
    mutable std::optional<std::vector<RegionId>> stacked;
  };
  bool holds(const Entry& entry, const Eigen::Vector2d& p) const;
  void relink();  // recomputes every entry's neighbours and forgets the stacked regions
  const std::vector<RegionId>& stackedWith(const Entry& entry) const;

  BeamModelConfig config_;
  std::map<RegionId, Entry> regions_;
  std::map<GatewayId, LocalizationGateway> gateways_;
  // The regions whose freespace shares at least BeamModelConfig::overlapMinCells cells with `id`'s.
  std::vector<RegionId> overlapping(RegionId id) const;

  struct CachedField {
    std::vector<std::pair<RegionId, std::uint64_t>> key;  // the revisions of the region and its neighbours
    std::unique_ptr<LikelihoodField> field;
  };
  mutable std::map<RegionId, CachedField> fields_;
};

}  // namespace rgnav
