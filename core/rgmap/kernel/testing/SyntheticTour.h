// Test helper: the inputs of the RG Mapping Kernel on a robot tour through a synthetic world of
// walls and narrow passages, as the ScanMapper and the GatewayDetection module would give them:
// a ray-cast scan per step with its corrected pose (the true pose) and an odometry pose that
// drifted by a fixed transform, and a fake detector's gateway events in that odometry frame.
// The fake detector reports a door (per its DoorReports):
//   - Detected when the robot first comes within detectRangeM of its centre, the crossing point
//     on the robot's side first;
//   - Updated each time the robot comes within range again after having been out of it;
//   - Detected anew under another ID after redetect();
//   - Traversed when two steps lie on different sides of its line and the path between them
//     crosses it (if it was not known yet, it is reported first by this traversal).
// Also the two worlds and tours of the kernel's tests.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/gateways/detection/GatewayRecord.h"
#include "core/lines/testing/SyntheticScan.h"
#include "core/rgmap/kernel/RgMappingKernel.h"

namespace rgnav::testing {

enum class DoorReports { All, TraversalsOnly, None };

struct TourDoor {
  DetectorGatewayId detectorId;
  Eigen::Vector2d left = Eigen::Vector2d::Zero();  // gateway points, map frame
  Eigen::Vector2d right = Eigen::Vector2d::Zero();
  DoorReports reports = DoorReports::All;
};

struct TourWorld {
  std::vector<Wall> walls;
  std::vector<TourDoor> doors;
};

// A hallway (x in [0, 12], y in [0, 2]) with two rooms north of it, room 1 (x in [2, 6]) behind
// door 11 at x in [3.55, 4.45] and room 2 (x in [7, 11]) behind door 12 at x in [8.55, 9.45];
// the rooms reach y = 6.
TourWorld hallwayWithTwoRooms();
// hallwayWithTwoRooms() with a 0.7 x 1.2 m cabinet against room 1's east wall, centred at
// cabinetCentre().
TourWorld hallwayWithTwoRoomsAndCabinet();
inline Eigen::Vector2d cabinetCentre() { return {5.65, 3.2}; }
// A ring corridor 2 m wide around a 6 x 6 m block (outer walls 10 x 10 m from the origin) with
// door 21 across its south leg at x = 5 (y in [0.55, 1.45]).
TourWorld ringCorridor();

// One input of the kernel: a scan with its corrected pose, or a gateway event with the corrected
// pose of the gateway's last scan.
struct KernelInput {
  std::optional<StoredScan> scan;
  std::optional<GatewayEvent> event;
  Pose2D lastScanCorrected;
};

void feed(RgMappingKernel& kernel, const KernelInput& input);

// Feeds inputs [begin, end) and runs checkConsistency after each; returns the violations after
// the first input that caused any, one per line, prefixed with the input's index (empty if none did).
std::string feedChecked(RgMappingKernel& kernel, const std::vector<KernelInput>& inputs, std::size_t begin,
                        std::size_t end);
// A new kernel fed inputs [0, end); throws std::logic_error with feedChecked's report if the map
// was inconsistent after any of them.
RgMappingKernel mapped(const std::vector<KernelInput>& inputs, std::size_t end);

class SyntheticTour {
 public:
  SyntheticTour(TourWorld world, const Pose2D& drift, double stepM = 0.25, double detectRangeM = 1.0);

  // Drives from the current position (the first waypoint on the first call) along `waypoints`.
  void driveThrough(const std::vector<Eigen::Vector2d>& waypoints);
  void setReports(DetectorGatewayId detectorId, DoorReports reports);
  // The fake detector loses its track of door `detectorId` and reports the door anew, as door
  // `newId`: Detected when the robot next comes within range, crossing point 0 on its side then.
  void redetect(DetectorGatewayId detectorId, DetectorGatewayId newId);

  const std::vector<KernelInput>& inputs() const { return inputs_; }

 private:
  struct DoorState {
    TourDoor door;
    bool known = false;
    bool inRange = false;
    Eigen::Vector2d firstSide = Eigen::Vector2d::Zero();  // crossing point 0, map frame
    DataId firstScan = 0;
    std::size_t traversals = 0;
  };

  void step(const Pose2D& pose);
  GatewayRecord record(const DoorState& d, const Pose2D& pose) const;
  void emit(GatewayEventKind kind, const DoorState& d, const Pose2D& pose, const TraversalReport& traversal = {});

  std::vector<Wall> walls_;
  std::vector<DoorState> doors_;
  Pose2D drift_;
  double stepM_;
  double detectRangeM_;
  std::optional<Pose2D> last_;
  std::vector<KernelInput> inputs_;
  DataId nextScan_ = 1;
  GatewayEventId nextEvent_ = 1;
};

// The odometry drift of the tours: odometry = kTourDrift ∘ corrected.
inline constexpr Pose2D kTourDrift{0.4, -0.3, 0.15};

// `world` (hallwayWithTwoRooms(), perhaps with furniture added): along the hallway (y = 0.9) into
// room 1 and back, into room 2 and back, into room 1 again (a revisit) and back to the hallway's
// west end.
SyntheticTour twoRoomTour(TourWorld world = hallwayWithTwoRooms());
// ringCorridor(): from (1.1, 1) east through the door, once around the block, and through the
// door again to (6.6, 1).
SyntheticTour ringTour();

}  // namespace rgnav::testing
