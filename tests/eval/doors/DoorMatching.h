// matchDoors: one-to-one matching of detected gateways to ground-truth door lines by the
// distance of their segment midpoints (issue 6: a match within 0.5 m). Pairs within
// maxDistanceM are taken greedily, nearest first, first with the counted doors, then with the
// other lines that have two rooms, so a line matches at most one detection and a detection at
// most one line. A detection whose partner is a real door we do not count (kUnreachable,
// kNotApproached, or with traversedOnly a counted door the path did not cross) is ignored: it
// is neither right nor wrong. A detection at a line that is no narrow passage (kNotNarrow) or at
// no line is a false positive (pessimistic, as thesis 6.1.3: unclear passages count as no door).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "tests/eval/doors/DoorTruth.h"

namespace rgnav {

enum class DetectionOutcome { kMatch, kFalse, kIgnored };

struct DoorMatch {
  std::vector<DetectionOutcome> outcomes;  // per detection
  std::vector<int> detectionOfDoor;        // per GT line: the matched detection, or -1
  std::size_t doors = 0;       // counted GT doors
  std::size_t detections = 0;  // detections not ignored
  std::size_t matches = 0;
};

// With traversedOnly, only the counted doors the robot's path crossed count.
DoorMatch matchDoors(const std::vector<TruthDoor>& doors, const std::vector<Eigen::Vector2d>& detectionMidpoints,
                     double maxDistanceM, bool traversedOnly = false);

}  // namespace rgnav
