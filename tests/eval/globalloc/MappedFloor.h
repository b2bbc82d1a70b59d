// MappedFloor: an IPA floor plan mapped in process by the simulator's room tour (MappingRun.h, as
// "rgctl eval rooms --in-process" maps it) and taken as the RG Mapping Kernel serves it: its
// regions and gateways as views, and where the map frame lies in the world. Kept apart from the
// trials, which see the map only through these views, as the Localization module does.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/gateways/classify/HmmClassifier.h"
#include "core/rgmap/kernel/RgMapViews.h"
#include "core/sim/LoadedWorld.h"
#include "tests/eval/globalloc/LocalTruth.h"

namespace rgnav {

struct MappedFloor {
  LoadedWorld world;
  std::vector<RegionView> regions;
  std::vector<GatewayView> gateways;
  Pose2D mapToWorld;
  double slamErrorMeanM = 0.0, slamErrorMaxM = 0.0;  // the mapped scans' corrected poses against the truth
  std::vector<ScanPlacement> scans;  // every mapped scan's true and corrected position (LocalTruth.h)
};

// FileError if the floor plan has no ground-truth rooms beside it (the tour needs them).
// truePoses: the kernel maps with the true poses instead of SLAM's (MappingRunSetup::truePoses),
// so that the trials measure the localizer alone, not the map's distortion.
MappedFloor mapFloor(const std::string& floorPlanPath, const std::optional<HmmClassifier>& classifier, bool truePoses);

}  // namespace rgnav
