// Relations of the SLAM benchmark (Kümmerle et al. 2009, "On measuring the accuracy of SLAM
// algorithms"): "t1 t2 dx dy dz droll dpitch dyaw" lines giving the manually verified pose of
// the scan stamped t2 in the frame of the scan stamped t1. Matching them to the scans of a log by
// stamp, and, for logs without relations, deriving relations in the benchmark's style from a
// reference trajectory (short-range pairs along the path plus revisits of earlier places).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"

namespace rgnav {

struct Relation {
  Timestamp first = 0.0;
  Timestamp second = 0.0;
  Pose2D relative;  // pose at `second` in the frame of the pose at `first`
};

// A relation between two scans of a log.
struct ScanRelation {
  DataId first = 0;
  DataId second = 0;
  Pose2D relative;
};

struct StampedScan {
  DataId id = 0;
  Timestamp stamp = 0.0;
};

struct TrajectoryPose {
  DataId id = 0;
  Timestamp stamp = 0.0;
  Pose2D pose;
};

// Throws FileError if the file cannot be read, FormatError (file, line) for a malformed line.
// Blank lines and lines starting with '#' are skipped.
std::vector<Relation> readRelations(const std::string& path);

// The relations whose both stamps lie within `tolerance` seconds of a scan stamp plus
// `stampOffset` (the nearest scan is taken). `scans` need not be sorted.
std::vector<ScanRelation> matchRelations(std::span<const Relation> relations, std::span<const StampedScan> scans,
                                         double stampOffset, double tolerance);

struct DerivedRelationsConfig {
  double step = 0.5;            // m (or rad, whichever is reached first) between consecutive samples
  double revisitDistance = 1.0; // m; an earlier sample this close is a revisit
  double revisitRotation = 0.5; // rad; and at most this different in heading
  double revisitAge = 30.0;     // s; and at least this much older
};

// Samples the trajectory every `step` of motion; relates each sample to the next one and to its
// nearest revisited earlier sample, if any (the mix of local and loop relations the benchmark's
// relation files have).
std::vector<ScanRelation> relationsFromTrajectory(std::span<const TrajectoryPose> reference,
                                                  const DerivedRelationsConfig& config = {});

}  // namespace rgnav
