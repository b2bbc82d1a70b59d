// RegionDescriptor: the feature vector a region is recognised by (thesis table 2.1, "feature
// vector for recognition and classification: bounding rectangle, 2D freespace and its 1st/2nd
// order moments, main axes"; 5.3: "size, number of connected gateways, binary gridmap for
// freespace"), computed alike for a mapped region (from the kernel's RegionView and its
// GatewayViews) and for what the robot sees now (LocalObservation.h: its recent scans at their
// odometry poses), from the same code: FreespaceMoments for area and main axes, MainDirections
// for the lines, the 15 cm FreespaceBitmap.
// descriptorDistance compares an observation with a mapped region. An observation is a partial
// view: from inside a room the robot sees the room and, through its open gateways, parts of the
// neighbours, so the observed area may be smaller than the region's (not yet seen) or larger
// (seen through doors). The distance therefore counts only what a partial view cannot explain:
//   - area: ln(observed / (region + neighbours)) where positive, i.e. more freespace observed
//     than the region and everything it opens to hold;
//   - shape: the standard deviations along the main axes, |ln(obs / region)| for each, weighted
//     by how much of the region the observation covers (min(1, observed / region area)): a
//     fully seen room must have the room's proportions, a glimpse says nothing about them;
//   - gateways: observed gateways beyond the region's count (only when the caller knows them,
//     e.g. gateways it detected; the local scans alone do not classify gateways).
// The rotation-invariant parts only: the main directions are angles in each own frame and are
// used to align the two (RegionRecognition.h), not to rank.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/nav/localization/LocalObservation.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

struct RegionDescriptor {
  RegionId region;  // none for an observation
  double areaM2 = 0.0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  // own frame
  double majorSigmaM = 0.0, minorSigmaM = 0.0;         // square roots of the main-axis variances
  double majorAxisAngleRad = 0.0;                      // own frame, [0, pi)
  std::vector<MainDirection> mainDirections;           // of the line segments, own frame
  // The most probable class of each gateway (GatewayView::classes); unknown: not counted.
  std::optional<std::vector<std::string>> gatewayClasses;
  double neighbourAreaM2 = 0.0;  // the neighbouring regions' areas (mapped regions only)
  FreespaceBitmap freespace;     // 15 cm, own frame
};

struct DescriptorWeights {
  double area = 2.0;      // per unit of ln(area ratio) beyond what region and neighbours hold
  double shape = 1.0;     // per unit of |ln(sigma ratio)|, both axes, at full coverage
  double gateway = 0.5;   // per observed gateway beyond the region's count
};

// A mapped region; `regions` gives the neighbours' areas, `gateways` its gateways' classes.
RegionDescriptor describeMappedRegion(const RegionView& region, const std::vector<RegionView>& regions,
                                      const std::vector<GatewayView>& gateways);
// What the robot sees now (local frame).
RegionDescriptor describeObservation(const LocalObservation& observation);

// 0 for an observation the region explains fully; larger the less it fits (see above).
double descriptorDistance(const RegionDescriptor& observed, const RegionDescriptor& mapped,
                          const DescriptorWeights& weights = {});

}  // namespace rgnav
