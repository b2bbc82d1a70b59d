// MapFrameSource: the Collision Avoidance module's map frame (MapFrame.h) from its pose source,
// refreshed with every batch of scans the module reads (thesis 5.5.3 drives in the odometry frame;
// the targets come in the map frame of the RG map):
//  - odometry: the map frame is the odometry frame; known from the start, never refreshed;
//  - groundtruth: truePose(s) ⊕ ⊖odometry(s) of the newest scan s read (evaluations only);
//  - scanmapper (while mapping: the map is the ScanMapper's): corrected(s) ⊕ ⊖odometry(s) of the
//    newest scan s the ScanMapper has corrected, asked as ScanMapper::odomToMap(newest scan read,
//    identity), whose nearest-scan rule picks the ScanMapper's newest scan when it lags behind;
//  - localization (a known map): the Localization module's latest estimate, mapPose(s) ⊕
//    ⊖odometry(s) for the scan s of that estimate (its odometry from the batch read, or from the
//    Laser when the estimate lags behind the batch).
// A source that does not answer (away, restarting, not localized yet) leaves the frame as it was:
// the frame moves only as slowly as the odometry drifts, so the module drives on with the last
// one; the source's calls get a short retry budget for that reason (a restart of the source
// costs no drive a stall). The error is the module's health error "pose_source" until the next
// answer; health counts "frame_refreshes". Before the first answer the frame is unknown and the
// module plans no drive (where the robot stands in the map is not known yet).
#pragma once

#include <optional>
#include <span>

#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "clientlibs/laser/LaserClient.h"
#include "clientlibs/localization/LocalizationClient.h"
#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "servers/collisionavoidance/MapFrame.h"
#include "servers/common/ModuleHealth.h"

namespace rgnav {

struct MapFrameObjects {
  std::string truth = "GroundTruth";
  std::string scanMapper = "ScanMapper";
  std::string localization = "Localization";
  std::string laser = "Laser";
};

class MapFrameSource {
 public:
  // How long one call to the source is retried before the frame stays as it was.
  static constexpr std::chrono::milliseconds kRetryBudget{200};

  // Contacts no module yet.
  MapFrameSource(PoseSource source, ClientSettings settings, const MapFrameObjects& objects, ModuleHealth& health);

  // Asks the source about the newest of `scans` (oldest first, not empty).
  void refresh(std::span<const LaserScan> scans);
  // The map pose of the odometry frame's origin; nullopt before the source first answered.
  const std::optional<Pose2D>& frame() const { return frame_; }

 private:
  Pose2D ask(std::span<const LaserScan> scans);
  Pose2D fromLocalization(std::span<const LaserScan> scans);

  PoseSource source_;
  ModuleHealth& health_;
  std::optional<GroundTruthClient> truth_;
  std::optional<ScanMapperClient> scanMapper_;
  std::optional<LocalizationClient> localization_;
  std::optional<LaserClient> laser_;
  std::optional<Pose2D> frame_;
};

}  // namespace rgnav
